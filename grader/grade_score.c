/* Grader machinery: not part of any assignment.
 * The score: the one place points are computed from verdicts (grade.h, "score"). A part earns its
 * unit points times the share of its tests that passed (none when its suite could not be judged:
 * crashed, stopped, ran out of time, or its results were not its own) plus the points of each
 * image case that passed. The table, results.json and the HTML report all read these figures. */
#include "grade.h"

void grade_score_part(const grade_part_spec *p, grade_part_result *r)
{
    if (r->suite_reason[0]) {  /* nothing of a suite that could not be judged counts */
        r->tests_run = r->tests_failed = 0;
        r->failures[0] = '\0';
    }
    r->unit_max = p->unit_points;
    r->unit_score = r->tests_run > 0 ? p->unit_points * (double)(r->tests_run - r->tests_failed) / r->tests_run : 0.0;
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
