/* Grader machinery: not part of any assignment.
 * The score: the one place points are computed from verdicts (grade_score.h). A part's unit
 * points are shared out by task (cases.json's "unit_tasks", grading/README.md): a task earns its
 * share when every one of its tests ran and passed, and nothing otherwise, so that a task that is
 * wrong costs what it is worth rather than one test's weight; nothing counts for a suite that could
 * not be judged (crashed, stopped, ran out of time, or its results were not its own). Each image
 * case that passed adds its points. The table, results.json and the HTML report read these figures. */
#include "grade_score.h"
#include <string.h>

void grade_score_part(const grade_part_spec *p, grade_part_result *r)
{
    grade_suite_facts *s = &r->suite;
    if (!s->judged) s->run = s->failed = s->num_tests = 0;  /* nothing of a suite that could not be judged counts */
    r->unit_max = p->unit_points;
    r->unit_score = 0.0;
    for (int t = 0; t < p->num_tasks; t++) r->task_passed[t] = r->task_run[t] = 0;
    for (int i = 0; i < s->num_tests; i++) {
        int t = grade_spec_task_of(p, s->tests[i].name);
        if (t < 0) continue;  /* the count check (grade_suite_results) says whether the suite is the course's */
        r->task_run[t]++;
        r->task_passed[t] += s->tests[i].passed;
    }
    for (int t = 0; t < p->num_tasks; t++) {
        bool whole = s->judged && r->task_run[t] == p->tasks[t].tests && r->task_passed[t] == p->tasks[t].tests;
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
