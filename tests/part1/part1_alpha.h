/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 1 suite: a correct implementation fails a run with
 * probability at most PART1_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART1_FAMILY_ALPHA, PART1_CHECKS); PART1_CHECKS is an upper bound on the number of
 * checks in the suite (the three pixel-coverage tests of test_pixel.c). Each use of
 * PART1_CHECK_ALPHA counts one check; the suite fails at exit if more ran (tests/common/alpha.h). */
#ifndef PART1_ALPHA_H
#define PART1_ALPHA_H

#include "../common/alpha.h"

#define PART1_FAMILY_ALPHA 1e-3
#define PART1_CHECKS 3
#define PART1_CHECK_ALPHA alpha_check(PART1_FAMILY_ALPHA, PART1_CHECKS)

#endif
