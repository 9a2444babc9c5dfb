/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 5 suite: a correct implementation fails a run with
 * probability at most PART5_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART5_FAMILY_ALPHA, PART5_CHECKS); PART5_CHECKS is an upper bound on the number of
 * checks in the suite (test_adaptive.c: the mean sample count of the striped pixels, and the
 * tolerance-0 image against the fixed-rate one). Each use of PART5_CHECK_ALPHA counts one check;
 * the suite fails at exit if more ran (tests/common/alpha.h). */
#ifndef PART5_ALPHA_H
#define PART5_ALPHA_H

#include "../common/alpha.h"

#define PART5_FAMILY_ALPHA 1e-3
#define PART5_CHECKS 2
#define PART5_CHECK_ALPHA alpha_check(PART5_FAMILY_ALPHA, PART5_CHECKS)

#endif
