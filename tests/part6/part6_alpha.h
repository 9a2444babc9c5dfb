/* Test machinery: not part of any assignment.
 * The false-alarm budget of the part 6 suite: a correct implementation fails a run with
 * probability at most PART6_FAMILY_ALPHA. Each statistical check runs at the Sidak level
 * alpha_check(PART6_FAMILY_ALPHA, PART6_CHECKS); PART6_CHECKS is an upper bound on the number of
 * checks in the suite (test_specular.c: glass_sample_f's reflected fraction against Schlick's R,
 * one check per direction entering and two per direction leaving, one for each cosine the
 * handout allows; test_render.c: one t test of a render through a glass sphere). Each use of
 * PART6_CHECK_ALPHA counts one check; the suite fails at exit if more ran (tests/common/alpha.h). */
#ifndef PART6_ALPHA_H
#define PART6_ALPHA_H

#include "../common/alpha.h"

#define PART6_FAMILY_ALPHA 1e-3
#define PART6_CHECKS 10
#define PART6_CHECK_ALPHA alpha_check(PART6_FAMILY_ALPHA, PART6_CHECKS)

#endif
