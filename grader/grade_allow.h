/* Grader machinery: not part of any assignment.
 * The allow-list (grade_allow.c): every function a student's part may call, in one place. */
#ifndef PL_GRADE_ALLOW_H
#define PL_GRADE_ALLOW_H

#include <stdbool.h>
#include "grade_names.h"

/* True when part code may refer to name: the allow-list, not counting the parts' own functions. */
bool grade_allow_has(const char *name);
/* The framework functions on that list, NULL-terminated: the ones the framework headers mark
 * PL_PART_API (tests/grader/test_allow.c checks that the two agree). */
const char *const *grade_allow_framework(void);
/* Adds every name of the allow-list to set (libm's in all three precisions); false when out of memory. */
bool grade_allow_add_all(grade_names *set);

#endif
