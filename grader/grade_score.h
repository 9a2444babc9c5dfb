/* Grader machinery: not part of any assignment.
 * The score stage (grade_score.c): the one place points are computed, from the verdicts' facts. */
#ifndef PL_GRADE_SCORE_H
#define PL_GRADE_SCORE_H

#include "grade_result.h"

/* Part p's unit, case and total points in r, from its facts: each task's share when all its tests
 * passed (none count when the suite could not be judged) and each case's pass. */
void grade_score_part(const grade_part_spec *p, grade_part_result *r);
/* The whole grading's points, and its maximum in *max. */
double grade_score_total(const grade_result *r, double *max);

#endif
