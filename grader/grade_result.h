/* Grader machinery: not part of any assignment.
 * The facts of a grading: what each stage found, as values, never as words. The build says whether
 * the part built and why not, and the compiler's lines about the student's own files; the suite, each
 * test's verdict (the judge's, with the course's test's message) and why a suite could not be judged;
 * each image case, its verdict (per block: the statistic; the image: ratios, bad pixels), its figures
 * (samples per pixel and their map, noise, CPU time), the pixels that differ most, the two images;
 * the score, the points. The report alone turns these into words and pictures (grade_report.c), and
 * facts.json writes them for machines (grade_facts.c). A grading's result is allocated
 * (grade_result_new): several megabytes, never a stack's. */
#ifndef PL_GRADE_RESULT_H
#define PL_GRADE_RESULT_H

#include <stdbool.h>
#include <stdint.h>
#include "grade_limits.h"
#include "grade_sandbox.h"
#include "grade_spec.h"
#include "grade_why.h"
#include "verdict.h"
#include "../framework/image.h"

/* ---- the build -------------------------------------------------------------------------------- */

typedef struct {
    bool built;
    grade_why why;                     /* why not, when it did not */
    char diagnostics[4096];            /* the compiler's lines about the student's own files (grade_diag.h) */
} grade_build_facts;

/* ---- the suite -------------------------------------------------------------------------------- */

/* One test's verdict, the judge's: the course's name of the test, its task, and for a failure the
 * course's test's message (its numbers rounded: grade_figure_text) or the grader's why. */
typedef struct {
    char name[128];
    bool passed;
    grade_why why;                     /* GRADE_WHY_NONE: the message says why it failed */
    char message[GRADE_MESSAGE_MAX + 1];
} grade_test_fact;

typedef struct {
    bool judged;                       /* the suite could be judged; else nothing of it counts (why) */
    grade_why why;
    int run, failed;                   /* tests run and not passed */
    grade_test_fact *tests;            /* GRADE_MAX_TESTS of them, in the suite's order (owned) */
    int num_tests;
} grade_suite_facts;

/* ---- one image case --------------------------------------------------------------------------- */

/* A pixel that differs most, in a block that differs most: where to trace (from the bottom-left). */
typedef struct {
    int x, y;
    float diff;                        /* its luminance's difference from the reference's */
} grade_pixel_fact;

typedef struct {
    const grade_case *spec;
    bool ran;                          /* the render finished and its film was read */
    bool pass;                         /* it ran, its image matches and its figures are in bounds */
    grade_why why;                     /* why it did not run */
    verdict v;                         /* the image verdict (when ran) */
    double spp, course_spp;            /* adaptive cases: mean samples per pixel, the candidate's and the course's */
    double rate_distance;              /* adaptive cases: the sample-rate map's distance from the course's
                                          (grade_rate_map_distance; -1: not judged) */
    double cpu, base_cpu;              /* work_check cases: CPU seconds of the candidate's render and of the
                                          baseline's, each as the kernel counted it (0: not judged) */
    bool base_is_scan;                 /* the baseline is the framework's linear scan (a student's own tree),
                                          not the course's BVH (the autograder) */
    double noise;                      /* noise_check cases: per-sample variance over the course's */
    grade_pixel_fact trace[GRADE_TRACE_PIXELS];  /* a failing public case's pixels to trace */
    int num_trace;
    image candidate, reference;        /* the two images, for the report's pictures (owned) */
    char images[3][160];               /* the pictures' names in the report folder (the plan's), once written */
    unsigned long long seed;           /* the seed of the render this result judges */
    /* Rendered twice (grade_image.h: a failure a correct render has by chance is confirmed or not by
     * a second render, which this result judges): the first render's seed and p-value. */
    bool rendered_twice;
    unsigned long long first_seed;
    double first_p;
    bool chance_failure;               /* it failed on its p-value alone (not its figures, not a bad
                                          pixel, not a deterministic case) */
    double score;
} grade_case_result;

/* ---- a part, a grading ------------------------------------------------------------------------ */

typedef struct {
    int part;
    char folder[64];                   /* its folder in the course, "part2_bvh" (the words name it) */
    const grade_part_spec *spec;       /* its tasks and cases */
    grade_build_facts build;
    grade_suite_facts suite;
    double task_score[GRADE_MAX_TASKS];
    int task_passed[GRADE_MAX_TASKS], task_run[GRADE_MAX_TASKS];  /* per task of the spec: its tests that passed, ran */
    double unit_score, unit_max;
    grade_case_result cases[GRADE_MAX_CASES];
    int num_cases;
    double score, max_score;
} grade_part_result;

typedef struct {
    uint64_t seed;                     /* drawn at grading time, recorded */
    bool submission;                   /* a submission's grading (the autograder), not a student's own tree */
    grade_sandbox sandbox;             /* the protections this machine gave student code */
    double seconds;
    grade_part_result parts[GRADE_MAX_PART];
    int num_parts;
} grade_result;

/* A new, empty result (its parts' test arrays allocated), or NULL when out of memory. */
grade_result *grade_result_new(void);
/* Frees a result and everything its cases and suites hold. NULL-safe. */
void grade_result_free(grade_result *r);
/* Case c emptied (its verdict and images freed), for another render to judge. */
void grade_result_clear_case(grade_case_result *c);
/* The mean of the lit channels' ratios of v (NaN when none is lit). */
double grade_result_mean_ratio(const verdict *v);

#endif
