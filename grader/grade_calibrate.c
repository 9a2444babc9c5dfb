/* Grader machinery: not part of any assignment.
 * --calibrate (grade_calibrate.h): each case through the same stages a grading runs (grade_part_case:
 * the reference, the render, the verdict, the second render of a chance failure), so the rate it
 * measures is the grading's own. */
#include "grade_calibrate.h"
#include "grade_guard.h"
#include "grade_limits.h"
#include "grade_part.h"
#include "grade_result.h"
#include "grade_words.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* One case, `runs` times: its line. False when a render did not run (the tree is not the solution,
 * or the course's files are wrong: a calibration means nothing then). */
static bool calibrate_case(const grade_plan *plan, const grade_env *base, const grade_spec *spec, const grade_plan_case *pc,
                           int runs, unsigned long long (*seed)(void), int *confirmed_out)
{
    const grade_case *k = pc->spec;
    int failures = 0, confirmed = 0, decile[10] = {0};
    figure_range noise = {INFINITY, 0}, rate = {INFINITY, 0}, work = {INFINITY, 0};
    grade_case_result c;
    memset(&c, 0, sizeof c);
    c.spec = k;
    for (int run = 0; run < runs; run++) {
        grade_env env = *base;
        env.seed = seed();
        grade_part_case(plan, &env, spec, pc, &c);
        if (!c.ran) {
            char why[1024];
            grade_words_why(&c.why, plan->part, plan->folder, why, sizeof why);
            fprintf(stderr, "grade: %s: %s\n", k->name, why);
            grade_result_clear_case(&c);
            return false;
        }
        /* Two counts: the first render's failures (the test's own rate, what its alpha claims) and
         * the case's, confirmed by a second render (grade_image.h). A failure of the solution is a
         * false failure: its seed makes it again. */
        bool first_failed = c.rendered_twice || !c.pass;
        double first_p = c.rendered_twice ? c.first_p : c.v.p_value;
        failures += first_failed;
        confirmed += !c.pass;
        if (first_failed)
            fprintf(stderr, "grade: part %d, case %s fails at seed %llu (p = %.3g)%s: bin/grade --parts %d --seed %llu "
                            "shows it\n", plan->part, k->name, (unsigned long long)env.seed, first_p,
                    c.pass ? ", its second render passes" : c.rendered_twice ? ", its second render too" : "", plan->part,
                    (unsigned long long)env.seed);
        range_add(&noise, c.noise);
        range_add(&rate, c.rate_distance);
        range_add(&work, c.base_cpu > 0 ? c.cpu / c.base_cpu : NAN);
        decile[first_p >= 1.0 ? 9 : (int)(first_p * 10)]++;
    }
    grade_result_clear_case(&c);
    printf("part%d/%-22s %6d %9d %9d %8.0e ", plan->part, k->name, runs, failures, confirmed, spec->family_alpha);
    for (int d = 0; d < 10; d++) printf(" %3d", decile[d]);
    if (k->noise_check) printf("   noise ratio %.3f to %.3f (limit %.2f)", noise.min, noise.max, GRADE_NOISE_FACTOR);
    if (rate.max > 0) printf("   rate map distance %.3f to %.3f (limit %.2f)", rate.min, rate.max, GRADE_RATE_TOLERANCE);
    if (k->work_check)  /* a tree's own grading: against the framework's linear scan */
        printf("   CPU time over the linear scan's %.4f to %.4f (limit %.4f)", work.min, work.max, 1.0 / GRADE_SCAN_FACTOR);
    printf("\n");
    fflush(stdout);
    *confirmed_out = confirmed;
    return true;
}

int grade_calibrate(const grade_env *env, const grade_run_plan *rp, const grade_spec *spec, const char *parts,
                    const char *cases, int runs, unsigned long long (*seed)(void))
{
    int worst = 0;
    printf("%-28s %6s %9s %9s %8s  p-value deciles\n", "case", "runs", "failures", "confirmed", "alpha");
    for (int n = 1; n <= GRADE_MAX_PART; n++) {
        if (!strchr(parts, '0' + n)) continue;
        grade_plan *plan = calloc(1, sizeof *plan);
        char why[512] = "out of memory";
        /* This tree's own plan (no submission): its cases render with its own renderer. */
        if (!plan || !grade_plan_part(env, rp, &spec->parts[n - 1], NULL, 0, plan, why, sizeof why) ||
            !grade_guard_own_dir(plan->work)) {
            fprintf(stderr, "grade: part %d: %s\n", n, plan && plan->work[0] ? plan->work : why);
            grade_plan_free(plan);
            free(plan);
            return 1;
        }
        bool ok = true;
        for (int i = 0; ok && i < plan->num_cases; i++) {
            int confirmed = 0;
            if (!name_listed(cases, plan->cases[i].spec->name)) continue;
            ok = calibrate_case(plan, env, spec, &plan->cases[i], runs, seed, &confirmed);
            worst = confirmed > worst ? confirmed : worst;
        }
        grade_plan_free(plan);
        free(plan);
        if (!ok) return 1;
    }
    return worst > 0;
}
