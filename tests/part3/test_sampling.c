/* Test machinery: not part of any assignment.
 * Direction samplers and the diffuse BSDF: each sampler's histogram must match its pdf twin
 * (Pearson chi-square), and the BSDF sample weight f cos / pdf must average to the albedo.
 * alpha: each statistical check runs at PART3_CHECK_ALPHA, the Sidak share of the suite's
 * PART3_FAMILY_ALPHA = 1e-3 (part3_alpha.h). Seeds are fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../common/stats.h"
#include "../common/mc_assert.h"
#include "../common/histogram_png.h"
#include "../../framework/sampler.h"
#include "../../parts/part3_direct/part3.h"
#include "part3_alpha.h"
#include <stdlib.h>

#define SEED mc_seed(0x5eed3001ull)
#define N_SAMPLES 200000
#define BINS_Z 10     /* cos(theta) in [0, 1] */
#define BINS_PHI 20   /* phi in [0, 2 pi) */
#define BINS (BINS_Z * BINS_PHI + 1)  /* the last bin holds directions below the surface */

typedef vec3 (*dir_sampler)(void *user, vec2 u, float *pdf_out);
typedef float (*dir_pdf)(void *user, vec3 w);

static int bin_of(vec3 w)
{
    if (!(w.z >= 0.0f)) return BINS - 1;
    int iz = (int)(w.z * BINS_Z);
    if (iz >= BINS_Z) iz = BINS_Z - 1;
    double phi = atan2(w.y, w.x);
    if (phi < 0) phi += 2 * M_PI;
    int ip = (int)(phi / (2 * M_PI) * BINS_PHI);
    if (ip >= BINS_PHI) ip = BINS_PHI - 1;
    return iz * BINS_PHI + ip;
}

/* Expected counts: the pdf integrated over each (z, phi) cell, dw = dz dphi, by an 8 x 8 midpoint
 * rule. Returns the total probability, which must be 1 for a normalised pdf. */
static double expected_counts(dir_pdf pdf, void *user, double *expected, double n)
{
    const int sub = 8;
    double total = 0.0;
    for (int iz = 0; iz < BINS_Z; iz++)
        for (int ip = 0; ip < BINS_PHI; ip++) {
            double p = 0.0;
            for (int a = 0; a < sub; a++)
                for (int b = 0; b < sub; b++) {
                    double z = (iz + (a + 0.5) / sub) / BINS_Z;
                    double phi = (ip + (b + 0.5) / sub) / BINS_PHI * 2 * M_PI;
                    double r = sqrt(fmax(0.0, 1.0 - z * z));
                    p += pdf(user, vec3_make((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z));
                }
            p *= (1.0 / BINS_Z) * (2 * M_PI / BINS_PHI) / (sub * sub);
            expected[iz * BINS_PHI + ip] = p * n;
            total += p;
        }
    expected[BINS - 1] = 0.0;
    return total;
}

static void check_sampler(const char *name, dir_sampler sample, dir_pdf pdf, void *user, uint64_t seed)
{
    mc_print_seed(name, seed);
    double *observed = calloc(BINS, sizeof *observed), *expected = calloc(BINS, sizeof *expected);
    assert_non_null(observed);
    assert_non_null(expected);
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < N_SAMPLES; i++) {
        float p = 0.0f;
        vec3 w = sample(user, rng_uniform2(&g), &p);
        assert_implemented();
        if (!(fabsf(vec3_length(w) - 1.0f) < 1e-3f)) {
            print_error("%s: sample %d is not a unit vector: (%g, %g, %g)\n", name, i, w.x, w.y, w.z);
            check_fail(__FILE__, __LINE__);
        }
        observed[bin_of(w)] += 1.0;
    }
    double total = expected_counts(pdf, user, expected, N_SAMPLES);
    assert_float_near(1.0, total, 2e-3);
    double alpha = PART3_CHECK_ALPHA;
    stats_result r = stats_chi2_test(observed, expected, BINS, 5.0, alpha);
    if (r.reject) {
        print_error("%s: directions do not follow the pdf: chi-square %.1f with %g dof, p = %.3g < %.3g "
                    "(below-surface samples: %g)\n", name, r.stat, r.dof, r.p, alpha, observed[BINS - 1]);
        print_error("  cos(theta) bin: observed / expected\n");
        for (int iz = 0; iz < BINS_Z; iz++) {
            double o = 0, e = 0;
            for (int ip = 0; ip < BINS_PHI; ip++) { o += observed[iz * BINS_PHI + ip]; e += expected[iz * BINS_PHI + ip]; }
            print_error("  [%.1f, %.1f): %8.0f / %8.0f\n", (double)iz / BINS_Z, (double)(iz + 1) / BINS_Z, o, e);
        }
        char png[256];
        pl_diag d = pl_diag_default();
        histogram_png_path(name, png, sizeof png);
        if (histogram_png_write(png, observed, expected, BINS_Z, BINS_PHI, &d) == PL_OK)
            print_error("  picture: %s (rows: cos(theta) from 0 at the top to 1; columns: phi from 0 to 2 pi;\n"
                        "  panels: observed, expected, residual: red = too many samples, blue = too few)\n", png);
    }
    free(observed);
    free(expected);
    PL_CHECK(!r.reject);
}
#define check_sampler(...) PL_AT(check_sampler(__VA_ARGS__))  /* failures name the calling test's line */

/* ---- the framework's samplers -------------------------------------------------------------- */
static vec3 uniform_sample(void *u, vec2 xi, float *p) { (void)u; vec3 w = sample_uniform_hemisphere(xi); *p = sample_uniform_hemisphere_pdf(w); return w; }
static float uniform_pdf(void *u, vec3 w) { (void)u; return sample_uniform_hemisphere_pdf(w); }
static vec3 cosine_sample(void *u, vec2 xi, float *p) { (void)u; vec3 w = sample_cosine_hemisphere(xi); *p = sample_cosine_hemisphere_pdf(w); return w; }
static float cosine_pdf(void *u, vec3 w) { (void)u; return sample_cosine_hemisphere_pdf(w); }

static void test_uniform_hemisphere__matches_its_pdf(void **state)
{
    (void)state;
    check_sampler("sample_uniform_hemisphere", uniform_sample, uniform_pdf, NULL, SEED + 1);
    assert_float_near(1.0 / (2.0 * M_PI), sample_uniform_hemisphere_pdf(vec3_make(0, 0, 1)), 1e-6);
}

static void test_cosine_hemisphere__matches_its_pdf(void **state)
{
    (void)state;
    check_sampler("sample_cosine_hemisphere", cosine_sample, cosine_pdf, NULL, SEED + 2);
}

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
        assert_true(wi.z >= 0.0f);
        assert_rgb_near(bsdf_f(&m, WO, wi), f, 1e-6f);
        assert_float_near(bsdf_pdf(&m, WO, wi), pdf, 1e-4 * (1.0 + pdf));
    }
}

static void test_bsdf_pdf__integrates_to_one(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    double *e = calloc(BINS, sizeof *e);
    assert_non_null(e);
    double total = expected_counts(bsdf_pdf_of, &m, e, 1.0);
    free(e);
    assert_implemented();
    assert_float_near(1.0, total, 2e-3);
}

static void test_bsdf_sample_f__matches_bsdf_pdf(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    check_sampler("bsdf_sample_f", bsdf_sample, bsdf_pdf_of, &m, SEED + 4);
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
    for (int i = 0; i < N_SAMPLES / 4; i++) {
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
        cmocka_unit_test_setup(test_uniform_hemisphere__matches_its_pdf, test_setup),
        cmocka_unit_test_setup(test_cosine_hemisphere__matches_its_pdf, test_setup),
        cmocka_unit_test_setup(test_bsdf_f__is_albedo_over_pi, test_setup),
        cmocka_unit_test_setup(test_bsdf_f__is_black_below_the_surface, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__returns_f_and_pdf_of_its_direction, test_setup),
        cmocka_unit_test_setup(test_bsdf_pdf__integrates_to_one, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__matches_bsdf_pdf, test_setup),
        cmocka_unit_test_setup(test_bsdf_sample_f__weight_averages_to_albedo, test_setup),
    };
    return cmocka_run_group_tests_name("part3: samplers and the diffuse BSDF", tests, NULL, NULL);
}
