/* Grader machinery: not part of any assignment. One image case: render, read, judge, picture. */
#ifndef PL_GRADE_IMAGE_H
#define PL_GRADE_IMAGE_H

#include "grade.h"

/* Renders case c->spec with tree's bin/pathtracer at env->seed, reads the film it sent and the
 * reference (root/reference_images/part<N>/<case>.exr), judges them, writes the report's pictures,
 * and scores the case (all of its points on a pass, none otherwise).
 * A statistical case that fails on its p-value alone is rendered once more, at
 * grade_confirm_seed(env->seed), and judged on that render: it fails only when both renders fail.
 * A correct render fails one test by chance (at most about 1 in 1,000 measured, grading/CALIBRATION.md),
 * two independent renders of it both fail about once in a million; a bug fails both. c then holds
 * the second render's result, with the first's seed and p-value. */
void grade_image_case(const grade_env *env, const grade_spec *spec, const char *tree, int part, grade_case_result *c);

/* Why a render stopped, from its log (written by the grader from the render's output), as one of the
 * grader's own fixed sentences: a tree the framework refused (which of bvh_validate's rules it
 * broke), an error from bvh_build, a task still a stub; "" when the log names no reason the grader
 * knows. The log is the render's: nothing of it is copied, its line only selects a sentence. */
void grade_image_log_reason(const char *log, char *out, size_t size);

/* The seed of a case's second render: a fixed function of the grading's seed (so bin/grade --seed
 * makes both renders again), far from it in the seed space, below 10^12 like every grading seed. */
unsigned long long grade_confirm_seed(unsigned long long seed);

#endif
