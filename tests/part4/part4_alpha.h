/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 4 suite: a correct implementation fails a run with
 * probability at most PART4_FAMILY_ALPHA; each statistical check runs at the Sidak level
 * stats_sidak(PART4_FAMILY_ALPHA, PART4_CHECKS), PART4_CHECKS an upper bound on their number.
 * Each use of PART4_CHECK_ALPHA counts one check; the suite fails at exit if more ran (alpha.h). */
#ifndef PART4_ALPHA_H
#define PART4_ALPHA_H

#include "../common/alpha.h"

#define PART4_FAMILY_ALPHA 1e-3
#define PART4_CHECKS 32
#define PART4_CHECK_ALPHA alpha_check(PART4_FAMILY_ALPHA, PART4_CHECKS)

#endif
