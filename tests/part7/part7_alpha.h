/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 7 suite: a correct implementation fails a run with
 * probability at most PART7_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART7_FAMILY_ALPHA, PART7_CHECKS); PART7_CHECKS is an upper bound on the number of
 * checks in the suite (test_microfacet.c: microfacet_sample_f's directions against its pdf by
 * chi-square, and its mean weight against the BSDF's albedo by t test, for each of the cases it
 * lists). Each use of PART7_CHECK_ALPHA counts one check; the suite fails at exit if more ran
 * (tests/common/alpha.h). */
#ifndef PART7_ALPHA_H
#define PART7_ALPHA_H

#include "../common/alpha.h"

#define PART7_FAMILY_ALPHA 1e-3
#define PART7_CHECKS 8
#define PART7_CHECK_ALPHA alpha_check(PART7_FAMILY_ALPHA, PART7_CHECKS)

#endif
