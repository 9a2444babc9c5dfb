/* Grader machinery: not part of any assignment. One image case: render, read, judge, picture. */
#ifndef PL_GRADE_IMAGE_H
#define PL_GRADE_IMAGE_H

#include "grade.h"

/* Renders case c->spec with tree's bin/pathtracer at env->seed, reads the EXR it wrote and the
 * reference (root/reference_images/part<N>/<case>.exr), judges them, writes the report's pictures,
 * and scores the case (all of its points on a pass, none otherwise). */
void grade_image_case(const grade_env *env, const grade_spec *spec, const char *tree, int part, grade_case_result *c);

#endif
