/* Grader machinery: not part of any assignment.
 * bin/grade [--submission DIR] [--public] [--out DIR] [--seed N] [--threads N] [--parts 1,3] [--deadline S]
 * bin/grade --calibrate N [--parts ...] [--cases name,name]
 * bin/grade --prebuild   build the course's objects ahead of time (setup.sh), for every grading to reuse
 * bin/grade --handout write|check   the grading tables of handout/part<N>.md from grading/cases.json
 *   --submission DIR  grade DIR/parts/ part by part, each among the solution's other parts (autograder);
 *                     without it, grade this tree as it is, public cases only (a student's make grade)
 *   --out DIR         where results.json, the report (DIR/report/index.html) and scratch go (out/grade)
 *   --deadline S      the whole grading ends within S seconds of the start (the autograder passes its own
 *                     limit, less the time it needs after): every stage's limit is the least of its own
 *                     and what is left of its part's share; what ran out says so, what finished counts
 *   --calibrate N     render every case of this tree N times with fresh seeds and print, per case, how
 *                     often its first render failed beside the alpha it claims, how often the case
 *                     failed (its second render too), and the deciles of the first render's p-values
 *   --cases A,B       with --calibrate: only the cases of these names (a slow case's 2,000 runs alone)
 * Exit status: 0 when every graded part got full marks, 1 otherwise, 2 for bad arguments or a course's
 * file that is not usable (grading/cases.json, a reference: grade_refs.h), before anyone is graded, 3
 * when the grader's own set-up on this machine is wrong (the course's problem: no part was graded). */
#include "grade_calibrate.h"
#include "grade_facts.h"
#include "grade_guard.h"
#include "grade_handout.h"
#include "grade_part.h"
#include "grade_plan.h"
#include "grade_refs.h"
#include "grade_report.h"
#include "grade_score.h"
#include "grade_tree.h"
#include "grade_words.h"
#include "sandbox.h"
#include "../framework/clock.h"
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static int usage(const char *msg)
{
    fprintf(stderr, "grade: %s\nusage: grade [--submission DIR] [--public] [--out DIR] [--seed N] [--threads N] [--prebuild] "
                    "[--parts 1,2,...] [--deadline S]\n       grade --calibrate N [--parts 1,2,...] [--cases name,...]\n       grade --handout write|check\n", msg);
    return 2;
}

/* The grading seed: fresh from the kernel unless given, and recorded in every output. /dev/urandom
 * is on Linux and macOS alike (getrandom is Linux's). */
static unsigned long long fresh_seed(void)
{
    uint64_t s = 0;
    FILE *f = fopen("/dev/urandom", "rb");
    if (!f || fread(&s, sizeof s, 1, f) != 1) s = (uint64_t)time(NULL) * 2654435761u;
    if (f) fclose(f);
    return s % 1000000000000ull;
}

/* Whether this machine confines student code as the autograder does (namespaces). A student's
 * laptop often cannot (macOS, a user without privileges): make grade then runs their own code
 * unconfined, which is safe for their own code and gives the same verdicts. */
static bool sandbox_confines(const grade_sandbox *s)
{
    return s->no_network;
}

/* The report folder holds this run's pages and pictures only: the PNGs and pages an earlier run left
 * (another part's cases) are removed, regular files directly inside it and nothing else. */
static void clear_report(const char *report)
{
    DIR *d = opendir(report);
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        grade_path_buf path;
        struct stat st;
        bool page = (n > 4 && !strcmp(e->d_name + n - 4, ".png")) || (n > 5 && !strcmp(e->d_name + n - 5, ".html"));
        if (page && grade_join(report, e->d_name, path, sizeof path) && lstat(path, &st) == 0 && S_ISREG(st.st_mode))
            unlink(path);
    }
    if (d) closedir(d);
}

/* The sandbox's folder: the only one the sandbox's user may enter (0711: it cannot list it either),
 * made fresh outside --out (the plan names it under $TMPDIR), so that an --out the sandbox's user
 * cannot reach (a `mktemp -d` folder, root's home) does not matter. */
static bool make_sandbox_dir(grade_run_plan *rp)
{
    grade_plan_sandbox_template(rp);
    if (!mkdtemp(rp->sandbox) || chmod(rp->sandbox, 0711) != 0) return false;
    grade_plan_sandbox_made(rp);
    return true;
}

/* ---- the janitor ---------------------------------------------------------------------------- */

/* A grading stopped from outside (a Ctrl-C, a CI job's timeout, `kill`) would leave
 * its sandbox folder behind, with whatever the sandbox's user wrote in it, and its stages running
 * until their own limits end them: they sit in process groups of their own, out of reach of a
 * terminal's signal. So the grading runs in a child, and its parent, the janitor, waits: it hands
 * on the signals that stop a grading, and when the grading has ended, however it ended, kills what
 * is left of it (the orphans it adopted: the stages and their namespaces) and removes the folder. */
static volatile sig_atomic_t janitor_child;

static void janitor_forward(int sig)
{
    if (janitor_child > 0) kill((pid_t)janitor_child, sig);
}

/* Returns in the grading process (0), or -1 when there is no janitor (fork failed: the grading
 * runs as before); the janitor itself never returns: it exits as its grading did. */
static int janitor_start(const char *sandbox_dir)
{
    static const int stops[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    sigset_t held, before;
    sigemptyset(&held);
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++) sigaddset(&held, stops[i]);
    /* Held from the fork until the janitor forwards them: a stop that comes in between waits,
     * rather than ending the janitor alone and leaving its grading without one. */
    sigprocmask(SIG_BLOCK, &held, &before);
    fflush(stdout);  /* nothing buffered may be written twice */
    fflush(stderr);
    pid_t pid = fork();
    if (pid <= 0) {
        sigprocmask(SIG_SETMASK, &before, NULL);
        return pid == 0 ? 0 : -1;
    }
    janitor_child = pid;
    sandbox_adopt_orphans();
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++) {
        struct sigaction sa = {.sa_handler = janitor_forward};  /* no SA_RESTART: waitpid returns */
        sigemptyset(&sa.sa_mask);
        sigaction(stops[i], &sa, NULL);
    }
    sigprocmask(SIG_SETMASK, &before, NULL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) continue;
    sandbox_kill_orphans();
    grade_tree_remove(sandbox_dir);  /* done already when the grading ended by itself */
    if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
    int sig = WIFSIGNALED(status) ? WTERMSIG(status) : SIGTERM;
    signal(sig, SIG_DFL);
    raise(sig);  /* ends as the grading did, so a shell sees the same status */
    _exit(128 + sig);
}

/* Whether the sandbox's user can enter path (tried as that user, in a throwaway child). */
static bool reachable_by_sandbox_user(const grade_sandbox *s, const char *path)
{
    pid_t pid = fork();
    if (pid == 0) _exit(setgid(s->gid) == 0 && setuid(s->uid) == 0 && access(path, X_OK) == 0 ? 0 : 1);
    int status = 1;
    if (pid > 0) waitpid(pid, &status, 0);
    return pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* The grader's own set-up, checked before any part is graded (a submission, as root): the filter,
 * the sandbox's folder, the secrets out of reach, the course's own build. False with why: the
 * course's problem, which must never become a student's 0. */
static bool setup_ok(const grade_env *env, const grade_run_plan *rp, const char *parts, char *why, size_t size)
{
    const grade_sandbox *s = &env->sandbox;
    if (s->as_other_user && !s->filter)
        return grade_msg(why, size, "student code cannot be confined: %s", s->filter_why), false;
    if (s->as_other_user && !reachable_by_sandbox_user(s, env->sandbox_dir))
        return grade_msg(why, size, "the sandbox's user cannot reach %s (a parent folder closed to others? set TMPDIR "
                                   "to a folder it can reach)", env->sandbox_dir), false;
    if (chmod(env->work, 0700) != 0) return grade_msg(why, size, "cannot make %s private", env->work), false;
    grade_secrets secrets;
    grade_plan_secrets(rp, &secrets);
    if (!grade_guard_secrets(&secrets, s, why, size)) return false;
    return grade_tree_course_build(rp, parts, why, size);
}

/* Grades the parts listed in `parts` into result; the staff log gets one line a part. */
/* Each part in turn. Under a deadline (--deadline), each gets an equal share of what is left when it
 * starts, so a part that stalls runs out of its own share and every later part still has its
 * own (what a quick part leaves goes to the parts after it). */
static void grade_parts(const grade_env *env, const grade_run_plan *rp, const grade_spec *spec, const char *parts,
                        grade_result *result)
{
    double t0 = clock_seconds();
    int left = 0;
    for (int k = 0; k < GRADE_MAX_PART; k++) left += strchr(parts, '1' + k) != NULL;
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        char digit[2] = {(char)('1' + k), 0};
        if (!strstr(parts, digit)) continue;
        fprintf(stderr, "grade: part %d ...\n", k + 1);
        double deadline = env->deadline > 0 ? clock_seconds() + (env->deadline - clock_seconds()) / left : 0;
        left--;
        grade_part(env, rp, spec, &spec->parts[k], deadline, &result->parts[result->num_parts++]);
        result->seconds = clock_seconds() - t0;
    }
}

/* The course's parts as "1,2,3,4,5": each part the tree at root holds (a folder parts/part<N>_<name>)
 * and, given a spec, grading/cases.json lists. A course that left a part out (COURSE_PARTS) has no
 * folder for it, whatever cases.json says. */
static void course_parts(const char *root, const grade_spec *spec, char *out, size_t size)
{
    size_t n = 0;
    out[0] = '\0';
    for (int k = 1; k <= GRADE_MAX_PART && n < size; k++) {
        char folder[256];
        if ((spec && spec->parts[k - 1].part != k) || !grade_plan_part_folder(root, k, folder, sizeof folder)) continue;
        n += (size_t)snprintf(out + n, size - n, "%s%d", n ? "," : "", k);
    }
}

/* --parts against the course's: NULL, or what is wrong (a part the course lacks would be skipped
 * without a word). */
static const char *check_parts(const char *asked, const char *course, char *why, size_t size)
{
    for (const char *c = asked; *c; c++) {
        if (*c == ',') continue;
        if (*c < '1' || *c > '9' || (c[1] && c[1] != ','))
            return "--parts: expected part numbers separated by commas, such as 1,3";
        if (!strchr(course, *c)) {
            snprintf(why, size, "--parts: part %c is not one of this course's (%s)", *c, course);
            return why;
        }
    }
    return NULL;
}

/* --prebuild: the course's objects built ahead of time (setup.sh, when the image is made), so that
 * each grading only copies and links them. */
static int prebuild_course(void)
{
    grade_run_plan *rp = calloc(1, sizeof *rp);
    char why[512], parts[2 * GRADE_MAX_PART + 1];
    const char *bad = rp ? grade_plan_prebuild(rp) : "out of memory";
    if (bad) {
        free(rp);
        return usage(bad);
    }
    course_parts(rp->root, NULL, parts, sizeof parts);
    int code = 0;
    if (!grade_tree_course_build(rp, parts, why, sizeof why)) {
        fprintf(stderr, "grade: --prebuild: %s\n", why);
        code = 3;
    }
    else fprintf(stderr, "grade: the course's objects are prebuilt in %s/build\n", rp->course);
    free(rp);
    return code;
}

/* The table, results.json, the report and the staff's facts.json (grade_facts.h); as root with a submission, results.json and the report
 * made root's alone. The exit status: 0 full marks, 1 otherwise or when an output failed. */
static int write_outputs(const grade_result *result, const grade_run_plan *rp, const grade_env *env)
{
    char why[512];
    pl_diag diag = pl_diag_default();
    grade_report_table(result, stdout);
    int code = 0;
    if (grade_report_results_json(result, rp->results, &diag) != PL_OK || grade_report_html(result, rp->report, &diag) != PL_OK ||
        grade_facts_write(result, rp->facts, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        code = 1;
    }
    grade_secrets secrets;
    grade_plan_secrets(rp, &secrets);
    if (env->submission && !grade_guard_secrets(&secrets, &env->sandbox, why, sizeof why)) {
        fprintf(stderr, "grade: %s\n", why);  /* the new results.json */
        code = 1;
    }
    printf("results: %s\nreport:  %s/index.html\n", rp->results, rp->report);
    for (int i = 0; i < result->num_parts; i++) code |= result->parts[i].score < result->parts[i].max_score;
    return code;
}

/* The command line (see the top of this file). */
typedef struct {
    const char *submission, *out, *parts, *cases, *handout;
    bool public_only, seed_given, prebuild;
    uint64_t seed;
    int threads, calibrate_runs;
    double deadline;  /* --deadline: seconds the whole grading may take, 0 for no limit */
    char course_parts[2 * GRADE_MAX_PART + 1];  /* the course's parts, "1,2,3": parts by default */
} grade_args;

/* Reads argv into a; NULL, or what was wrong. */
static const char *parse_args(int argc, char **argv, grade_args *a)
{
    *a = (grade_args){.out = "out/grade", .threads = 2};  /* .parts NULL: the course's (course_parts) */
    for (int i = 1; i < argc; i++) {
        const char *f = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(f, "--public")) a->public_only = true;
        else if (!strcmp(f, "--prebuild")) a->prebuild = true;
        else if (!v) return "missing value";
        else if (!strcmp(f, "--submission")) a->submission = argv[++i];
        else if (!strcmp(f, "--out")) a->out = argv[++i];
        else if (!strcmp(f, "--parts")) a->parts = argv[++i];
        else if (!strcmp(f, "--seed")) { a->seed = strtoull(argv[++i], NULL, 10); a->seed_given = true; }
        else if (!strcmp(f, "--threads")) a->threads = atoi(argv[++i]);
        else if (!strcmp(f, "--deadline")) a->deadline = strtod(argv[++i], NULL);
        else if (!strcmp(f, "--calibrate")) a->calibrate_runs = atoi(argv[++i]);
        else if (!strcmp(f, "--cases")) a->cases = argv[++i];
        else if (!strcmp(f, "--handout")) a->handout = argv[++i];
        else return "unknown option";
    }
    if (a->threads < 1 || a->threads > 64) return "--threads: expected 1..64";
    if (!(a->deadline >= 0 && a->deadline <= 86400)) return "--deadline: expected seconds, 0..86400";
    if (a->handout && strcmp(a->handout, "write") && strcmp(a->handout, "check")) return "--handout: expected write or check";
    if (!a->submission) a->public_only = true;  /* a student's own tree has no hidden cases */
    return NULL;
}

/* --handout write|check: each part's grading table in handout/part<N>.md against grading/cases.json's
 * public cases (grade_handout.h). */
static int handout_tables(bool write)
{
    grade_spec spec;
    pl_diag diag = pl_diag_default();
    if (grade_spec_load(GRADE_CASES, NULL, &spec, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        return 2;
    }
    int code = 0;
    char parts[2 * GRADE_MAX_PART + 1];
    course_parts(".", &spec, parts, sizeof parts);
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        if (!strchr(parts, '1' + k)) continue;  /* a part the course has not (or cases.json does not list) */
        char path[64];
        grade_plan_handout(k + 1, path, sizeof path);
        if (grade_handout_update(path, &spec.parts[k], write, &diag) != PL_OK) {
            fprintf(stderr, "grade: %s\n", diag.error);
            code = 1;
        }
    }
    grade_spec_free(&spec);
    return code;
}

/* ---- main: folders, the course's cases and references, the sandbox, then the parts ----------- */

/* The cases, the parts to grade (--parts, checked against the course's; by default the course's),
 * and the course's references checked before anyone is graded: a broken one stops the run as the
 * course's error (exit 2), never a check skipped or a student's 0. */
static bool load_course(const char *root, grade_args *a, grade_spec *spec)
{
    pl_diag diag = pl_diag_default();
    if (grade_spec_load(GRADE_CASES, GRADE_HIDDEN_CASES, spec, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        return false;
    }
    char *parts = a->course_parts, why[160];
    course_parts(root, spec, parts, sizeof a->course_parts);
    const char *bad = a->parts ? check_parts(a->parts, parts, why, sizeof why) : NULL;
    if (!a->parts) a->parts = parts;
    if (bad || !parts[0]) {
        fprintf(stderr, "grade: %s\n", bad ? bad : "this tree has none of the parts grading/cases.json lists");
        grade_spec_free(spec);
        return false;
    }
    if (grade_refs_check(root, spec, a->parts, a->public_only, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        grade_spec_free(spec);
        return false;
    }
    return true;
}

/* The protections: those in force go to the staff log; those missing to a submission's report, or
 * to a student grading their own tree as a warning (their own code on their own machine:
 * containment is the autograder's concern). */
static void announce_protections(const grade_env *env)
{
    char in_force[512], missing[512];
    grade_words_protections_in_force(&env->sandbox, in_force, sizeof in_force);
    fprintf(stderr, "grade: protections in force: %s\n", in_force);
    grade_words_protections_missing(&env->sandbox, missing, sizeof missing);
    if (env->submission && missing[0]) fprintf(stderr, "grade: unavailable protections: %s\n", missing);
    else if (!env->submission && !sandbox_confines(&env->sandbox))
        fprintf(stderr, "grade: no sandbox on this machine: your own code runs unconfined; "
                        "your official grade comes from the autograder\n");
}

int main(int argc, char **argv)
{
    double start = clock_seconds();
    grade_args a;
    const char *bad = parse_args(argc, argv, &a);
    if (bad) return usage(bad);
    if (a.handout) return handout_tables(!strcmp(a.handout, "write"));
    if (a.prebuild) return prebuild_course();
    /* The run's plan: every folder of the grading, each path bounded (grade_plan.h). */
    grade_run_plan rp;
    if ((bad = grade_plan_run(a.out, a.submission, &rp))) return usage(bad);
    clear_report(rp.report);
    grade_spec spec;
    if (!load_course(rp.root, &a, &spec)) return 2;
    grade_result *result = grade_result_new();
    if (!result) return usage("out of memory");
    result->seed = a.seed_given ? a.seed : fresh_seed();
    result->submission = a.submission != NULL;
    if (!make_sandbox_dir(&rp)) return usage("cannot create the sandbox's folder under $TMPDIR or /tmp");
    if (janitor_start(rp.sandbox) < 0) fprintf(stderr, "grade: cannot fork a janitor: a grading stopped from outside may leave %s\n", rp.sandbox);
    /* The grader's own children (the course's build, its compilers) keep their temporary files in
     * the sandbox's folder too, which the janitor removes whole: a compiler killed mid-file cannot
     * delete its own. Root's alone (0700); student code gets an environment of its own. */
    if (mkdir(rp.own_tmp, 0700) != 0 || setenv("TMPDIR", rp.own_tmp, 1) != 0)
        return usage("cannot create the grader's temporary folder in its sandbox folder");
    grade_env env = {.root = rp.root, .submission = a.submission ? rp.submission : NULL, .work = rp.work,
                     .sandbox_dir = rp.sandbox, .report = rp.report, .public_only = a.public_only, .seed = result->seed,
                     .threads = a.threads, .sandbox = grade_sandbox_probe()};
    /* The deadline counts from the grader's start, the course's build and checks included. */
    if (a.deadline > 0) env.deadline = start + a.deadline;
    grade_sandbox_keep(&env.sandbox, rp.sandbox);
    result->sandbox = env.sandbox;
    /* Before any child runs: the grader's own set-up, and the answers out of the children's reach. */
    char why[512] = "";
    bool set_up = !a.submission || setup_ok(&env, &rp, a.parts, why, sizeof why);
    if (set_up) announce_protections(&env);
    else fprintf(stderr, "grade: the grader's set-up on this machine is wrong (the course's problem, not the "
                         "submission's): %s\n", why);
    int code = !set_up ? 3
             : a.calibrate_runs > 0 ? grade_calibrate(&env, &rp, &spec, a.parts, a.cases, a.calibrate_runs, fresh_seed)
                                    : -1;
    if (code < 0) grade_parts(&env, &rp, &spec, a.parts, result);
    grade_tree_remove(rp.sandbox);  /* every grading tree, before the outputs are written */
    if (code < 0) code = write_outputs(result, &rp, &env);
    grade_result_free(result);
    grade_spec_free(&spec);
    return code;
}
