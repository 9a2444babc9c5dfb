/* Grader machinery: not part of any assignment.
 * The build stage's course side (grade_tree.c): the course's tree, copied into the grader's work
 * folder and built there once per grading, before any student code runs; and the removal of a
 * grading tree, only ever one in the grading's sandbox folder. */
#ifndef PL_GRADE_TREE_H
#define PL_GRADE_TREE_H

#include <stdbool.h>
#include <stddef.h>
#include "grade_plan.h"

/* Copies the course's tree into rp->course and builds there (grade_plan_course_build says what), for
 * each of `parts` ("1,3") its suite's subject and judge; false with why (the course's problem:
 * grading must not start). Objects prebuilt with `bin/grade --prebuild` are reused. */
bool grade_tree_course_build(const grade_run_plan *rp, const char *parts, char *why, size_t size);

/* Removes a tree (or anything at that path) in a sandbox folder, or that folder; anything else is
 * refused with a line on stderr. */
void grade_tree_remove(const char *tree);

#endif
