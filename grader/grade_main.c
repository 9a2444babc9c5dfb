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
#include "grade.h"
#include "grade_facts.h"
#include "grade_handout.h"
#include "../framework/clock.h"
#include "grade_guard.h"
#include "grade_image.h"
#include "grade_refs.h"
#include "grade_tree.h"
#include "sandbox.h"
#include <dirent.h>
#include <errno.h>
#include <math.h>
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
static uint64_t fresh_seed(void)
{
    uint64_t s = 0;
    FILE *f = fopen("/dev/urandom", "rb");
    if (!f || fread(&s, sizeof s, 1, f) != 1) s = (uint64_t)time(NULL) * 2654435761u;
    if (f) fclose(f);
    return s % 1000000000000ull;
}

/* --calibrate: the grader's own false-failure rate, measured on this tree (the solution). */
/* Whether name is one of the comma-separated names (NULL: every name). */
static bool name_listed(const char *names, const char *name)
{
    if (!names) return true;
    size_t len = strlen(name);
    for (const char *p = names; (p = strstr(p, name)) != NULL; p += len)
        if ((p == names || p[-1] == ',') && (p[len] == ',' || p[len] == '\0')) return true;
    return false;
}

/* The smallest and largest of a figure over the runs (NaN and negative values, "not judged", left out). */
typedef struct { double min, max; } figure_range;

static void range_add(figure_range *r, double x)
{
    if (!(x >= 0)) return;
    if (x < r->min) r->min = x;
    if (x > r->max) r->max = x;
}

static int calibrate(const grade_env *base, const grade_spec *spec, const char *parts, const char *cases, int runs)
{
    int worst = 0;
    printf("%-28s %6s %9s %9s %8s  p-value deciles\n", "case", "runs", "failures", "confirmed", "alpha");
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        char digit[2] = {(char)('1' + k), 0};
        if (!strstr(parts, digit)) continue;
        const grade_part_spec *p = &spec->parts[k];
        if (!grade_part_dirs(base, p->part)) {
            fprintf(stderr, "grade: cannot create %s/part%d\n", base->work, p->part);
            return 1;
        }
        for (int i = 0; i < p->num_cases; i++) {
            if (!name_listed(cases, p->cases[i].name)) continue;
            int failures = 0, confirmed = 0, decile[10] = {0};
            figure_range noise = {INFINITY, 0}, rate = {INFINITY, 0}, work = {INFINITY, 0};
            for (int run = 0; run < runs; run++) {
                grade_env env = *base;
                env.seed = fresh_seed();
                grade_case_result c;
                memset(&c, 0, sizeof c);
                c.spec = &p->cases[i];
                grade_image_case(&env, spec, env.root, p->part, &c);
                if (!c.ran) {
                    fprintf(stderr, "grade: %s: %s\n", c.spec->name, c.reason);
                    return 1;
                }
                /* Two counts: the first render's failures (the test's own rate, what its alpha claims)
                 * and the case's, confirmed by a second render (grade_image.h). A failure of the
                 * solution is a false failure: its seed makes it again. */
                bool first_failed = c.rendered_twice || !c.pass;
                double first_p = c.rendered_twice ? c.first_p : c.v.p_value;
                failures += first_failed;
                confirmed += !c.pass;
                if (first_failed)
                    fprintf(stderr, "grade: part %d, case %s fails at seed %llu (p = %.3g)%s: bin/grade --parts %d --seed %llu "
                                    "shows it\n", p->part, c.spec->name, (unsigned long long)env.seed, first_p,
                            c.pass ? ", its second render passes" : c.rendered_twice ? ", its second render too" : "",
                            p->part, (unsigned long long)env.seed);
                range_add(&noise, c.noise);
                range_add(&rate, c.rate_distance);
                range_add(&work, c.base_cpu > 0 ? c.cpu / c.base_cpu : NAN);
                decile[first_p >= 1.0 ? 9 : (int)(first_p * 10)]++;
                verdict_free(&c.v);
            }
            printf("part%d/%-22s %6d %9d %9d %8.0e ", p->part, p->cases[i].name, runs, failures, confirmed,
                   spec->family_alpha);
            for (int d = 0; d < 10; d++) printf(" %3d", decile[d]);
            if (p->cases[i].noise_check)
                printf("   noise ratio %.3f to %.3f (limit %.2f)", noise.min, noise.max, GRADE_NOISE_FACTOR);
            if (rate.max > 0)
                printf("   rate map distance %.3f to %.3f (limit %.2f)", rate.min, rate.max, GRADE_RATE_TOLERANCE);
            if (p->cases[i].work_check)  /* a tree's own grading: against the framework's linear scan */
                printf("   CPU time over the linear scan's %.4f to %.4f (limit %.4f)", work.min, work.max,
                       1.0 / GRADE_SCAN_FACTOR);
            printf("\n");
            fflush(stdout);
            worst = confirmed > worst ? confirmed : worst;
        }
    }
    return worst > 0;
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
        char path[4400];
        struct stat st;
        bool page = (n > 4 && !strcmp(e->d_name + n - 4, ".png")) || (n > 5 && !strcmp(e->d_name + n - 5, ".html"));
        if (page && grade_path(path, sizeof path, "%s/%s", report, e->d_name) && lstat(path, &st) == 0 && S_ISREG(st.st_mode))
            unlink(path);
    }
    if (d) closedir(d);
}

/* mkdir -p: the default out/grade may be the first thing made under out/. */
static bool make_dir(const char *path)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf) return false;
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST) return false;
            *p = '/';
        }
    return mkdir(buf, 0755) == 0 || errno == EEXIST;
}

/* The sandbox's folder: the only one the sandbox's user may enter (0711: it cannot list it either),
 * made fresh outside --out, so that an --out the sandbox's user cannot reach (a `mktemp -d` folder,
 * root's home) does not matter. */
static bool make_sandbox_dir(char *out, size_t size)
{
    const char *tmp = getenv("TMPDIR") && getenv("TMPDIR")[0] == '/' ? getenv("TMPDIR") : "/tmp";
    grade_path(out, size, "%s/" GRADE_SANDBOX_NAME "XXXXXX", tmp);
    return mkdtemp(out) && chmod(out, 0711) == 0;
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
static bool setup_ok(const grade_env *env, const char *outdir, const char *parts, char *why, size_t size)
{
    const grade_sandbox *s = &env->sandbox;
    if (s->as_other_user && !s->filter)
        return grade_msg(why, size, "student code cannot be confined: %s", s->filter_why), false;
    if (s->as_other_user && !reachable_by_sandbox_user(s, env->sandbox_dir))
        return grade_msg(why, size, "the sandbox's user cannot reach %s (a parent folder closed to others? set TMPDIR "
                                   "to a folder it can reach)", env->sandbox_dir), false;
    if (chmod(env->work, 0700) != 0) return grade_msg(why, size, "cannot make %s private", env->work), false;
    if (!grade_guard_secrets(env->root, outdir, s, why, size)) return false;
    return grade_tree_course_build(env, parts, why, size);
}

/* Grades the parts listed in `parts` into result; the staff log gets one line a part. */
/* Each part in turn. Under a deadline (--deadline), each gets an equal share of what is left when it
 * starts, so a part that stalls runs out of its own share and every later part still has its
 * own (what a quick part leaves goes to the parts after it). */
static void grade_parts(const grade_env *env, grade_spec *spec, const char *parts, grade_result *result)
{
    double t0 = clock_seconds();
    int left = 0;
    for (int k = 0; k < GRADE_MAX_PART; k++) left += strchr(parts, '1' + k) != NULL;
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        char digit[2] = {(char)('1' + k), 0};
        if (!strstr(parts, digit)) continue;
        fprintf(stderr, "grade: part %d ...\n", k + 1);
        grade_env part = *env;
        if (env->deadline > 0) part.deadline = clock_seconds() + (env->deadline - clock_seconds()) / left;
        left--;
        grade_part(&part, spec, &spec->parts[k], &result->parts[result->num_parts++]);
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
        if ((spec && spec->parts[k - 1].part != k) || !grade_part_folder(root, k, folder, sizeof folder)) continue;
        n += (size_t)snprintf(out + n, size - n, "%s%d", n ? "," : "", k);
    }
}

/* --parts against the course's: NULL, or what is wrong (a part the course lacks would be skipped
 * without a word). */
static const char *check_parts(const char *asked, const char *course)
{
    static char why[160];
    for (const char *c = asked; *c; c++) {
        if (*c == ',') continue;
        if (*c < '1' || *c > '9' || (c[1] && c[1] != ','))
            return "--parts: expected part numbers separated by commas, such as 1,3";
        if (!strchr(course, *c)) {
            snprintf(why, sizeof why, "--parts: part %c is not one of this course's (%s)", *c, course);
            return why;
        }
    }
    return NULL;
}

/* --prebuild: the course's objects built ahead of time (setup.sh, when the image is made), so that
 * each grading only copies and links them. */
static int prebuild_course(const char *root)
{
    char work[4200], why[512];
    grade_path(work, sizeof work, "%s/" GRADE_PREBUILD, root);
    if (!make_dir(work) || chmod(work, 0700) != 0) return usage("--prebuild: cannot create " GRADE_PREBUILD);
    grade_env env = {.root = root, .work = work};
    char parts[2 * GRADE_MAX_PART + 1];
    course_parts(root, NULL, parts, sizeof parts);
    if (!grade_tree_course_build(&env, parts, why, sizeof why)) {
        fprintf(stderr, "grade: --prebuild: %s\n", why);
        return 3;
    }
    fprintf(stderr, "grade: the course's objects are prebuilt in %s/course/build\n", work);
    return 0;
}

/* The table, results.json, the report and the staff's facts.json (grade_facts.h); as root with a submission, results.json and the report
 * made root's alone. The exit status: 0 full marks, 1 otherwise or when an output failed. */
static int write_outputs(const grade_result *result, const char *outdir, const grade_env *env)
{
    char json[4200], facts[4200], why[512];
    pl_diag diag = pl_diag_default();
    grade_print_table(result, stdout);
    grade_path(json, sizeof json, "%s/results.json", outdir);
    grade_path(facts, sizeof facts, "%s/facts.json", outdir);
    int code = 0;
    if (grade_write_results_json(result, json, &diag) != PL_OK || grade_write_html(result, env->report, &diag) != PL_OK ||
        grade_write_facts(result, facts, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        code = 1;
    }
    if (env->submission && !grade_guard_secrets(env->root, outdir, &env->sandbox, why, sizeof why)) {
        fprintf(stderr, "grade: %s\n", why);  /* the new results.json */
        code = 1;
    }
    printf("results: %s\nreport:  %s/index.html\n", json, env->report);
    for (int i = 0; i < result->num_parts; i++) code |= result->parts[i].score < result->parts[i].max_score;
    return code;
}

/* The verdicts' t maps, once every output is written (a leak test runs bin/grade under SAN=1). */
static void free_verdicts(grade_result *result)
{
    for (int i = 0; i < result->num_parts; i++)
        for (int k = 0; k < result->parts[i].num_cases; k++) verdict_free(&result->parts[i].cases[k].v);
}

/* The command line (see the top of this file). */
typedef struct {
    const char *submission, *out, *parts, *cases, *handout;
    bool public_only, seed_given, prebuild;
    uint64_t seed;
    int threads, calibrate_runs;
    double deadline;  /* --deadline: seconds the whole grading may take, 0 for no limit */
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
        grade_handout_path(k + 1, path, sizeof path);
        if (grade_handout_update(path, &spec.parts[k], write, &diag) != PL_OK) {
            fprintf(stderr, "grade: %s\n", diag.error);
            code = 1;
        }
    }
    grade_spec_free(&spec);
    return code;
}

/* ---- main: folders, the course's cases and references, the sandbox, then the parts ----------- */

/* The folders a run needs, as absolute paths: the course (the current folder), --out with its work/
 * and report/, and the submission. Every path the grader builds later starts with one of these, so
 * bounding them here (GRADE_ROOT_MAX) leaves room for every name joined onto them. NULL or why not. */
typedef struct { char root[GRADE_ROOT_MAX], outdir[GRADE_ROOT_MAX], work[4096], report[4096], submission[GRADE_ROOT_MAX]; } grade_folders;

static const char *open_folders(const grade_args *a, grade_folders *f)
{
    if (!getcwd(f->root, sizeof f->root)) return "cannot read the current folder (or its path is over 1 KiB)";
    if (a->prebuild) return NULL;
    char real[4096];
    if (!make_dir(a->out) || !realpath(a->out, real)) return "--out: cannot create the folder";
    if (!grade_path(f->outdir, sizeof f->outdir, "%s", real)) return "--out: its path is over 1 KiB";
    if (!grade_path(f->work, sizeof f->work, "%s/work", f->outdir) ||
        !grade_path(f->report, sizeof f->report, "%s/report", f->outdir) || !make_dir(f->work) || !make_dir(f->report))
        return "--out: cannot create its work/ and report/ folders";
    clear_report(f->report);
    f->submission[0] = '\0';
    if (!a->submission) return NULL;
    if (!realpath(a->submission, real)) return "--submission: no such folder";
    if (!grade_path(f->submission, sizeof f->submission, "%s", real)) return "--submission: its path is over 1 KiB";
    return NULL;
}

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
    static char parts[2 * GRADE_MAX_PART + 1];
    course_parts(root, spec, parts, sizeof parts);
    const char *bad = a->parts ? check_parts(a->parts, parts) : NULL;
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
static void announce_protections(const grade_env *env, grade_result *result)
{
    char in_force[512];
    grade_sandbox_in_force(&env->sandbox, in_force, sizeof in_force);
    fprintf(stderr, "grade: protections in force: %s\n", in_force);
    if (env->submission) grade_sandbox_describe(&env->sandbox, result->unprotected, sizeof result->unprotected);
    else if (!sandbox_confines(&env->sandbox))
        fprintf(stderr, "grade: no sandbox on this machine: your own code runs unconfined; "
                        "your official grade comes from the autograder\n");
    if (result->unprotected[0]) fprintf(stderr, "grade: unavailable protections: %s\n", result->unprotected);
}

int main(int argc, char **argv)
{
    double start = clock_seconds();
    grade_args a;
    const char *bad = parse_args(argc, argv, &a);
    if (bad) return usage(bad);
    if (a.handout) return handout_tables(!strcmp(a.handout, "write"));
    static grade_folders f;
    if ((bad = open_folders(&a, &f))) return usage(bad);
    if (a.prebuild) return prebuild_course(f.root);
    grade_spec spec;
    if (!load_course(f.root, &a, &spec)) return 2;
    grade_result result;
    memset(&result, 0, sizeof result);
    result.seed = a.seed_given ? a.seed : fresh_seed();
    char sandbox_dir[4096];
    if (!make_sandbox_dir(sandbox_dir, sizeof sandbox_dir)) return usage("cannot create the sandbox's folder under $TMPDIR or /tmp");
    if (janitor_start(sandbox_dir) < 0) fprintf(stderr, "grade: cannot fork a janitor: a grading stopped from outside may leave %s\n", sandbox_dir);
    /* The grader's own children (the course's build, its compilers) keep their temporary files in
     * the sandbox's folder too, which the janitor removes whole: a compiler killed mid-file cannot
     * delete its own. Root's alone (0700); student code gets an environment of its own. */
    char own_tmp[4200];
    grade_path(own_tmp, sizeof own_tmp, "%s/tmp", sandbox_dir);
    if (mkdir(own_tmp, 0700) != 0 || setenv("TMPDIR", own_tmp, 1) != 0)
        return usage("cannot create the grader's temporary folder in its sandbox folder");
    grade_env env = {.root = f.root, .submission = a.submission ? f.submission : NULL, .work = f.work,
                     .sandbox_dir = sandbox_dir, .report = f.report, .public_only = a.public_only, .seed = result.seed,
                     .threads = a.threads, .sandbox = grade_sandbox_probe()};
    /* The deadline counts from the grader's start, the course's build and checks included. */
    if (a.deadline > 0) env.deadline = start + a.deadline;
    grade_sandbox_keep(&env.sandbox, sandbox_dir);
    /* Before any child runs: the grader's own set-up, and the answers out of the children's reach. */
    char why[512] = "";
    bool set_up = !a.submission || setup_ok(&env, f.outdir, a.parts, why, sizeof why);
    if (set_up) announce_protections(&env, &result);
    else fprintf(stderr, "grade: the grader's set-up on this machine is wrong (the course's problem, not the "
                         "submission's): %s\n", why);
    int code = !set_up ? 3 : a.calibrate_runs > 0 ? calibrate(&env, &spec, a.parts, a.cases, a.calibrate_runs) : -1;
    if (code < 0) grade_parts(&env, &spec, a.parts, &result);
    grade_tree_remove(sandbox_dir);  /* every grading tree, before the outputs are written */
    if (code < 0) {
        code = write_outputs(&result, f.outdir, &env);
        free_verdicts(&result);
    }
    grade_spec_free(&spec);
    return code;
}
