/* Grader machinery: not part of any assignment.
 * One part, through the pipeline (grade_part.h): the plan, then each stage in turn, each handed what
 * the plan and the stage before it made, each returning its own facts into the part's result. This
 * is the one module that calls every stage; the stages call none of each other's. */
#include "grade_part.h"
#include "grade_fmt.h"
#include "grade_build.h"
#include "grade_guard.h"
#include "grade_image.h"
#include "grade_render.h"
#include "grade_score.h"
#include "grade_tests.h"
#include "grade_tree.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The part's cases, listed in r with their points before anything runs (every case is in the results
 * whatever happens), as the plan lists them. */
static void list_cases(const grade_plan *plan, const grade_part_spec *p, grade_part_result *r)
{
    grade_test_fact *tests = r->suite.tests;  /* the result's own array, kept */
    memset(r, 0, sizeof *r);
    r->suite.tests = tests;
    r->part = p->part;
    r->spec = p;
    for (int i = 0; plan && i < plan->num_cases; i++) r->cases[r->num_cases++].spec = plan->cases[i].spec;
}

/* A case's render and verdict at seed, into c (emptied first). */
static void render_and_judge(const grade_plan *plan, const grade_env *env, const grade_spec *spec,
                             const grade_plan_case *pc, unsigned long long seed, const image *ref, const image *refvar,
                             grade_case_result *c)
{
    film f = {0};
    grade_result_clear_case(c);
    if (grade_render_case(plan, env, pc, seed, &f, c)) grade_image_judge(spec, pc, &f, ref, refvar, c);
    film_free(&f);
}

/* One image case: its reference, its render and verdict, and a second render when the first failed
 * on its p-value alone. Why a second render, and not a smaller alpha: the tests' p-values are exact
 * only as far as a block's sum of samples is normal, and at the 5 to 6 sigma that Sidak's correction
 * asks of each block, the rare bright paths of a path tracer make its tail heavier than the normal's
 * (measured: 8 failures of the solution in 14,000 gradings where 1.4 were due). Two renders at
 * independent seeds both fail with the square of one's chance, whatever the shape of that tail; a
 * biased render fails both. The first failure costs nothing but time. */
void grade_part_case(const grade_plan *plan, const grade_env *env, const grade_spec *spec, const grade_plan_case *pc,
                     grade_case_result *c)
{
    image ref = {0}, refvar = {0};
    grade_result_clear_case(c);
    if (grade_image_reference(pc->reference, &ref, &refvar, &c->why) != PL_OK) return;
    render_and_judge(plan, env, spec, pc, env->seed, &ref, &refvar, c);
    if (c->chance_failure) {
        unsigned long long first_seed = c->seed;
        double first_p = c->v.p_value;
        render_and_judge(plan, env, spec, pc, grade_render_confirm_seed(env->seed), &ref, &refvar, c);
        c->rendered_twice = true;
        c->first_seed = first_seed;
        c->first_p = first_p;
    }
    image_free(&ref);
    image_free(&refvar);
}

/* The part's own folder (its logs and films): the grader's alone; the children get the sandbox's. */
static bool part_folder(const grade_plan *plan)
{
    return grade_guard_own_dir(plan->work);
}

void grade_part(const grade_env *env, const grade_run_plan *rp, const grade_spec *spec, const grade_part_spec *p,
                double deadline, grade_part_result *r)
{
    grade_plan *plan = calloc(1, sizeof *plan);  /* every path of the part: a few megabytes */
    grade_manifest m;
    grade_why why = grade_why_of(GRADE_WHY_NONE);
    /* The spec stage's submission side: the part's folder, read as data, before anything plans it. */
    char folder[64] = "";
    bool ok = plan != NULL;
    if (ok && env->submission) {
        grade_path_buf submitted;
        ok = grade_plan_part_folder(env->root, p->part, folder, sizeof folder) &&
             grade_plan_submitted(env, folder, submitted, sizeof submitted) && grade_manifest_read(submitted, folder, &m, &why);
    }
    char planned[512] = "";
    if (ok) ok = grade_plan_part(env, rp, p, env->submission ? &m : NULL, deadline, plan, planned, sizeof planned);
    if (!ok && why.code == GRADE_WHY_NONE) {
        why = grade_why_of(GRADE_WHY_GRADER);
        grade_msg(why.detail, sizeof why.detail, "%s", plan ? planned : "out of memory");
    }
    list_cases(ok ? plan : NULL, p, r);
    if (!folder[0]) grade_plan_part_folder(env->root, p->part, folder, sizeof folder);
    snprintf(r->folder, sizeof r->folder, "%s", folder);
    if (!ok) {
        for (int i = 0; i < p->num_cases; i++)  /* every case in the results, none run */
            if (!(env->public_only && p->cases[i].hidden)) r->cases[r->num_cases++].spec = &p->cases[i];
    }
    if (ok && !part_folder(plan)) why = grade_why_of(GRADE_WHY_GRADER), ok = false;
    /* The build, then the suite (a submission's split: its verdicts from the course's judge, never from
     * a process its code ran in; a student's own tree runs its suite whole), then each case. */
    if (ok) {
        if (env->submission) grade_build_submission(plan, &m, &env->sandbox, &r->build);
        else grade_build_own_tree(plan, &r->build);
    }
    else r->build.why = why;
    if (r->build.built) {
        if (env->submission) grade_tests_split(plan, env, p, &r->suite);
        else grade_tests_own(plan, p, &r->suite);
        for (int i = 0; i < r->num_cases; i++) grade_part_case(plan, env, spec, &plan->cases[i], &r->cases[i]);
    }
    else {
        r->suite.why = r->build.why;
        for (int i = 0; i < r->num_cases; i++) r->cases[i].why = grade_why_of(GRADE_WHY_NOT_BUILT);
    }
    /* Nothing of this part stays in reach of the next: its tree and its suite's folder go. */
    if (ok && plan->suite_dir[0]) grade_tree_remove(plan->suite_dir);
    if (ok && env->submission) grade_tree_remove(plan->tree);
    grade_score_part(p, r);
    grade_plan_free(plan);
    free(plan);
}
