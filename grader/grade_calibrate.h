/* Grader machinery: not part of any assignment.
 * bin/grade --calibrate N (grade_calibrate.c): the grader's own false-failure rate, measured on this
 * tree (the solution): every case of the parts rendered N times at fresh seeds, each judged as a
 * grading judges it. */
#ifndef PL_GRADE_CALIBRATE_H
#define PL_GRADE_CALIBRATE_H

#include "grade_env.h"
#include "grade_plan.h"
#include "grade_spec.h"

/* Prints, per case of the parts listed in `parts` whose name `cases` lists (NULL: every case), how
 * often its first render failed beside the alpha it claims, how often the case failed (its second
 * render too), the deciles of the first render's p-values, and the range of each figure it judges.
 * seed() draws each run's seed. 0 when no case failed twice, 1 otherwise or on an error. */
int grade_calibrate(const grade_env *env, const grade_run_plan *rp, const grade_spec *spec, const char *parts,
                    const char *cases, int runs, unsigned long long (*seed)(void));

#endif
