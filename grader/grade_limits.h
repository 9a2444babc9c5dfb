/* Grader machinery: not part of any assignment.
 * Every limit and every bound of the grader, in one place, each with its reason: how many cases,
 * tests and files; the factors the figures of a case are judged by; and the wall-clock, CPU, memory,
 * file and output limits of each stage. Wall-clock limits are per stage, and each is cut to what
 * is left of the grading's deadline (grade_run_opts.deadline); CPU limits are per process
 * (RLIMIT_CPU), so a render's threads share its CPU allowance. */
#ifndef PL_GRADE_LIMITS_H
#define PL_GRADE_LIMITS_H

/* ---- counts ----------------------------------------------------------------------------------- */
#define GRADE_MAX_CASES 16
#define GRADE_MAX_FLAGS 16
#define GRADE_MAX_PART 9          /* parts are numbered 1..9 (folders parts/part<N>_<name>); a course has some
                                     of them: those grading/cases.json lists and its tree holds are graded */
#define GRADE_MAX_TASKS 8         /* a part's unit-test tasks ("unit_tasks" in cases.json) */
#define GRADE_MAX_MATCH 4         /* test-name prefixes per task */
#define GRADE_MAX_TESTS 256       /* tests in one suite: the course's largest has ~40 */

/* ---- the figures a case judges beside its image ------------------------------------------------ */

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


/* ---- stages ------------------------------------------------------------------------------------ */

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
#define GRADE_INSPECT_SECONDS 120        /* the object inspection (libelf, in a confined child): ~0.1 s */
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
#define GRADE_TOOL_LOG_MAX (4 << 20)     /* a file of the grader's own read whole (the recipes, a dependency file) */
#define GRADE_SCENE_MAX (64L << 20)      /* a hidden scene copied for its render */
#define GRADE_ROOT_MAX 1024              /* the course, --out and --submission paths: every path is one of
                                            these and short names, so buffers of 4096 always fit */
#define GRADE_FILM_MAX ((long)128 << 20) /* a streamed film: 136 bytes a pixel, far above any case */
#define GRADE_SUITE_XML_MAX (4L << 20)   /* a group's results file: far more than 100 tests need */
/* -- what the grader shows */
#define GRADE_DIAG_LINES 40              /* the compiler's lines about the student's own files */
#define GRADE_MESSAGE_MAX 700            /* bytes of one failed test's message */

#define GRADE_TRACE_PIXELS 3             /* pixels a failing public case names, with the command tracing each */
#define GRADE_BASELINE_RUNS 2            /* renders of a work_check case's baseline: the least CPU time counts */

#endif
