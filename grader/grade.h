/* Grader machinery: not part of any assignment.
 * bin/grade grades parts one at a time: a submission's part among the course's other parts (the
 * autograder), or a student's own tree as it is (make grade, public cases). grader/README.md maps
 * the pipeline, spec -> plan -> build -> run -> verdicts -> score -> report, module by module, and
 * says what each stage trusts. This header holds what the stages share: the cases, the results, the
 * one scoring function, the children's runner and, in one block, every limit. */
#ifndef PL_GRADE_H
#define PL_GRADE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "../framework/status.h"
#include "verdict.h"

#define GRADE_MAX_CASES 16
#define GRADE_MAX_FLAGS 16
#define GRADE_MAX_PART 9          /* parts are numbered 1..9 (folders parts/part<N>_<name>); a course has some
                                     of them: those grading/cases.json lists and its tree holds are graded */
#define GRADE_MAX_TASKS 8         /* a part's unit-test tasks ("unit_tasks" in cases.json) */
#define GRADE_MAX_MATCH 4         /* test-name prefixes per task */
#define GRADE_MAX_TESTS 256       /* tests in one suite: the course's largest has ~40 */
/* The BVH's work: the kernel's count of the render's CPU time, against a render in which no student
 * code runs, of the same case in the same grading (grade_image.c, grading/README.md: calibrated on
 * the solution and the correct alternatives, slow ones included). */
#define GRADE_WORK_FACTOR 5.0     /* at most 5x the CPU time of the course's own part 2 (the autograder) */
#define GRADE_SCAN_FACTOR 8.0     /* at least 8x faster than the framework's linear scan (a student's own
                                     tree, which holds no course part 2 to compare with) */
#define GRADE_SPP_TOLERANCE 0.05  /* an adaptive render's mean samples per pixel: the course's +-5% */
#define GRADE_RATE_TOLERANCE 0.5  /* and its map, block by block: at most half the course's variation
                                     unfollowed (grade_rate_map_distance; grading/CALIBRATION.md) */
#define GRADE_NOISE_FACTOR 1.15   /* noise_check cases: per-sample variance at most 1.15x the course's
                                     (grading/README.md: measured on the solution and the alternatives) */

/* ---- cases (grading/cases.json) ------------------------------------------------------------ */

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

/* The command of case k's own render (its flags, resolution and samples; not the reference's):
 * `bin flags... -r W H -s S --seed SEED -t THREADS -q -f out scene` (out NULL: `--film-fd 3`, the
 * film to the grader's pipe), into argv (room for
 * GRADE_MAX_FLAGS + 16 entries, NULL-terminated); the numbers are formatted into text. The grader
 * renders a candidate with it, the reference maker the course's figures (probe_case). */
#define GRADE_FILM_FD 3
#define GRADE_FILM_FD_TEXT "3"
typedef struct { char width[16], height[16], samples[16], seed[32], threads[16]; } grade_case_text;
void grade_case_command(const grade_case *k, const char *bin, const char *scene, const char *out,
                        unsigned long long seed, int threads, grade_case_text *text, char **argv);

/* ---- results ------------------------------------------------------------------------------- */

typedef struct {
    const grade_case *spec;
    bool ran;                  /* the render finished and its file was read */
    bool pass;                 /* it ran, its image matches and its figures are in bounds */
    char reason[256];          /* why it did not run or failed, when it did not pass */
    verdict v;                 /* the image verdict (when ran) */
    double spp, course_spp;    /* adaptive cases: mean samples per pixel, the candidate's and the course's */
    double rate_distance;      /* adaptive cases: the sample-rate map's distance from the course's
                                  (grade_rate_map_distance; -1: not judged) */
    double cpu, base_cpu;      /* work_check cases: CPU seconds of the candidate's render and of the
                                  baseline's, each as the kernel counted it (0: not judged) */
    bool base_is_scan;         /* the baseline is the framework's linear scan (a student's own tree),
                                  not the course's BVH (the autograder) */
    double noise;              /* noise_check cases: per-sample variance over the course's (0: not judged) */
    double score;
    char images[3][320];       /* candidate, reference, z-map PNGs, relative to the report folder */
    /* A failing case: the pixels that differ most from the reference, one line each with the
     * --trace-pixel command that replays the render of that pixel (framework/trace.h); or "". */
    char trace[1536];
    unsigned long long seed;   /* the seed of the render this result judges */
    /* Rendered twice (grade_image.h: a failure a correct render has by chance is confirmed or not by
     * a second render, which this result judges): the first render's seed and p-value. */
    bool rendered_twice;
    unsigned long long first_seed;
    double first_p;
    bool chance_failure;       /* set by the judge: it failed on its p-value alone (not its figures,
                                  not a bad pixel, not a deterministic case) */
} grade_case_result;

typedef struct {
    int part;
    const grade_part_spec *spec;  /* its tasks and cases */
    bool built;
    char build_log[320];       /* path of the compiler's output */
    char build_output[4096];   /* its last lines, when the part does not build */
    int tests_run, tests_failed;
    struct { char name[96]; bool passed; } tests[GRADE_MAX_TESTS];  /* each test's verdict, in the suite's order */
    int num_tests;
    double task_score[GRADE_MAX_TASKS];
    int task_passed[GRADE_MAX_TASKS], task_run[GRADE_MAX_TASKS];  /* per task of the spec: its tests that passed, ran */
    char suite_reason[256];    /* why the suite scored zero (crash, timeout, no results), or "" */
    char failures[8192];       /* names and messages of the failed tests, Markdown */
    double unit_score, unit_max;
    grade_case_result cases[GRADE_MAX_CASES];
    int num_cases;
    double score, max_score;
} grade_part_result;

typedef struct {
    uint64_t seed;             /* drawn at grading time, recorded */
    char unprotected[256];     /* the protections this machine could not give student code, or "" */
    double seconds;
    grade_part_result parts[GRADE_MAX_PART];
    int num_parts;
} grade_result;

/* ---- the score (grade_score.c: the one place points are computed) ---------------------------- */

/* Part p's unit, case and total points in r, from its verdicts: each task's share when all its
 * tests passed (none count when r->suite_reason says the suite could not be judged) and each
 * case's pass. */
void grade_score_part(const grade_part_spec *p, grade_part_result *r);
/* Records test `name`'s verdict in r (in the suite's order; names past GRADE_MAX_TESTS are dropped,
 * and the count check then fails the suite). */
void grade_score_note_test(grade_part_result *r, const char *name, bool passed);
/* The index of the task of p that test `name` belongs to, or -1. */
int grade_task_of(const grade_part_spec *p, const char *name);
/* The whole grading's points, and its maximum in *max. */
double grade_score_total(const grade_result *r, double *max);
/* A case's figures beside its image, each true where the case does not judge it: the adaptive
 * render's mean samples per pixel and its sample-rate map against the course's, and the render's
 * CPU time against the baseline's (GRADE_WORK_FACTOR, GRADE_SCAN_FACTOR). */
bool grade_case_spp_ok(const grade_case_result *c);
bool grade_case_rate_ok(const grade_case_result *c);
bool grade_case_work_ok(const grade_case_result *c);

/* ---- running children ---------------------------------------------------------------------- */

/* Every limit of the grader, in one place, each with its reason. Wall-clock limits are per stage;
 * CPU limits per process (RLIMIT_CPU), so a render's threads share its CPU allowance. */
/* -- wall clock */
#define GRADE_COMPILE_SECONDS 60         /* one submitted file's confined compile: a part's takes ~2 s */
#define GRADE_LINK_SECONDS 120           /* one graded program's link, as root, from the course's objects */
#define GRADE_COURSE_BUILD_SECONDS 900   /* the course's whole tree, once, trusted: ~60 s on a busy 2 cores */
#define GRADE_SUITE_SECONDS 300          /* a part's suite (a student's own tree, whole; a split suite, all
                                            its tests): the slowest (part 4) takes ~40 s */
#define GRADE_TEST_SECONDS 120           /* one test's subject in a split suite; the slowest takes ~8 s, but
                                            a correct full-sweep SAH build (course/alternatives) ran past
                                            60 s on a 2-core machine running five jobs: now that a failed
                                            test costs its task's share, a loaded grader must not fail it */
#define GRADE_JUDGE_SECONDS 150          /* its judge: it waits for the subject, so it gets longer */
#define GRADE_RENDER_SECONDS 120         /* one case's render: the slowest takes ~20 s at two threads */
#define GRADE_INSPECT_SECONDS 120        /* one tool reading the submission's objects (nm, objdump) */
#define GRADE_CPU_PER_WALL 2             /* CPU seconds per wall second: the grader's two threads */
/* -- memory, processes, files */
#define GRADE_COMPILER_MEMORY ((long)1 << 30)   /* cc1 on a part: ~150 MB; `#include "/dev/zero"` stops here */
#define GRADE_CODE_MEMORY ((long)4 << 30)       /* a render, a suite's subject or its judge: the largest
                                                   case needs ~600 MB */
#define GRADE_FILE_BYTES ((long)64 << 20)       /* any file a child writes (an object, the legacy XML) */
#define GRADE_TMP_BYTES ((long)64 << 20)        /* each of a stage's private /tmp, /var/tmp, /dev/shm */
#define GRADE_PROCESSES 256              /* the sandbox user's processes and threads: cc and its cc1, as */
/* -- what a submission may hold (grade_build.c's manifest) */
#define GRADE_SOURCE_FILES 32            /* files in one part's folder: the course's have 2 to 5 */
#define GRADE_SOURCE_BYTES ((long)1 << 20)   /* one submitted file: the course's largest is ~30 KB */
#define GRADE_SOURCE_NAME 64             /* characters of a file's name, [a-z0-9_] then .c or .h */
/* -- what the grader reads back */
#define GRADE_LOG_MAX (256 * 1024)       /* what the grader keeps of a child's output */
#define GRADE_TOOL_LOG_MAX (4 << 20)     /* a trusted tool's listing (nm over every object) */
#define GRADE_SCENE_MAX (64L << 20)      /* a hidden scene copied for its render */
#define GRADE_ROOT_MAX 1024              /* the course, --out and --submission paths: every path is one of
                                            these and short names, so buffers of 4096 always fit */
#define GRADE_FILM_MAX ((long)128 << 20) /* a streamed film: 136 bytes a pixel, far above any case */
#define GRADE_SUITE_XML_MAX (4L << 20)   /* a group's results file: far more than 100 tests need */
/* -- what the grader shows */
#define GRADE_DIAG_LINES 40              /* the compiler's lines about the student's own files */
#define GRADE_MESSAGE_MAX 700            /* bytes of one failed test's message */

/* Formatting into fixed buffers (grade_fmt.c). grade_path: a path, never cut: false (and a line on
 * stderr) when it does not fit, with out emptied; the caller gives up on what the path was for.
 * grade_msg: a message for a person, cut to fit with "..." at the end. */
bool grade_path(char *out, size_t size, const char *format, ...) __attribute__((format(printf, 3, 4)));
void grade_msg(char *out, size_t size, const char *format, ...) __attribute__((format(printf, 3, 4)));
/* Text for Markdown (results.json's "md" outputs): the first len bytes of in (to its NUL), every
 * character CommonMark could read as markup escaped with a backslash, cut to fit out (never inside a
 * character, a backslash never left alone). A text escaped so shows as itself, whatever it holds. */
void grade_md_escape(const char *in, size_t len, char *out, size_t size);

/* What a child sends the grader on a descriptor of its own besides its log (a render's film): the
 * grader reads it while the child runs, into memory, never through a file the child could name. */
typedef struct {
    int child_fd;              /* the descriptor number the child writes to (3 and up) */
    long max;                  /* keep at most this many bytes */
    char *data;                /* filled by grade_run: what arrived (malloc'd; the caller frees) */
    long len;
    bool overflow;             /* it sent more than max (data holds the first max bytes) */
} grade_capture;

typedef struct {
    double wall_seconds;       /* kill the whole process group after this */
    double deadline;           /* and at the latest at this clock_seconds() (the grading's deadline:
                                  grade_env), 0 for none; a child never starts past it */
    const char *cwd;           /* run in this folder */
    const char *log_path;      /* stdout and stderr go here (a fresh file the grader writes, in a folder
                                  the child cannot write), cut at log_max bytes; NULL: discarded */
    long log_max;
    char *const *env;          /* extra "NAME=value" entries, NULL-terminated, or NULL */
    bool untrusted;            /* runs student code: the sandbox's user, limits, namespaces, a private
                                  read-only view with its own /tmp, and the seccomp filter from its
                                  first instruction (grader/sandbox.h) */
    bool compiler;             /* with untrusted: the compiler or a tool reading student files, running
                                  none of them: all of the above but the filter (cc forks cc1 and as) */
    bool writes_files;         /* with untrusted: the filter lets it create files (the XML suite) */
    const char *writable;      /* with untrusted: the one folder it may write (its output), or NULL */
    bool bounded;              /* trusted, but reading what student code made (the linker on its
                                  objects, the judge on its records): the limits, as the grader's user */
    grade_capture *capture;    /* a second channel to the grader, or NULL */
} grade_run_opts;

/* What grade_run can do to contain untrusted code on this machine: limits always; a network
 * namespace, PID and mount namespaces and another user only as root (and not in a container whose
 * profile refuses namespaces: then limits, the user and the filter remain); the filter where libseccomp and the kernel allow. The
 * report names what was unavailable, the staff log what was in force. */
typedef struct {
    bool as_other_user;        /* runs as `nobody` (the grader is root) */
    bool no_network;           /* a new network namespace */
    bool isolated;             /* new PID and mount namespaces with their own /proc (sandbox_isolate) */
    unsigned uid, gid;         /* nobody's */
    long process_limit;        /* RLIMIT_NPROC for untrusted children (counts the whole user's) */
    bool filter;               /* the seccomp filter is installed before student code runs */
    const char *dir;           /* the sandbox's folder: the one a stage sees of its /tmp (grade_sandbox_keep) */
    char filter_why[160];      /* why not, when it is not */
} grade_sandbox;

/* Finds what this machine allows (call once, before any child runs). */
grade_sandbox grade_sandbox_probe(void);
/* The sandbox's folder, where every stage's files are: it stays in view when a stage gets a private
 * /tmp (call before any child runs, with a path that outlives the grading). */
void grade_sandbox_keep(grade_sandbox *s, const char *dir);
/* The protections this machine could not give, in words for the report ("" when none is missing). */
void grade_sandbox_describe(const grade_sandbox *s, char *out, size_t size);
/* The protections in force, for the staff log ("user nobody, network namespace, seccomp ..."). */
void grade_sandbox_in_force(const grade_sandbox *s, char *out, size_t size);

typedef struct {
    bool exited;               /* ended by exit(), not by a signal or the timeout */
    int status;                /* exit status when exited, else the signal */
    bool timed_out;
    bool out_of_time;          /* timed out at the grading's deadline, not at the stage's own limit (or
                                  not started: the deadline had passed) */
    bool output_cut;           /* it printed more than log_max */
    double seconds;            /* wall clock */
    double cpu_seconds;        /* user + system CPU time, the kernel's count (wait4), threads and
                                  waited-for descendants included */
} grade_run_result;

/* Runs argv as a child in its own process group; never reads what it prints except into the log. */
grade_run_result grade_run(char *const argv[], const grade_run_opts *o);
/* Runs the n jobs (argv[i] with o[i]) two at a time, the machine's cores, each in a helper process
 * of its own that adopts its job's orphans (so a job's clean-up never touches the other), and fills
 * r[i]. With stop_on_failure, no job starts after one failed (those read as not exited, status -1):
 * a part's compile stops at its first file that fails, so a file that stalls its compile costs one
 * compile's time, not one per file. Only jobs without a capture: a build's compiles and links. */
#define GRADE_JOBS 2
void grade_run_jobs(int n, char *const *const argv[], const grade_run_opts o[], grade_run_result r[], bool stop_on_failure);
/* Runs fn(arg, fd) in a forked child under o's limits and, with o->untrusted, the whole confinement
 * of an untrusted stage and the filter, installed before fn runs; the child never execs. For the
 * grader's own code reading hostile files (the object inspection): what fn writes to fd (the
 * capture's descriptor, o->capture required) arrives in o->capture. */
grade_run_result grade_run_function(void (*fn)(void *arg, int out_fd), void *arg, const grade_run_opts *o);
/* grade_run with pipe ends for the split suite (grade_judge.c): in_fd > 0 becomes the child's stdin
 * (else /dev/null), fd3 > 0 its fd 3. */
grade_run_result grade_run_piped(char *const argv[], const grade_run_opts *o, int in_fd, int fd3);
/* pipe(2) with both ends close-on-exec (POSIX has no pipe2): a child gets only the ends it is given. */
bool grade_pipe(int fds[2]);
/* A one-line reason for a child that did not exit normally ("killed by signal 11", "timed out"). */
void grade_run_describe(const grade_run_result *r, char *out, size_t size);
/* The words for running out of the grading's time (r->out_of_time), the same everywhere. */
#define GRADE_OUT_OF_TIME "the grading ran out of time (each part gets its share of the autograder's limit)"

/* ---- one part -------------------------------------------------------------------------------- */

typedef struct {
    const char *root;          /* the tree holding the other parts (the course's), or the student's tree */
    const char *submission;    /* a folder holding the submission's parts/, or NULL (cumulative) */
    const char *work;          /* the grader's scratch, root's alone: the course's build, logs, films */
    const char *sandbox_dir;   /* the only folder the sandbox's user may reach: the part's tree */
    const char *report;        /* the report folder (images and index.html) */
    bool public_only;
    uint64_t seed;
    int threads;
    double deadline;           /* clock_seconds() by which this part's grading must end (its share of
                                  bin/grade --deadline), 0 for none: every stage's limit is the least
                                  of its own and what is left (grade_run_opts.deadline) */
    grade_sandbox sandbox;     /* what containment this machine allows */
} grade_env;

/* Builds (or reuses) the tree for part p, runs its suite and cases, and fills r. */
void grade_part(const grade_env *env, const grade_spec *spec, const grade_part_spec *p, grade_part_result *r);
/* Fresh scratch for part `part`: work/partN (the grader's: logs) and work/partN/renders (the child's). */
bool grade_part_dirs(const grade_env *env, int part);
/* The split suite (grade_judge.c): each of part p's tests run as the subject (tree's
 * bin/subject-partN: the submission's code, contained) piped into the judge (the course's
 * bin/judge-partN under env->root, trusted, no student code), scored from the judge's results only. */
void grade_judge_suite(const grade_env *env, const char *tree, const grade_part_spec *p, grade_part_result *r);


/* ---- reports --------------------------------------------------------------------------------- */

void grade_print_table(const grade_result *r, FILE *out);
pl_status grade_write_results_json(const grade_result *r, const char *path, pl_diag *diag);
pl_status grade_write_html(const grade_result *r, const char *folder, pl_diag *diag);

#endif
