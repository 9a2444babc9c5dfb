/* Grader machinery: not part of any assignment.
 * The run stage of an image case (grade_render.c): the candidate's render, confined, its film
 * streamed to the grader and checked for shape, and for a work_check case the CPU time the kernel
 * counted of it and of its baseline. */
#ifndef PL_GRADE_RENDER_H
#define PL_GRADE_RENDER_H

#include "grade_env.h"
#include "grade_plan.h"
#include "grade_result.h"
#include "../framework/film.h"

/* Renders case pc with the part's renderer at seed (the plan says where and how), into out (free with
 * film_free), and into c its seed, its figures' measurements (CPU times: c->cpu, c->base_cpu), and on
 * a failure c->why. True when a film of the case's shape came back. */
bool grade_render_case(const grade_plan *plan, const grade_env *env, const grade_plan_case *pc, unsigned long long seed,
                       film *out, grade_case_result *c);

/* Why a render stopped, from its log (written by the grader from the render's output): a tree the
 * framework refused (which of bvh_validate's rules it broke), an error from bvh_build, a task still
 * a stub; GRADE_WHY_NONE when the log names no reason the grader knows. Nothing of the log is kept. */
grade_why grade_render_log_reason(const char *log);

/* The seed of a case's second render: a fixed function of the grading's seed (so bin/grade --seed
 * makes both renders again), far from it in the seed space, below 10^12 like every grading seed. */
unsigned long long grade_render_confirm_seed(unsigned long long seed);

#endif
