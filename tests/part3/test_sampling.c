/* Test machinery: not part of any assignment.
 * The diffuse BSDF: its sampler's histogram must match its pdf (Pearson chi-square,
 * tests/common/dir_check.h; the framework's hemisphere samplers are tested in tests/framework), and the BSDF sample weight f cos / pdf must average to the albedo.
 * alpha: each statistical check runs at PART3_CHECK_ALPHA, the Sidak share of the suite's
 * PART3_FAMILY_ALPHA = 1e-3 (part3_alpha.h). Seeds are fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/dir_check.h"
#include "../../parts/part3_direct/part3.h"
#include "part3_alpha.h"
#include <stdlib.h>

#define SEED mc_seed(0x5eed3001ull)
/* ---- the diffuse BSDF (student code) --------------------------------------------------------- */
static const vec3 WO = {0.3f, -0.2f, 0.932738f};

static vec3 bsdf_sample(void *user, vec2 xi, float *p)
{
    vec3 wi;
    bsdf_sample_f((const material *)user, WO, xi, &wi, p);
    return wi;
}
static float bsdf_pdf_of(void *user, vec3 w) { return bsdf_pdf((const material *)user, WO, w); }

static void test_bsdf_f__is_albedo_over_pi(void **state)
{
    (void)state;
    material m = material_make(rgb_make(0.8f, 0.5f, 0.2f), rgb_gray(0.0f));
    rgb f = bsdf_f(&m, WO, vec3_normalize(vec3_make(-0.5f, 0.1f, 0.4f)));
    assert_implemented();
    assert_rgb_near(rgb_make(0.8f / (float)M_PI, 0.5f / (float)M_PI, 0.2f / (float)M_PI), f, 1e-6f);
}

static void test_bsdf_f__is_black_below_the_surface(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.7f), rgb_gray(0.0f));
    rgb f = bsdf_f(&m, WO, vec3_make(0.6f, 0.0f, -0.8f));
    assert_implemented();
    assert_rgb_near(rgb_gray(0.0f), f, 0.0f);
}

static void test_bsdf_sample_f__returns_f_and_pdf_of_its_direction(void **state)
{
    (void)state;
    material m = material_make(rgb_make(0.8f, 0.5f, 0.2f), rgb_gray(0.0f));
    rng g = rng_seeded(SEED + 3, 0);
    for (int i = 0; i < 1000; i++) {
        vec3 wi;
        float pdf = -1.0f;
        rgb f = bsdf_sample_f(&m, WO, rng_uniform2(&g), &wi, &pdf);
        assert_implemented();
        if (!(wi.z >= 0.0f))
            PL_FAIL("wrong: bsdf_sample_f gave wi = (%g, %g, %g), below the surface; a diffuse BSDF samples the upper "
                    "hemisphere (z >= 0 in the local frame)", wi.x, wi.y, wi.z);
        assert_rgb_near(bsdf_f(&m, WO, wi), f, 1e-6f);
        assert_float_near(bsdf_pdf(&m, WO, wi), pdf, 1e-4 * (1.0 + pdf));
    }
}

static void test_bsdf_pdf__integrates_to_one(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    double *e = calloc(DIR_BINS, sizeof *e);
    assert_non_null(e);
    double total = dir_expected_counts(bsdf_pdf_of, &m, e, 1.0);
    free(e);
    assert_implemented();
    assert_float_near(1.0, total, 2e-3);
}

static void test_bsdf_sample_f__matches_bsdf_pdf(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    check_sampler("bsdf_sample_f", bsdf_sample, bsdf_pdf_of, &m, SEED + 4, PART3_CHECK_ALPHA);
}

/* E[f cos / pdf] = integral of f cos = albedo: the estimator's weight is unbiased. */
static void test_bsdf_sample_f__weight_averages_to_albedo(void **state)
{
    (void)state;
    mc_print_seed("bsdf_sample_f weight", SEED + 5);
    rgb albedo = rgb_make(0.8f, 0.5f, 0.2f);
    material m = material_make(albedo, rgb_gray(0.0f));
    stats_acc acc[3] = {stats_acc_make(), stats_acc_make(), stats_acc_make()};
    rng g = rng_seeded(SEED + 5, 0);
    for (int i = 0; i < DIR_SAMPLES / 4; i++) {
        vec3 wi;
        float pdf = 0.0f;
        rgb f = bsdf_sample_f(&m, WO, rng_uniform2(&g), &wi, &pdf);
        assert_implemented();
        rgb w = pdf > 0.0f ? rgb_scale(f, fmaxf(wi.z, 0.0f) / pdf) : rgb_gray(0.0f);
        char where[32];
        snprintf(where, sizeof where, "sample %d", i);
        assert_radiance_valid(w, "f cos / pdf", where);
        stats_acc_add(&acc[0], w.r);
        stats_acc_add(&acc[1], w.g);
        stats_acc_add(&acc[2], w.b);
    }
    assert_mean_matches(&acc[0], albedo.r, PART3_CHECK_ALPHA, "mean f cos / pdf, red");
    assert_mean_matches(&acc[1], albedo.g, PART3_CHECK_ALPHA, "mean f cos / pdf, green");
    assert_mean_matches(&acc[2], albedo.b, PART3_CHECK_ALPHA, "mean f cos / pdf, blue");
}

int sampling_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bsdf_f__is_albedo_over_pi, test_setup),
        cmocka_unit_test_setup(test_bsdf_f__is_black_below_the_surface, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__returns_f_and_pdf_of_its_direction, test_setup),
        cmocka_unit_test_setup(test_bsdf_pdf__integrates_to_one, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__matches_bsdf_pdf, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__weight_averages_to_albedo, test_setup),
    };
    return cmocka_run_group_tests_name("part3: the diffuse BSDF", tests, NULL, NULL);
}
