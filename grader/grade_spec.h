/* Grader machinery: not part of any assignment.
 * The spec stage's course side: grading/cases.json (and grading/hidden/cases.json) read strictly
 * into the cases, tasks and parts every later stage is told about (grading/README.md explains the
 * file field by field). Nothing here is the student's. */
#ifndef PL_GRADE_SPEC_H
#define PL_GRADE_SPEC_H

#include <stdbool.h>
#include "grade_limits.h"
#include "../framework/status.h"

typedef struct {
    char name[64];
    char scene[256];                    /* relative to the repository root */
    char *flags[GRADE_MAX_FLAGS];       /* renderer flags, owned */
    int num_flags;
    int width, height, samples;         /* the candidate's render */
    int block_side;                     /* verdict blocks of this many pixels square; 0: sized to hold
                                           8192 candidate samples (verdict.h says why) */
    int reference_samples;              /* the reference: the solution's render at this many samples */
    char *reference_flags[GRADE_MAX_FLAGS];  /* its flags when they differ (adaptive cases), owned */
    int num_reference_flags;            /* 0: the reference uses flags */
    double points;
    bool hidden;
    bool work_check;                    /* also judge the render's CPU time against the course's BVH */
    bool known_variance;                /* "statistic": "known_variance" (verdict.h), else the paired t */
    bool grazing;                       /* "grazing": lit at grazing angles, so dark means self-shadowing */
    bool noise_check;                   /* also judge the per-sample variance against the reference's */
    double tolerance;                   /* "tolerance": a block may differ by this share of its brightness
                                           before its test counts the difference (verdict_params) */
    bool rounding;                      /* "statistic": "rounding": a deterministic case, compared up to
                                           VERDICT_ROUNDING_TOLERANCE with VERDICT_TIE_PIXELS ties */
    char shows[160];                    /* what the case makes visible, for the report */
} grade_case;

/* One task's share of a part's unit points ("unit_tasks" in cases.json): the tests whose names,
 * less "test_", begin with one of match[]. The share is earned whole when all `tests` of them ran
 * and passed, and not at all otherwise: a wrong task loses its share, not one test's weight. */
typedef struct {
    char task[16];                      /* "3.2", or "3.4+3.5" for tests of two tasks together */
    char functions[96];                 /* what the task writes, for the report: "bsdf_pdf, bsdf_sample_f" */
    double points;
    int tests;                          /* how many tests the suite has for it */
    char match[GRADE_MAX_MATCH][48];
    int num_match;
} grade_task;

typedef struct {
    int part;                           /* 1..9; 0: cases.json does not list this part */
    double unit_points;                 /* the sum of the tasks' points */
    int unit_tests;                     /* the tests its suite runs to its end ("unit_tests" in cases.json) */
    grade_task tasks[GRADE_MAX_TASKS];
    int num_tasks;
    grade_case cases[GRADE_MAX_CASES];
    int num_cases;
} grade_part_spec;

typedef struct {
    double family_alpha;
    grade_part_spec parts[GRADE_MAX_PART];  /* parts[n - 1] is part n's */
} grade_spec;

/* grading/cases.json, plus the hidden cases of hidden_path when that file exists (NULL: none). */
#define GRADE_CASES "grading/cases.json"
#define GRADE_HIDDEN_CASES "grading/hidden/cases.json"
pl_status grade_spec_load(const char *path, const char *hidden_path, grade_spec *out, pl_diag *diag);
void grade_spec_free(grade_spec *s);

/* Whether case k is adaptive: its flags hold -a (part 5's sampling rule decides each pixel's count). */
bool grade_spec_adaptive(const grade_case *k);
/* The index of the task of p that test `name` belongs to (its name, less "test_", begins with one
 * of the task's match[]), or -1. */
int grade_spec_task_of(const grade_part_spec *p, const char *name);

#endif
