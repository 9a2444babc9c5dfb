/* Test machinery: not part of any assignment.
 * The image verdict (grader/verdict.c) on synthetic renders whose truth is known: a smooth image
 * with a bright patch, each pixel the mean of spp heavy-tailed samples (most samples half the
 * truth, a rare one carrying the rest, as paths that find a small light do). A correct "render"
 * must pass at the stated rate; biased ones (a factor, a dark region, a NaN) must fail. */
#include "../common/test.h"
#include "../../grader/verdict.h"
#include "../../framework/rng.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120
#define SPP 16
#define RUNS 200
#define FIREFLY_P 0.02f  /* chance a sample is the rare bright one */

static float truth(int x, int y, int ch)
{
    float base = 0.2f + 0.6f * (float)x / W + 0.1f * ch;
    bool patch = x > 100 && x < 130 && y > 20 && y < 50;  /* a lit patch, 4x brighter */
    return patch ? 4.0f * base : base;
}

/* A render of the synthetic scene: per pixel the mean of spp samples with the truth as mean. */
static void render(float *out, int spp, uint64_t seed)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            rng g = rng_for_sample(seed, (uint64_t)y * W + x, 0);
            for (int ch = 0; ch < 3; ch++) {
                double sum = 0.0;
                for (int s = 0; s < spp; s++) {
                    float u = rng_uniform(&g);
                    sum += 0.5f * truth(x, y, ch) * (1.0f + (u < FIREFLY_P ? 1.0f / FIREFLY_P : 0.0f));
                }
                out[3 * (y * W + x) + ch] = (float)(sum / spp);
            }
        }
}

static float *reference;

/* Seeds of the correct renders: fixed, so the suite is reproducible; PL_TEST_SEED draws others. */
static uint64_t base_seed(void)
{
    const char *e = getenv("PL_TEST_SEED");
    return e ? strtoull(e, NULL, 10) * RUNS + 1000 : 1000;
}

static int make_reference(void **state)
{
    (void)state;
    reference = malloc(sizeof(float) * 3 * W * H);
    if (!reference) return -1;
    render(reference, 4096, 999);
    return 0;
}

static int free_reference(void **state)
{
    (void)state;
    free(reference);
    return 0;
}

static verdict judge(const float *cand)
{
    verdict_image c = {W, H, cand, NULL}, r = {W, H, reference, NULL};
    verdict_params p = verdict_params_default(SPP);
    verdict v;
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
    return v;
}

/* The solution's false-failure rate is the verdict's alpha (1e-3): over RUNS fresh seeds at most 3
 * fail (a verdict at its alpha exceeds that with probability 6e-5), and the case p-values are
 * uniform: every decile holds 4 to 40 of the 200 (all ten hold, for uniform p, but for 3e-4).
 * Measured over PL_TEST_SEED=1..10 (2000 renders): 2 failures, every decile 12..33. */
static void test_verdict__correct_render_passes_at_its_alpha(void **state)
{
    (void)state;
    float *cand = malloc(sizeof(float) * 3 * W * H);
    assert_non_null(cand);
    int failures = 0, decile[10] = {0};
    for (int run = 0; run < RUNS; run++) {
        render(cand, SPP, base_seed() + (uint64_t)run);
        verdict v = judge(cand);
        failures += !v.pass;
        decile[v.p_value >= 1.0 ? 9 : (int)(v.p_value * 10)]++;
        verdict_free(&v);
    }
    free(cand);
    print_message("verdict: %d of %d correct renders failed; p-value deciles:", failures, RUNS);
    for (int k = 0; k < 10; k++) print_message(" %d", decile[k]);
    print_message("\n");
    assert_in_range(failures, 0, 3);
    for (int k = 0; k < 10; k++) assert_in_range(decile[k], 4, 40);
}

static void test_verdict__global_factor_fails_with_hint(void **state)
{
    (void)state;
    static const struct { double factor; const char *word; } cases[] = {
        {2.0, "2x"}, {0.5, "1/2"}, {M_PI, "pi x"}, {1.0 / M_PI, "1/pi"}, {1.05, NULL}};
    float *cand = malloc(sizeof(float) * 3 * W * H);
    assert_non_null(cand);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        render(cand, SPP, 7);
        for (int i = 0; i < 3 * W * H; i++) cand[i] *= (float)cases[k].factor;
        verdict v = judge(cand);
        assert_false(v.pass);
        if (cases[k].word) assert_non_null(strstr(v.hint, cases[k].word));
        else assert_string_equal(v.hint, "");
        /* Off by one factor everywhere: the blocks that stand out agree on it. */
        if (!v.uniform_factor) fail_msg("a factor %g everywhere: the verdict did not find the blocks agree", cases[k].factor);
        verdict_free(&v);
    }
    free(cand);
}

/* A local bug: the lit patch 20% too dark. The worst block must lie on the patch. */
static void test_verdict__local_bias_fails_at_its_block(void **state)
{
    (void)state;
    float *cand = malloc(sizeof(float) * 3 * W * H);
    assert_non_null(cand);
    render(cand, SPP, 8);
    for (int y = 20; y < 50; y++)
        for (int x = 100; x < 130; x++)
            for (int ch = 0; ch < 3; ch++) cand[3 * (y * W + x) + ch] *= 0.8f;
    verdict v = judge(cand);
    assert_false(v.pass);
    assert_true(v.worst_t < 0);
    /* A region, not a factor everywhere: the blocks that stand out lie on the patch, 0.8 of its light. */
    assert_false(v.uniform_factor);
    assert_true(v.region_blocks > 0);
    /* Within the blocks the patch (100..130, 20..50) overlaps. */
    int rx0 = v.region_x0 * W / v.blocks_x, rx1 = (v.region_x1 + 1) * W / v.blocks_x;
    int ry0 = v.region_y0 * H / v.blocks_y, ry1 = (v.region_y1 + 1) * H / v.blocks_y;
    if (!(rx0 >= 100 / (W / v.blocks_x) * (W / v.blocks_x) && rx1 <= 160 && ry0 >= 0 && ry1 <= 50 + H / v.blocks_y &&
          rx0 < 130 && rx1 > 100 && ry0 < 50 && ry1 > 20))
        fail_msg("the region x %d..%d, y %d..%d is not the patch's blocks (100..130, 20..50)", rx0, rx1, ry0, ry1);
    if (!(v.region_ratio > 0.75 && v.region_ratio < 0.9)) fail_msg("the region's ratio %g: expected about 0.8", v.region_ratio);
    if (v.worst_block_x >= 0) {
        /* the block [x0, x1) x [y0, y1) overlaps the patch (100, 130) x (20, 50) */
        int x0 = v.worst_block_x * W / v.blocks_x, x1 = (v.worst_block_x + 1) * W / v.blocks_x;
        int y0 = v.worst_block_y * H / v.blocks_y, y1 = (v.worst_block_y + 1) * H / v.blocks_y;
        assert_true(x0 < 130 && x1 > 100 && y0 < 50 && y1 > 20);
    }
    verdict_free(&v);
    free(cand);
}

/* A case lit at grazing angles ("grazing" in cases.json) names self-shadowing when a candidate
 * fails dark there, and only then: not on another case, not when it fails bright. */
static void test_verdict__grazing_case_dark_names_self_shadowing(void **state)
{
    (void)state;
    static const struct { float factor; bool grazing; bool hint; } cases[] = {
        {0.8f, true, true}, {0.8f, false, false}, {1.25f, true, false}};
    float *cand = malloc(sizeof(float) * 3 * W * H);
    assert_non_null(cand);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        render(cand, SPP, 9);
        for (int y = 20; y < 50; y++)
            for (int x = 100; x < 130; x++)
                for (int ch = 0; ch < 3; ch++) cand[3 * (y * W + x) + ch] *= cases[k].factor;
        verdict_image c = {W, H, cand, NULL}, r = {W, H, reference, NULL};
        verdict_params p = verdict_params_default(SPP);
        p.grazing = cases[k].grazing;
        verdict v;
        assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
        assert_false(v.pass);
        assert_int_equal(cases[k].hint, strstr(v.hint, "self-shadowing") != NULL);
        verdict_free(&v);
    }
    free(cand);
}

static void test_verdict__black_where_lit_and_bad_pixels(void **state)
{
    (void)state;
    float *cand = calloc(3 * W * H, sizeof(float));
    assert_non_null(cand);
    verdict v = judge(cand);
    assert_false(v.pass);
    assert_non_null(strstr(v.hint, "black where the reference is lit"));
    verdict_free(&v);

    render(cand, SPP, 9);
    cand[3 * (5 * W + 7) + 1] = NAN;  /* row 5 from the top: y = H - 1 - 5 from the bottom */
    cand[3 * (6 * W + 7) + 2] = -1.0f;
    v = judge(cand);
    assert_false(v.pass);
    assert_int_equal(v.bad_pixels, 2);
    assert_int_equal(v.bad_x, 7);
    assert_int_equal(v.bad_y, H - 1 - 5);
    verdict_free(&v);
    free(cand);
}

static void test_verdict__identical_deterministic_images_pass(void **state)
{
    (void)state;
    verdict v = judge(reference);
    assert_true(v.pass);
    assert_true(v.p_value == 1.0);
    verdict_free(&v);
    verdict_image c = {W, H - 1, reference, NULL}, r = {W, H, reference, NULL};
    verdict_params p = verdict_params_default(SPP);
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_ERR_INVALID);
}

/* ---- known variance: an image like normal shading at jittered edges --------------------------- */

/* Flat everywhere (every sample the same colour) but a band of edge pixels, where each sample is
 * one of two colours with a coverage that varies along the band, as samples either side of a
 * sphere's outline do. The paired t test misjudges such blocks (a few varying pixels among many
 * exact zeros); the known-variance z test uses the reference's variance instead. */
#define EDGE_REF_SPP 1024

static float edge_coverage(int x, int y)
{
    if (x < 60 || x >= 100) return -1.0f;  /* flat: no edge here */
    return (float)(x - 60) / 40.0f * (0.6f + 0.4f * sinf(0.2f * (float)y));
}

/* Means and variances of the means of an edge render at spp, the coverage shifted by bias. */
static void render_edge(float *mean, float *var, int spp, uint64_t seed, float bias)
{
    static const float inside[3] = {0.8f, 0.2f, 0.5f}, outside[3] = {0.3f, 0.6f, 0.9f};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float p = edge_coverage(x, y);
            int k = 0;
            if (p >= 0.0f) {
                rng g = rng_for_sample(seed, (uint64_t)y * W + x, 0);
                for (int s = 0; s < spp; s++) k += rng_uniform(&g) < p + bias;
            }
            for (int ch = 0; ch < 3; ch++) {
                double a = inside[ch], b = outside[ch], f = (double)k / spp;
                mean[3 * (y * W + x) + ch] = (float)(f * a + (1.0 - f) * b);
                /* the sample variance of k values a and spp - k values b, over spp: the mean's */
                var[3 * (y * W + x) + ch] = (float)((double)k * (spp - k) / ((double)spp * (spp - 1)) * (a - b) * (a - b) / spp);
            }
        }
}

/* The same false-failure bound as the t test's (at most 3 of RUNS); a coverage 0.05 off fails. */
static void test_verdict__known_variance_passes_jittered_edges_at_its_alpha(void **state)
{
    (void)state;
    float *ref = malloc(sizeof(float) * 3 * W * H), *ref_var = malloc(sizeof(float) * 3 * W * H);
    float *cand = malloc(sizeof(float) * 3 * W * H), *cand_var = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && ref_var && cand && cand_var);
    render_edge(ref, ref_var, EDGE_REF_SPP, 777, 0.0f);
    verdict_image r = {W, H, ref, ref_var};
    verdict_params p = verdict_params_default(SPP);
    p.known_variance = true;
    p.reference_spp = EDGE_REF_SPP;
    int failures = 0;
    for (int run = 0; run < RUNS; run++) {
        render_edge(cand, cand_var, SPP, base_seed() + (uint64_t)run, 0.0f);
        verdict_image c = {W, H, cand, NULL};
        verdict v;
        assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
        failures += !v.pass;
        verdict_free(&v);
    }
    print_message("known variance: %d of %d correct edge renders failed\n", failures, RUNS);
    assert_in_range(failures, 0, 3);
    render_edge(cand, cand_var, SPP, base_seed() + RUNS, 0.05f);
    verdict_image c = {W, H, cand, NULL};
    verdict v;
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
    if (v.pass) fail_msg("a coverage 0.05 too high passed (p = %g)", v.p_value);
    verdict_free(&v);
    free(ref);
    free(ref_var);
    free(cand);
    free(cand_var);
}

/* ---- deterministic cases: rounding tolerated, nothing else ------------------------------------- */

/* A normal-shaded picture as a pixel-centre render makes it: a wall facing the camera, a floor
 * below row FLOOR_Y, and a sphere of radius SPHERE_R pixels. The sphere's normal varies across it;
 * the picture is moved by (dx, dy) pixels, zoomed about the centre by zoom, and flipped upside down
 * when flip is set. */
#define SPHERE_R 30.0
#define FLOOR_Y 30.0

static void normals_picture(float *out, double dx, double dy, double zoom, bool flip)
{
    for (int row = 0; row < H; row++)
        for (int x = 0; x < W; x++) {
            int y = flip ? row : H - 1 - row;  /* from the bottom, as the renderer counts */
            double px = (x + 0.5 - dx - W / 2.0) / zoom + W / 2.0, py = (y + 0.5 - dy - H / 2.0) / zoom + H / 2.0;
            double sx = (px - 80.0) / SPHERE_R, sy = (py - 64.0) / SPHERE_R, n[3] = {0.0, 0.0, 1.0};
            if (sx * sx + sy * sy < 1.0) {
                n[0] = sx;
                n[1] = sy;
                n[2] = sqrt(1.0 - sx * sx - sy * sy);
            } else if (py < FLOOR_Y) {
                n[1] = 1.0;
                n[2] = 0.0;
            }
            for (int ch = 0; ch < 3; ch++) out[3 * (row * W + x) + ch] = (float)(0.5 * n[ch] + 0.5);
        }
}

static verdict judge_rounding_case(const float *cand, const float *ref)
{
    verdict_image c = {W, H, cand, NULL}, r = {W, H, ref, NULL};
    verdict_params p = verdict_params_default(1);
    p.deterministic = true;
    p.min_block_pixels = 32 * 32;
    p.min_block_samples = 0;
    verdict v;
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
    return v;
}

/* Another correct implementation: every pixel off by rounding (up to 0.9 of the tolerance, both
 * signs), and VERDICT_TIE_PIXELS pixels of an edge that went the other way. It passes, and the
 * verdict says how many pixels were beyond the tolerance. One tie more fails. */
static void test_verdict__deterministic_tolerates_rounding_and_ties(void **state)
{
    (void)state;
    float *ref = malloc(sizeof(float) * 3 * W * H), *cand = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && cand);
    normals_picture(ref, 0.0, 0.0, 1.0, false);
    rng g = rng_for_sample(4242, 0, 0);
    for (int i = 0; i < 3 * W * H; i++)
        cand[i] = ref[i] + (float)((2.0 * rng_uniform(&g) - 1.0) * 0.9 * VERDICT_ROUNDING_TOLERANCE);
    for (int k = 0; k < VERDICT_TIE_PIXELS; k++) {  /* ties along the floor's edge */
        int i = 3 * ((H - 1 - (int)FLOOR_Y) * W + 10 * k);
        cand[i + 1] = 1.0f;  /* the floor's colour (0.5, 1, 0.5) where the wall's (0.5, 0.5, 1) is */
        cand[i + 2] = 0.5f;
    }
    verdict v = judge_rounding_case(cand, ref);
    if (!v.pass) fail_msg("rounding and %d ties failed: %ld beyond, largest %g", VERDICT_TIE_PIXELS, v.beyond_tolerance, v.max_diff);
    assert_true(v.deterministic);
    assert_int_equal(v.beyond_tolerance, VERDICT_TIE_PIXELS);
    assert_true(v.max_diff >= 0.49 && v.p_value == 1.0);
    verdict_free(&v);
    cand[3 * ((H - 1 - (int)FLOOR_Y) * W + 155) + 2] = 0.5f;  /* one tie too many */
    v = judge_rounding_case(cand, ref);
    assert_false(v.pass);
    assert_int_equal(v.beyond_tolerance, VERDICT_TIE_PIXELS + 1);
    verdict_free(&v);
    free(ref);
    free(cand);
}

/* Real bugs fail by a wide margin: at least ten times the ties allowed beyond the tolerance, and
 * a largest difference at least ten times the tolerance. */
static void test_verdict__deterministic_fails_flips_shifts_scales_and_wrong_normals(void **state)
{
    (void)state;
    static const struct { const char *what; double dx, dy, zoom; bool flip; int channel; float gain; } bugs[] = {
        {"flipped upside down", 0, 0, 1, true, -1, 1},  {"shifted half a pixel right", 0.5, 0, 1, false, -1, 1},
        {"shifted one pixel up", 0, 1, 1, false, -1, 1}, {"zoomed by 2%", 0, 0, 1.02, false, -1, 1},
        {"a normal not normalised (x 1.1)", 0, 0, 1, false, 0, 1.1f}, {"blue channel 2% dark", 0, 0, 1, false, 2, 0.98f},
    };
    float *ref = malloc(sizeof(float) * 3 * W * H), *cand = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && cand);
    normals_picture(ref, 0.0, 0.0, 1.0, false);
    for (size_t k = 0; k < sizeof bugs / sizeof bugs[0]; k++) {
        normals_picture(cand, bugs[k].dx, bugs[k].dy, bugs[k].zoom, bugs[k].flip);
        for (int i = 0; bugs[k].channel >= 0 && i < W * H; i++) {  /* scale the component, not the colour */
            float *c = &cand[3 * i + bugs[k].channel];
            *c = 0.5f + bugs[k].gain * (*c - 0.5f);
            if (bugs[k].channel == 2) *c = bugs[k].gain * *c;
        }
        verdict v = judge_rounding_case(cand, ref);
        print_message("%s: %ld pixels beyond the tolerance, largest difference %.3g\n", bugs[k].what,
                      v.beyond_tolerance, v.max_diff);
        if (v.pass || v.beyond_tolerance < 10 * VERDICT_TIE_PIXELS || v.max_diff < 10 * VERDICT_ROUNDING_TOLERANCE)
            fail_msg("%s: not a wide failure (%ld pixels beyond, largest %g)", bugs[k].what, v.beyond_tolerance,
                     v.max_diff);
        assert_true(v.p_value == 0.0 && v.max_x >= 0 && v.worst_block_x >= 0);
        verdict_free(&v);
    }
    free(ref);
    free(cand);
}

/* ---- statistical cases: coverage the reference never saw --------------------------------------- */

/* Slivers: pixels scattered over a flat image where a sample hits another surface with a tiny
 * probability (1e-5 to 1e-4), so the reference's 1024 samples almost always all miss it (zero
 * variance) while a candidate's 16 now and then hit it. Such a pixel must weigh what one Bernoulli
 * hit weighs, never p = 0: the verdict uses the candidate's own variance where the reference's is
 * zero, up to what one hit in SPP weighs against the reference's neighbourhood. Alpha: the case's 1e-3; at most 3 of RUNS fail (6e-5 at that alpha). Fixed seeds
 * (base_seed). Without the candidate's variance most renders fail; a coverage 0.05 too high fails. */
static float sliver_coverage(int x, int y)
{
    if ((x + 3 * y) % 7 != 0) return -1.0f;
    return 1e-5f + 9e-5f * (float)((x * 7 + y * 13) % 17) / 16.0f;
}

static void render_slivers(float *mean, float *var, int spp, uint64_t seed, float bias)
{
    static const float inside[3] = {0.8f, 0.2f, 0.5f}, outside[3] = {0.3f, 0.6f, 0.9f};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float p = sliver_coverage(x, y);
            int k = 0;
            rng g = rng_for_sample(seed, (uint64_t)y * W + x, 0);
            for (int s = 0; p >= 0.0f && s < spp; s++) k += rng_uniform(&g) < p + bias;
            for (int ch = 0; ch < 3; ch++) {
                double a = inside[ch], b = outside[ch], f = (double)k / spp;
                mean[3 * (y * W + x) + ch] = (float)(f * a + (1.0 - f) * b);
                var[3 * (y * W + x) + ch] = (float)((double)k * (spp - k) / ((double)spp * (spp - 1)) * (a - b) * (a - b) / spp);
            }
        }
}

static void test_verdict__known_variance_models_coverage_the_reference_missed(void **state)
{
    (void)state;
    float *ref = malloc(sizeof(float) * 3 * W * H), *ref_var = malloc(sizeof(float) * 3 * W * H);
    float *cand = malloc(sizeof(float) * 3 * W * H), *cand_var = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && ref_var && cand && cand_var);
    render_slivers(ref, ref_var, EDGE_REF_SPP, 778, 0.0f);
    verdict_image r = {W, H, ref, ref_var};
    verdict_params p = verdict_params_default(SPP);
    p.known_variance = true;
    p.reference_spp = EDGE_REF_SPP;
    int failures = 0, unseen = 0;
    for (int run = 0; run < RUNS; run++) {
        render_slivers(cand, cand_var, SPP, base_seed() + 5000 + (uint64_t)run, 0.0f);
        for (int i = 0; i < W * H; i++) unseen += ref_var[3 * i] == 0.0f && cand[3 * i] != ref[3 * i];
        verdict_image c = {W, H, cand, cand_var};
        verdict v;
        assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
        failures += !v.pass;
        verdict_free(&v);
    }
    print_message("slivers: %d of %d correct renders failed; %d candidate pixels hit what the reference never "
                  "saw\n", failures, RUNS, unseen);
    assert_true(unseen > RUNS);  /* the test exercises what it claims to: several per render */
    assert_in_range(failures, 0, 3);
    render_slivers(cand, cand_var, SPP, base_seed() + 9000, 0.05f);
    verdict_image c = {W, H, cand, cand_var};
    verdict v;
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
    if (v.pass) fail_msg("slivers 0.05 more covered passed (p = %g)", v.p_value);
    verdict_free(&v);
    free(ref);
    free(ref_var);
    free(cand);
    free(cand_var);
}

/* A forged film: flat grey where the reference is a sharp black and white edge whose samples never
 * varied, with an enormous claimed sum of squares. Where the reference saw no spread the verdict
 * takes the candidate's variance only up to what one hit weighs against the reference's
 * neighbourhood, so the claim buys nothing: the film fails (it passed at p = 1 when the candidate's
 * variance counted whole). */
static void test_verdict__known_variance_ignores_a_forged_variance(void **state)
{
    (void)state;
    float *ref = malloc(sizeof(float) * 3 * W * H), *ref_var = calloc((size_t)3 * W * H, sizeof(float));
    float *cand = malloc(sizeof(float) * 3 * W * H), *cand_var = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && ref_var && cand && cand_var);
    for (int i = 0; i < 3 * W * H; i++) {
        ref[i] = i / 3 % W < W / 2 ? 0.0f : 1.0f;
        cand[i] = 0.5f;
        cand_var[i] = 1e30f;
    }
    verdict_image c = {W, H, cand, cand_var}, r = {W, H, ref, ref_var};
    verdict_params p = verdict_params_default(SPP);
    p.known_variance = true;
    p.reference_spp = EDGE_REF_SPP;
    verdict v;
    assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
    if (v.pass) fail_msg("a flat grey film with a forged variance passed (p = %g)", v.p_value);
    verdict_free(&v);
    free(ref);
    free(ref_var);
    free(cand);
    free(cand_var);
}

/* A tolerance (a case that accepts two conventions whose images differ a little): a region 2%
 * darker fails without it at many samples, passes with a 4% tolerance, and a region 10% darker still
 * fails with it. */
static void test_verdict__a_relative_tolerance_accepts_a_small_difference_only(void **state)
{
    (void)state;
    float *cand = malloc(sizeof(float) * 3 * W * H);
    assert_non_null(cand);
    static const struct { float factor; double tolerance; bool pass; } cases[] = {
        {0.98f, 0.0, false}, {0.98f, 0.04, true}, {0.90f, 0.04, false}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        render(cand, 1024, 11);  /* many samples: the 2% difference is far beyond the noise */
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W / 2; x++)
                for (int ch = 0; ch < 3; ch++) cand[3 * (y * W + x) + ch] *= cases[k].factor;
        verdict_image c = {W, H, cand, NULL}, r = {W, H, reference, NULL};
        verdict_params p = verdict_params_default(1024);
        p.relative_tolerance = cases[k].tolerance;
        verdict v;
        assert_int_equal(verdict_compute(&c, &r, &p, &v, NULL), PL_OK);
        if (v.pass != cases[k].pass)
            fail_msg("half the image at %g, tolerance %g: expected %s, p = %g", cases[k].factor, cases[k].tolerance,
                     cases[k].pass ? "a pass" : "a failure", v.p_value);
        verdict_free(&v);
    }
    free(cand);
}

/* ---- the noise check: as noisy as the course's render, not more --------------------------------- */

/* Per-sample variances: the reference's v everywhere; a candidate equal to it but for one firefly
 * pixel (a thousand times) has a ratio near 1, one whose third of pixels is 4x as noisy (a light
 * sample reused for 4) well above GRADE's 1.15. */
static void test_verdict__noise_ratio_sees_extra_noise_not_one_firefly(void **state)
{
    (void)state;
    float *ref = malloc(sizeof(float) * 3 * W * H), *ref_var = malloc(sizeof(float) * 3 * W * H);
    float *cand_var = malloc(sizeof(float) * 3 * W * H);
    assert_true(ref && ref_var && cand_var);
    for (int i = 0; i < 3 * W * H; i++) {
        ref[i] = 0.5f;
        ref_var[i] = 0.04f / 1024.0f;  /* per-sample 0.04 at 1024 samples */
        cand_var[i] = 0.04f / 16.0f;   /* the same per sample at 16 */
    }
    verdict_image c = {W, H, ref, cand_var}, r = {W, H, ref, ref_var};
    assert_float_near(1.0, verdict_noise_ratio(&c, &r, 16, 1024), 1e-6);
    cand_var[3 * 77] = cand_var[3 * 77 + 1] = 1000.0f * 0.04f / 16.0f;
    double one_firefly = verdict_noise_ratio(&c, &r, 16, 1024);
    for (int i = 0; i < 3 * W * H; i++)
        if (i / 3 % 3 == 0) cand_var[i] *= 4.0f;
    double reused = verdict_noise_ratio(&c, &r, 16, 1024);
    print_message("noise ratio: one firefly %.4f, a third of the pixels 4x as noisy %.3f\n", one_firefly, reused);
    assert_true(one_firefly < 1.001);
    assert_true(reused > 1.9);
    verdict_image no_var = {W, H, ref, NULL};
    assert_true(isnan(verdict_noise_ratio(&no_var, &r, 16, 1024)));
    free(ref);
    free(ref_var);
    free(cand_var);
}

int verdict_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_verdict__correct_render_passes_at_its_alpha),
        cmocka_unit_test(test_verdict__global_factor_fails_with_hint),
        cmocka_unit_test(test_verdict__grazing_case_dark_names_self_shadowing),
        cmocka_unit_test(test_verdict__local_bias_fails_at_its_block),
        cmocka_unit_test(test_verdict__a_relative_tolerance_accepts_a_small_difference_only),
        cmocka_unit_test(test_verdict__black_where_lit_and_bad_pixels),
        cmocka_unit_test(test_verdict__identical_deterministic_images_pass),
        cmocka_unit_test(test_verdict__known_variance_passes_jittered_edges_at_its_alpha),
        cmocka_unit_test(test_verdict__deterministic_tolerates_rounding_and_ties),
        cmocka_unit_test(test_verdict__deterministic_fails_flips_shifts_scales_and_wrong_normals),
        cmocka_unit_test(test_verdict__known_variance_models_coverage_the_reference_missed),
        cmocka_unit_test(test_verdict__known_variance_ignores_a_forged_variance),
        cmocka_unit_test(test_verdict__noise_ratio_sees_extra_noise_not_one_firefly),
    };
    return cmocka_run_group_tests_name("verdict", tests, make_reference, free_reference);
}
