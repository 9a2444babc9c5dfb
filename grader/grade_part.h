/* Grader machinery: not part of any assignment.
 * One part through the pipeline (grade_part.c): spec (the submitted folder's manifest), plan, build,
 * run (its tests, its renders), verdicts, score, each stage's facts into the part's result. */
#ifndef PL_GRADE_PART_H
#define PL_GRADE_PART_H

#include "grade_env.h"
#include "grade_plan.h"
#include "grade_result.h"

/* Grades part p within env (the run's folders: rp), by `deadline` (clock_seconds; 0 for none), into r
 * (whose suite's tests array it keeps). */
void grade_part(const grade_env *env, const grade_run_plan *rp, const grade_spec *spec, const grade_part_spec *p,
                double deadline, grade_part_result *r);

/* One image case of a planned part: its reference, its render at env->seed and its verdict, and a
 * second render when the first failed on its p-value alone (grade_image.h says why); into c. */
void grade_part_case(const grade_plan *plan, const grade_env *env, const grade_spec *spec, const grade_plan_case *pc,
                     grade_case_result *c);

#endif
