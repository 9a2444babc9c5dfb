/* Grader machinery: not part of any assignment.
 * bin/grade [--submission DIR] [--public] [--out DIR] [--seed N] [--threads N] [--parts 1,3]
 * bin/grade --calibrate N [--parts ...] [--cases name,name]
 *   --submission DIR  grade DIR/parts/ part by part, each among the solution's other parts (autograder);
 *                     without it, grade this tree as it is, public cases only (a student's make grade)
 *   --out DIR         where results.json, the report (DIR/report/index.html) and scratch go (out/grade)
 *   --calibrate N     render every case of this tree N times with fresh seeds and print, per case, how
 *                     often it failed beside the alpha it claims, and the deciles of its p-values
 *   --cases A,B       with --calibrate: only the cases of these names (a slow case's 2,000 runs alone)
 * Exit status: 0 when every graded part got full marks, 1 otherwise, 2 for bad arguments. */
#include "grade.h"
#include "grade_guard.h"
#include "grade_image.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int usage(const char *msg)
{
    fprintf(stderr, "grade: %s\nusage: grade [--submission DIR] [--public] [--out DIR] [--seed N] [--threads N] "
                    "[--parts 1,2,...]\n       grade --calibrate N [--parts 1,2,...] [--cases name,...]\n", msg);
    return 2;
}

/* The grading seed: fresh from the kernel unless given, and recorded in every output. */
static uint64_t fresh_seed(void)
{
    uint64_t s = 0;
    if (getrandom(&s, sizeof s, 0) != (ssize_t)sizeof s) s = (uint64_t)time(NULL) * 2654435761u;
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

static int calibrate(const grade_env *base, const grade_spec *spec, const char *parts, const char *cases, int runs)
{
    int worst = 0;
    printf("%-28s %6s %9s %8s  p-value deciles\n", "case", "runs", "failures", "alpha");
    for (int k = 0; k < GRADE_NUM_PARTS; k++) {
        char digit[2] = {(char)('1' + k), 0};
        if (!strstr(parts, digit)) continue;
        const grade_part_spec *p = &spec->parts[k];
        if (!grade_part_dirs(base, p->part)) {
            fprintf(stderr, "grade: cannot create %s/part%d\n", base->work, p->part);
            return 1;
        }
        for (int i = 0; i < p->num_cases; i++) {
            if (!name_listed(cases, p->cases[i].name)) continue;
            int failures = 0, decile[10] = {0};
            double noise_min = INFINITY, noise_max = 0.0;  /* noise_check cases: the range over the runs */
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
                failures += !c.pass;
                noise_max = c.noise > noise_max ? c.noise : noise_max;
                noise_min = c.noise < noise_min ? c.noise : noise_min;
                decile[c.v.p_value >= 1.0 ? 9 : (int)(c.v.p_value * 10)]++;
                verdict_free(&c.v);
            }
            printf("part%d/%-22s %6d %9d %8.0e ", p->part, p->cases[i].name, runs, failures, spec->family_alpha);
            for (int d = 0; d < 10; d++) printf(" %3d", decile[d]);
            if (p->cases[i].noise_check) printf("   noise ratio %.3f to %.3f (limit %.2f)", noise_min, noise_max,
                                                   GRADE_NOISE_FACTOR);
            printf("\n");
            fflush(stdout);
            worst = failures > worst ? failures : worst;
        }
    }
    return worst > 0;
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

int main(int argc, char **argv)
{
    const char *submission = NULL, *out = "out/grade", *parts = "1,2,3,4,5", *cases = NULL;
    bool public_only = false, seed_given = false;
    uint64_t seed = 0;
    int threads = 2, calibrate_runs = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--public")) public_only = true;
        else if (!v) return usage("missing value");
        else if (!strcmp(a, "--submission")) submission = argv[++i];
        else if (!strcmp(a, "--out")) out = argv[++i];
        else if (!strcmp(a, "--parts")) parts = argv[++i];
        else if (!strcmp(a, "--seed")) { seed = strtoull(argv[++i], NULL, 10); seed_given = true; }
        else if (!strcmp(a, "--threads")) threads = atoi(argv[++i]);
        else if (!strcmp(a, "--calibrate")) calibrate_runs = atoi(argv[++i]);
        else if (!strcmp(a, "--cases")) cases = argv[++i];
        else return usage("unknown option");
    }
    if (threads < 1 || threads > 64) return usage("--threads: expected 1..64");
    if (!submission) public_only = true;  /* a student's own tree has no hidden cases */

    char root[4096], outdir[4096], work[4096], report[4096], json[4200];
    if (!getcwd(root, sizeof root)) return usage("cannot read the current folder");
    if (!make_dir(out) || !realpath(out, outdir)) return usage("--out: cannot create the folder");
    snprintf(work, sizeof work, "%s/work", outdir);
    snprintf(report, sizeof report, "%s/report", outdir);
    if (!make_dir(work) || !make_dir(report)) return usage("--out: cannot create its work/ and report/ folders");
    char subdir[4096];
    if (submission && !realpath(submission, subdir)) return usage("--submission: no such folder");

    pl_diag diag = pl_diag_default();
    grade_spec spec;
    if (grade_spec_load(GRADE_CASES, GRADE_HIDDEN_CASES, &spec, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        return 2;
    }
    grade_result result;
    memset(&result, 0, sizeof result);
    result.seed = seed_given ? seed : fresh_seed();
    grade_env env = {root, submission ? subdir : NULL, work, report, public_only, result.seed, threads,
                     grade_sandbox_probe()};
    /* Before any child runs: the answers out of its reach, and the report says what could not be. */
    char why[512];
    if (submission && !grade_guard_secrets(root, outdir, &env.sandbox, why, sizeof why)) {
        fprintf(stderr, "grade: %s\n", why);
        grade_spec_free(&spec);
        return 2;
    }
    /* A student's own tree is their code on their machine: containment is the autograder's concern. */
    if (submission) grade_sandbox_describe(&env.sandbox, result.unprotected, sizeof result.unprotected);
    if (result.unprotected[0]) fprintf(stderr, "grade: unavailable protections: %s\n", result.unprotected);
    if (calibrate_runs > 0) {
        int code = calibrate(&env, &spec, parts, cases, calibrate_runs);
        grade_spec_free(&spec);
        return code;
    }
    double t0 = now();
    for (int k = 0; k < GRADE_NUM_PARTS; k++) {
        char digit[2] = {(char)('1' + k), 0};
        if (!strstr(parts, digit)) continue;
        fprintf(stderr, "grade: part %d ...\n", k + 1);
        grade_part(&env, &spec, &spec.parts[k], &result.parts[result.num_parts++]);
        result.seconds = now() - t0;
    }
    result.seconds = now() - t0;

    grade_print_table(&result, stdout);
    snprintf(json, sizeof json, "%s/results.json", outdir);
    int code = 0;
    if (grade_write_results_json(&result, json, &diag) != PL_OK || grade_write_html(&result, report, &diag) != PL_OK) {
        fprintf(stderr, "grade: %s\n", diag.error);
        code = 1;
    }
    if (submission && !grade_guard_secrets(root, outdir, &env.sandbox, why, sizeof why)) {  /* the new results.json */
        fprintf(stderr, "grade: %s\n", why);
        code = 1;
    }
    printf("results: %s\nreport:  %s/index.html\n", json, report);
    for (int i = 0; i < result.num_parts; i++) code |= result.parts[i].score < result.parts[i].max_score;
    grade_spec_free(&spec);
    return code;
}
