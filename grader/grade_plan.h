/* Grader machinery: not part of any assignment.
 * The plan stage: every path, command and limit a grading needs, made in one place before any stage
 * runs, so that no other module formats a path or builds a command (tests/grader/test_layout.c checks
 * it). The run's plan (grade_run_plan) says where the grading's folders are; a part's plan
 * (grade_plan) says, for one part, where its tree, logs and films go, how each of its files is
 * compiled and each program linked, how each test and each case runs, and by when. The stages after
 * it take what the plan and the stage before them hand on. */
#ifndef PL_GRADE_PLAN_H
#define PL_GRADE_PLAN_H

#include <stdbool.h>
#include "grade_env.h"
#include "grade_fmt.h"
#include "grade_manifest.h"
#include "grade_spec.h"

/* ---- the layout the grader relies on ---------------------------------------------------------- */

/* What the course's build is given: no link-time optimisation (the objects then hold machine code,
 * the inspection reads the very files linked, and ld --wrap sees every call of the split suites),
 * the course's warnings whatever the caller exported (CI's WERROR=1), and no sanitizer. */
#define GRADE_MAKE_ARGS "-j2", "--no-print-directory", "LTO=0", "WERROR=0", "SAN=0"
/* Where that build puts its objects, in the course's tree and so in every grading tree. */
#define GRADE_OBJECTS "build/release"
/* The graded build's recipes (grader/grader.mk writes them in the course's tree, before any student
 * code is seen): the compiler, a part file's flags, each program's link line. */
#define GRADE_RECIPES GRADE_OBJECTS "/grade-recipes.txt"
/* Where `bin/grade --prebuild` builds the course's objects ahead of time, under the root. */
#define GRADE_PREBUILD "out/grader-prebuild"
/* The name every sandbox folder starts with (one per grading, under $TMPDIR). */
#define GRADE_SANDBOX_NAME "pathlab-sandbox."

/* ---- the run's folders --------------------------------------------------------------------- */

/* Where a grading reads and writes: every path below starts with one of these. */
typedef struct {
    grade_path_buf root;        /* the course's tree (the current folder) */
    grade_path_buf out;         /* --out, absolute */
    grade_path_buf work;        /* out/work: the grader's scratch, root's alone */
    grade_path_buf report;      /* out/report: index.html and its pictures */
    grade_path_buf results;     /* out/results.json */
    grade_path_buf facts;       /* out/facts.json */
    grade_path_buf submission;  /* --submission, absolute ("" for a student's own tree) */
    grade_path_buf sandbox;     /* the sandbox's folder, $TMPDIR/pathlab-sandbox.XXXXXX (made by main) */
    grade_path_buf own_tmp;     /* sandbox/tmp: the grader's own children's temporary files */
    grade_path_buf course;      /* work/course: the course's tree, copied and built there */
    grade_path_buf course_log;  /* work/course-build.log */
    grade_path_buf prebuilt;    /* root/out/grader-prebuild: objects `bin/grade --prebuild` made */
} grade_run_plan;

/* The run's folders from the command line's: NULL, or what was wrong (a path over GRADE_ROOT_MAX
 * bytes, a submission that is not a folder). Makes out, work and report. */
const char *grade_plan_run(const char *out, const char *submission, grade_run_plan *rp);
/* The folders of `bin/grade --prebuild`: the course's build in root/GRADE_PREBUILD, which later
 * gradings copy (grade_plan_course_build). NULL, or what was wrong. */
const char *grade_plan_prebuild(grade_run_plan *rp);
/* Sets rp->sandbox to the template mkdtemp fills ($TMPDIR or /tmp), and rp->own_tmp below it once
 * filled (grade_plan_sandbox_made). */
void grade_plan_sandbox_template(grade_run_plan *rp);
void grade_plan_sandbox_made(grade_run_plan *rp);

/* What of the course student code must never reach (grade_guard.c makes each root's alone). */
#define GRADE_PLAN_SECRETS 11
typedef struct { grade_path_buf path[GRADE_PLAN_SECRETS]; bool file[GRADE_PLAN_SECRETS]; int count; } grade_secrets;
void grade_plan_secrets(const grade_run_plan *rp, grade_secrets *out);

/* The course's build: what is copied from the root into rp->course, and the make that builds it. */
#define GRADE_PLAN_COPIED 9
typedef struct {
    grade_path_buf from[GRADE_PLAN_COPIED + 2];  /* the course's pieces, then the prebuilt objects and programs */
    int count, prebuilt;                          /* prebuilt: how many of them are the last (copied if there) */
    char *make[16 + 2 * GRADE_MAX_PART];         /* make -C course ... bin/pathtracer, recipes, each part's programs */
    char programs[2 * GRADE_MAX_PART][32];
} grade_course_build;
void grade_plan_course_build(const grade_run_plan *rp, const char *parts, grade_course_build *out);

/* The folder of part n in tree (its parts/part<N>_<name>): "part2_bvh"; false when there is none. */
bool grade_plan_part_folder(const char *tree, int n, char *out, size_t size);
/* The submission's parts/<folder> (env->submission's), into out; false when it does not fit. */
bool grade_plan_submitted(const grade_env *env, const char *folder, char *out, size_t size);
/* The reference of case k of part `part`: root/reference_images/[hidden/]part<N>/<case>.exr; and the
 * JSON of its figures beside it (<case>.json). False when the path does not fit. */
bool grade_plan_reference(const char *root, const grade_case *k, int part, char *out, size_t size);
bool grade_plan_reference_json(const char *ref_exr, char *out, size_t size);
/* tests/part<N>, the part's suite's sources, relative to the course's top. */
void grade_plan_suite_sources(int n, char *out, size_t size);
/* handout/part<N>.md, relative to the course's top. */
void grade_plan_handout(int n, char *out, size_t size);

/* ---- a part's plan ---------------------------------------------------------------------------- */

/* A command: its words (pointing into the plan's own text), NULL-terminated. */
#define GRADE_PLAN_WORDS 1100
typedef struct { char *argv[GRADE_PLAN_WORDS]; } grade_command;

/* One submitted .c file: its compile and what comes out of it. */
typedef struct {
    char name[GRADE_SOURCE_NAME + 1];  /* "direct.c" */
    grade_path_buf source;             /* parts/<folder>/<name>, relative to the compile's folder */
    grade_path_buf compiled_obj;       /* the compile's output folder: <stem>.o, .d */
    grade_path_buf compiled_dep;
    grade_path_buf obj;                /* the same in the part's tree, after they are taken out */
    grade_path_buf dep;
    grade_path_buf log;                /* the compiler's output */
    grade_command compile;
} grade_plan_source;

/* One of the programs a submission's part links: the renderer, the split suite's subject. */
#define GRADE_PLAN_LINKS 2
typedef struct {
    const char *what;        /* "the renderer", "the suite" (the grader's words for a build that fails) */
    grade_path_buf log;
    grade_command link;      /* the course's recipe, the part's objects in place of the course's */
} grade_plan_link;

/* One image case: where its renders' outputs go and how it is rendered. */
typedef struct {
    const grade_case *spec;
    grade_path_buf log, again_log, baseline_log;  /* the candidate's render, its second try, the baseline's */
    grade_path_buf film;            /* the candidate's EXR, written by the grader from the film it received */
    grade_path_buf reference;       /* reference_images/[hidden/]part<N>/<case>.exr */
    grade_path_buf scene;           /* the scene the render reads (a hidden one: a copy in the tree) */
    grade_path_buf scene_source;    /* the course's file, where a copy is made from it; "" when none */
    grade_path_buf baseline_cwd, baseline;  /* the work_check baseline: its folder and renderer */
    char images[3][160];            /* the report's pictures: candidate, reference, z-map (names in the report folder) */
    grade_path_buf image_paths[3];
} grade_plan_case;

/* A folder copied into another (cp -a from into to's parent, or a folder's headers into to). */
typedef struct { grade_path_buf from, to; } grade_plan_copy;

typedef struct grade_plan {
    int part;
    char folder[64];                  /* the course's folder of the part, "part2_bvh" */
    double deadline;                  /* this part's share of the grading's deadline (clock_seconds), or 0 */
    bool submission;                  /* a submission's part (built and confined), or a student's own tree */
    grade_path_buf work;              /* work/part<N>: the grader's own logs and films */
    grade_path_buf tree;              /* where the part is built and run: sandbox/part<N>, or the root */
    /* the build of a submission */
    grade_path_buf submitted;         /* the submission's parts/<folder> */
    grade_path_buf scratch, scratch_src, scratch_out, objects, tree_sources, build_log, tree_log, inspect_log;
    /* the compile's source folder: the course's headers (the framework's, each part's), and the part's
     * own submitted files in scratch_part */
    grade_plan_copy header_dirs[GRADE_MAX_PART + 1];
    int num_header_dirs;
    grade_path_buf scratch_parts, scratch_part;  /* scratch_src/parts, and the part's folder in it */
    /* the part's tree: the course's pieces copied in (into tree), every part's headers, the other
     * parts' object folders (closed to the sandbox's user) */
    grade_path_buf tree_bin;
    grade_plan_copy tree_pieces[8];
    int num_tree_pieces;
    grade_plan_copy tree_headers[GRADE_MAX_PART];
    int num_tree_headers;
    grade_path_buf other_objects[GRADE_MAX_PART];
    int num_other_objects;
    /* the inspection's course: its program of the part, and its own objects of the part */
    grade_path_buf course_program, course_objects;
    grade_plan_source sources[GRADE_SOURCE_FILES];
    int num_sources;
    grade_plan_link links[GRADE_PLAN_LINKS];
    char tmpdir_env[GRADE_PATH + 8];  /* TMPDIR=<the compile's output folder> */
    grade_command own_build;          /* a student's own tree: make -C root bin/pathtracer bin/test-part<N> */
    char own_target[32];
    /* the suite */
    grade_path_buf suite_dir;         /* a student's own tree: where its XML results go (sandbox/part<N>-suite) */
    char suite_xml_env[GRADE_PATH + 32];
    grade_path_buf suite_log, suite_list_log, test_program;
    grade_path_buf split_dir;         /* a submission: work/part<N>/split, the subjects' and judge's logs */
    grade_path_buf judge, subject, tests_list_log;
    /* the renders */
    grade_path_buf pathtracer;
    grade_plan_case cases[GRADE_MAX_CASES];
    int num_cases;
    /* the text the commands' words point into */
    char *text;
    size_t text_used, text_size;
} grade_plan;

/* Part p's plan in the grading env (its folders: rp), with the manifest m of a submission (NULL for a
 * student's own tree), its share of the deadline from now. False with why: a path that does not fit,
 * the course's recipes missing (the course's problem). Free with grade_plan_free. */
bool grade_plan_part(const grade_env *env, const grade_run_plan *rp, const grade_part_spec *p, const grade_manifest *m,
                     double deadline, grade_plan *out, char *why, size_t size);
void grade_plan_free(grade_plan *plan);  /* NULL-safe */

/* One test of the split suite: where its subject's and judge's logs and results go, and their
 * environments (the test's name in PL_TEST_FILTER). */
typedef struct {
    grade_path_buf subject_log, judge_log, judge_xml;
    char filter_env[200], xml_env[GRADE_PATH + 32];
    char *subject_env[3], *judge_env[5];
} grade_plan_test;
bool grade_plan_split_test(const grade_plan *plan, int k, const char *name, grade_plan_test *out);

/* The command of case k's own render (its flags, resolution and samples; not the reference's):
 * `bin flags... -r W H -s S --seed SEED -t THREADS -q -f out scene` (out NULL: `--film-fd 3`, the film
 * to the grader's pipe), with `--no-bvh` after the program when no_bvh, into argv (room for
 * GRADE_MAX_FLAGS + 17 entries, NULL-terminated), the numbers formatted into text. The grader renders
 * a candidate with it, the reference maker the course's figures (course/references). */
#define GRADE_FILM_FD 3
#define GRADE_FILM_FD_TEXT "3"
typedef struct { char width[16], height[16], samples[16], seed[32], threads[16]; } grade_case_text;
void grade_plan_case_command(const grade_case *k, const char *bin, const char *scene, const char *out,
                             unsigned long long seed, int threads, bool no_bvh, grade_case_text *text, char **argv);

#endif
