/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 9 suite: a correct implementation fails a run with
 * probability at most PART9_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART9_FAMILY_ALPHA, PART9_CHECKS); PART9_CHECKS is an upper bound on the number of
 * checks in the suite (test_lens.c: lens_sample_disk's points uniform over the disc; thin_lens_ray's
 * lens points are checked point by point against it, with no statistics). Each use of
 * PART9_CHECK_ALPHA counts one check; the suite fails at exit if more ran (tests/common/alpha.h). */
#ifndef PART9_ALPHA_H
#define PART9_ALPHA_H

#include "../common/alpha.h"

#define PART9_FAMILY_ALPHA 1e-3
#define PART9_CHECKS 1
#define PART9_CHECK_ALPHA alpha_check(PART9_FAMILY_ALPHA, PART9_CHECKS)

#endif
