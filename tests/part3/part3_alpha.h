/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 3 suite: a correct implementation fails a run with
 * probability at most PART3_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART3_FAMILY_ALPHA, PART3_CHECKS); PART3_CHECKS is an upper bound on the number of
 * checks in the suite (counting over is safe, it only makes each check stricter). Each use of
 * PART3_CHECK_ALPHA counts one check; the suite fails at exit if more ran (tests/common/alpha.h). */
#ifndef PART3_ALPHA_H
#define PART3_ALPHA_H

#include "../common/alpha.h"

#define PART3_FAMILY_ALPHA 1e-3
#define PART3_CHECKS 48
#define PART3_CHECK_ALPHA alpha_check(PART3_FAMILY_ALPHA, PART3_CHECKS)

#endif
