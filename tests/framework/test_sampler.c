/* Test machinery: not part of any assignment.
 * The framework's hemisphere samplers (framework/sampler.c): each sampler's histogram must match its
 * pdf twin (Pearson chi-square, tests/common/dir_check.h).
 * alpha: FRAMEWORK_CHECK_ALPHA (framework_alpha.h). Seeds are fixed and printed. */
#include "../common/test.h"
#include "../common/mc_assert.h"
#include "../common/dir_check.h"
#include "../../framework/sampler.h"
#include "framework_alpha.h"

#define SEED mc_seed(0x5eed3001ull)

/* ---- the framework's samplers -------------------------------------------------------------- */
static vec3 uniform_sample(void *u, vec2 xi, float *p) { (void)u; vec3 w = sample_uniform_hemisphere(xi); *p = sample_uniform_hemisphere_pdf(w); return w; }
static float uniform_pdf(void *u, vec3 w) { (void)u; return sample_uniform_hemisphere_pdf(w); }
static vec3 cosine_sample(void *u, vec2 xi, float *p) { (void)u; vec3 w = sample_cosine_hemisphere(xi); *p = sample_cosine_hemisphere_pdf(w); return w; }
static float cosine_pdf(void *u, vec3 w) { (void)u; return sample_cosine_hemisphere_pdf(w); }

static void test_uniform_hemisphere__matches_its_pdf(void **state)
{
    (void)state;
    check_sampler("sample_uniform_hemisphere", uniform_sample, uniform_pdf, NULL, SEED + 1, FRAMEWORK_CHECK_ALPHA);
    assert_float_near(1.0 / (2.0 * M_PI), sample_uniform_hemisphere_pdf(vec3_make(0, 0, 1)), 1e-6);
}

static void test_cosine_hemisphere__matches_its_pdf(void **state)
{
    (void)state;
    check_sampler("sample_cosine_hemisphere", cosine_sample, cosine_pdf, NULL, SEED + 2, FRAMEWORK_CHECK_ALPHA);
}

int sampler_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform_hemisphere__matches_its_pdf),
        cmocka_unit_test(test_cosine_hemisphere__matches_its_pdf),
    };
    return cmocka_run_group_tests_name("framework: hemisphere samplers", tests, test_setup, NULL);  /* forget stubs earlier groups ran */
}
