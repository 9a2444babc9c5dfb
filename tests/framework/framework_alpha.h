/* Test machinery: not part of any assignment.
 * The false-alarm budget of the framework suite: a correct framework fails a run with probability at
 * most FRAMEWORK_FAMILY_ALPHA. Each use of FRAMEWORK_CHECK_ALPHA counts one statistical check at the
 * Sidak level alpha_check(FRAMEWORK_FAMILY_ALPHA, FRAMEWORK_CHECKS); the suite fails at exit if more
 * than FRAMEWORK_CHECKS ran (tests/common/alpha.h). */
#ifndef FRAMEWORK_ALPHA_H
#define FRAMEWORK_ALPHA_H

#include "../common/alpha.h"

#define FRAMEWORK_FAMILY_ALPHA 1e-3
#define FRAMEWORK_CHECKS 16
#define FRAMEWORK_CHECK_ALPHA alpha_check(FRAMEWORK_FAMILY_ALPHA, FRAMEWORK_CHECKS)

#endif
