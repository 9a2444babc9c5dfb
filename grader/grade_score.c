/* Grader machinery: not part of any assignment.
 * The score: the one place points are computed from verdicts (grade.h, "score"). A part's unit
 * points are shared out by task (cases.json's "unit_tasks", grading/README.md): a task earns its
 * share when every one of its tests ran and passed, and nothing otherwise, so that a task that is
 * wrong costs what it is worth rather than one test's weight; nothing counts for a suite that could
 * not be judged (crashed, stopped, ran out of time, or its results were not its own). Each image
 * case that passed adds its points. The table, results.json and the HTML report read these figures. */
#include "grade.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

int grade_task_of(const grade_part_spec *p, const char *name)
{
    /* Test functions are named test_<function>__<behaviour>: the prefix is matched after "test_". */
    if (!strncmp(name, "test_", 5)) name += 5;
    for (int t = 0; t < p->num_tasks; t++)
        for (int m = 0; m < p->tasks[t].num_match; m++)
            if (!strncmp(name, p->tasks[t].match[m], strlen(p->tasks[t].match[m]))) return t;
    return -1;
}

void grade_score_note_test(grade_part_result *r, const char *name, bool passed)
{
    if (r->num_tests >= GRADE_MAX_TESTS) return;
    snprintf(r->tests[r->num_tests].name, sizeof r->tests[r->num_tests].name, "%s", name);
    r->tests[r->num_tests++].passed = passed;
}

void grade_score_part(const grade_part_spec *p, grade_part_result *r)
{
    if (r->suite_reason[0]) {  /* nothing of a suite that could not be judged counts */
        r->tests_run = r->tests_failed = 0;
        r->num_tests = 0;
        r->failures[0] = '\0';
    }
    r->unit_max = p->unit_points;
    r->unit_score = 0.0;
    for (int t = 0; t < p->num_tasks; t++) r->task_passed[t] = r->task_run[t] = 0;
    for (int i = 0; i < r->num_tests; i++) {
        int t = grade_task_of(p, r->tests[i].name);
        if (t < 0) continue;  /* the count check (grade_suite_results) says whether the suite is the course's */
        r->task_run[t]++;
        r->task_passed[t] += r->tests[i].passed;
    }
    for (int t = 0; t < p->num_tasks; t++) {
        bool whole = !r->suite_reason[0] && r->task_run[t] == p->tasks[t].tests && r->task_passed[t] == p->tasks[t].tests;
        r->task_score[t] = whole ? p->tasks[t].points : 0.0;
        r->unit_score += r->task_score[t];
    }
    r->score = r->unit_score;
    r->max_score = r->unit_max;
    for (int i = 0; i < r->num_cases; i++) {
        grade_case_result *c = &r->cases[i];
        c->score = c->pass ? c->spec->points : 0.0;
        r->score += c->score;
        r->max_score += c->spec->points;
    }
}

double grade_score_total(const grade_result *r, double *max)
{
    double total = 0.0;
    *max = 0.0;
    for (int i = 0; i < r->num_parts; i++) {
        total += r->parts[i].score;
        *max += r->parts[i].max_score;
    }
    return total;
}

/* ---- the figures a case judges beside its image (grade_image.c measures them) ----------------- */

bool grade_case_spp_ok(const grade_case_result *c)
{
    return !(c->course_spp > 0) || fabs(c->spp / c->course_spp - 1.0) <= GRADE_SPP_TOLERANCE;
}

bool grade_case_rate_ok(const grade_case_result *c)
{
    return c->rate_distance < 0 || c->rate_distance <= GRADE_RATE_TOLERANCE;
}

bool grade_case_work_ok(const grade_case_result *c)
{
    if (!c->spec->work_check) return true;
    if (!(c->base_cpu > 0) || !(c->cpu > 0)) return false;  /* not measured: nothing to stand on */
    return c->base_is_scan ? c->cpu * GRADE_SCAN_FACTOR <= c->base_cpu : c->cpu <= GRADE_WORK_FACTOR * c->base_cpu;
}
