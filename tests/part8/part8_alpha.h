/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 8 suite: a correct implementation fails a run with
 * probability at most PART8_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART8_FAMILY_ALPHA, PART8_CHECKS); PART8_CHECKS is an upper bound on the number of
 * checks in the suite (test_envlight.c: the uniform directions and the importance-sampled
 * directions by chi-square, three irradiance means by t test; test_render.c: two renders of a floor
 * under a constant sky by t test). Each use of PART8_CHECK_ALPHA counts one check; the suite fails
 * at exit if more ran (tests/common/alpha.h). */
#ifndef PART8_ALPHA_H
#define PART8_ALPHA_H

#include "../common/alpha.h"

#define PART8_FAMILY_ALPHA 1e-3
#define PART8_CHECKS 7
#define PART8_CHECK_ALPHA alpha_check(PART8_FAMILY_ALPHA, PART8_CHECKS)

#endif
