/* Test machinery: not part of any assignment.
 * Task 5.1, adaptive_converged, checked exactly on hand-computed cases (no randomness); then the
 * framework's pixel loop asking it after every batch (render_pixel with -a B T).
 * Adaptive sampling on the stripes scene (tests/common/tiny_scenes.h), rendered with -m 0 so each
 * sample's radiance is exactly known: the left half of the image is flat grey, and in the right
 * half every sample is red (1, 0, 0) or green (0, 1, 0) with probability 1/2 each. So:
 * - a flat pixel has zero variance and must stop at the first batch;
 * - a striped pixel's sample count has a distribution we compute exactly (a dynamic programme
 *   over the number of green samples, with the stopping rule of part5.h on LUMINANCE), and the
 *   mean count over the striped pixels must match it (t test). A rule on another statistic (the
 *   red channel, the max channel, the standard deviation instead of the standard error...) stops
 *   at other counts and fails;
 * - with tolerance 0 every striped pixel takes all spp samples and the image is the fixed-rate one.
 * alpha: two statistical checks, each at PART5_CHECK_ALPHA (family alpha and budget:
 * part5_alpha.h). Seeds fixed, printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <stdlib.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "part5_alpha.h"
#include "../../parts/part5_adaptive/part5.h"
#include "../../framework/render.h"

#define SEED mc_seed(0x5eed5001ull)

#define W 32
#define H 8
#define BATCH 32
#define SPP 128
/* Chosen so that no reachable (n, greens) sits within 2% of the stopping threshold: float and
 * double implementations of the rule make the same decisions. */
#define TOL 0.1663f

typedef struct {
    tiny_world w;
    int counts[W * H];  /* indexed like render_pixel's (x, y): y * W + x, y = 0 at the bottom */
    rgb pixels[W * H];
} adaptive_run;

static adaptive_run *run_stripes(bool adaptive, float tol, int spp, uint64_t seed)
{
    adaptive_run *run = malloc(sizeof *run);
    assert_non_null(run);
    tiny_world_begin(&run->w);
    assert_true(tiny_scene_stripes(&run->w.s));
    run->w.o.width = W;
    run->w.o.height = H;
    run->w.o.max_depth = 0;
    run->w.o.spp = spp;
    run->w.o.adaptive = adaptive;
    run->w.o.adaptive_batch = BATCH;
    run->w.o.adaptive_tol = tol;
    run->w.o.seed = seed;
    assert_int_equal(PL_OK, tiny_world_finish(&run->w));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            film_pixel p = {0};
            render_pixel(&run->w.ctx, x, y, &p);
            assert_implemented();
            rgb L = rgb_make((float)film_pixel_mean(&p, 0), (float)film_pixel_mean(&p, 1), (float)film_pixel_mean(&p, 2));
            char where[48];
            snprintf(where, sizeof where, "pixel (%d, %d)", x, y);
            assert_radiance_valid(L, "the pixel loop", where);
            run->pixels[y * W + x] = L;
            run->counts[y * W + x] = (int)p.n;
        }
    return run;
}

static void free_run(adaptive_run *run)
{
    tiny_world_free(&run->w);
    free(run);
}

/* The stopping rule of part5.h, in double, for n samples of which `greens` are green. */
static bool rule_stops(int n, int greens, double tol)
{
    double a = rgb_luminance(rgb_make(1, 0, 0)), b = rgb_luminance(rgb_make(0, 1, 0));
    double s1 = greens * b + (n - greens) * a, s2 = greens * b * b + (n - greens) * a * a;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}

/* Batches a striped pixel can stop after: BATCH, 2 BATCH, ..., SPP. */
#define STOPS ((SPP + BATCH - 1) / BATCH)

/* Exact distribution of a striped pixel's sample count: stop[j] is the chance it stops after batch
 * j + 1. Carries the distribution of the number of green samples among the pixels still running
 * from one batch to the next. */
static void count_distribution(double tol, double stop[STOPS])
{
    double *p = calloc(SPP + 1, sizeof *p), *next = calloc(SPP + 1, sizeof *next);
    assert_non_null(p);
    assert_non_null(next);
    p[0] = 1.0;
    for (int n = 0, j = 0; n < SPP; n += BATCH, j++) {
        int step = n + BATCH <= SPP ? BATCH : SPP - n;
        /* add `step` fair coin flips to every live state */
        for (int i = 0; i <= SPP; i++) next[i] = 0.0;
        for (int k = 0; k <= n; k++) {
            if (p[k] == 0.0) continue;
            double c = p[k] * pow(0.5, step);
            for (int i = 0; i <= step; i++) {
                next[k + i] += c;
                c = c * (step - i) / (i + 1);
            }
        }
        int m = n + step;
        stop[j] = 0.0;
        for (int k = 0; k <= m; k++) {
            p[k] = next[k];
            if (p[k] > 0.0 && (m == SPP || rule_stops(m, k, tol))) {
                stop[j] += p[k];
                p[k] = 0.0;
            }
        }
    }
    free(p);
    free(next);
}

/* Exact two-sided p-value of `total` batches summed over `pixels` independent striped pixels, each
 * stopping after batch j + 1 with chance stop[j]: twice the smaller tail of the convolution. */
static double batches_p2(const double stop[STOPS], int pixels, int total)
{
    int most = pixels * STOPS;
    double *dist = calloc((size_t)most + 1, sizeof *dist), *next = calloc((size_t)most + 1, sizeof *next);
    assert_non_null(dist);
    assert_non_null(next);
    dist[0] = 1.0;
    for (int i = 0; i < pixels; i++) {
        for (int t = 0; t <= most; t++) next[t] = 0.0;
        for (int t = 0; t <= i * STOPS; t++)
            for (int j = 0; j < STOPS; j++) next[t + j + 1] += dist[t] * stop[j];
        double *swap = dist; dist = next; next = swap;
    }
    double lower = 0.0, upper = 0.0;
    for (int t = 0; t <= most; t++) {
        if (t <= total) lower += dist[t];
        if (t >= total) upper += dist[t];
    }
    free(dist);
    free(next);
    double two = 2.0 * fmin(lower, upper);
    return fmin(1.0, two);
}

/* ---- adaptive_converged alone: exact ---------------------------------------------------------- */

static void expect_converged(int n, double s1, double s2, float tol, bool want, const char *why)
{
    bool got = adaptive_converged(n, s1, s2, tol);
    assert_implemented();
    if (got != want)
        fail_msg("wrong: adaptive_converged(n = %d, s1 = %g, s2 = %g, tol = %g) = %s, expected %s: %s",
                 n, s1, s2, tol, got ? "true" : "false", want ? "true" : "false", why);
}

static void test_adaptive_converged__one_sample_never_converges(void **state)
{
    (void)state;
    expect_converged(1, 5.0, 25.0, 1e6f, false, "one sample gives no variance estimate (n - 1 = 0)");
}

static void test_adaptive_converged__constant_samples_converge(void **state)
{
    (void)state;
    expect_converged(32, 32.0, 32.0, 0.05f, true, "32 samples of 1: variance 0, I = 0");
    expect_converged(2, 4.0, 8.0, 0.0f, true, "two samples of 2: I = 0 <= 0");
}

/* n = 100, mean 1, sample variance 1: the standard error is 0.1 and I = 0.196; one sample's
 * standard deviation would give I = 1.96. */
static void test_adaptive_converged__uses_the_standard_error_of_the_mean(void **state)
{
    (void)state;
    expect_converged(100, 100.0, 199.0, 0.25f, true, "I = 1.96 sqrt(var / n) = 0.196 <= 0.25 * mean 1");
    expect_converged(100, 100.0, 199.0, 0.15f, false, "I = 0.196 > 0.15 (the 1.96 factor)");
}

/* n = 2, samples 1 and 3: mean 2, var = (10 - 16 / 2) / (2 - 1) = 2, I = 1.96 sqrt(2 / 2) = 1.96,
 * I / mean = 0.98. Dividing by n instead of n - 1 would give I / mean = 0.69. */
static void test_adaptive_converged__sample_variance_divides_by_n_minus_1(void **state)
{
    (void)state;
    expect_converged(2, 4.0, 10.0, 1.0f, true, "I / mean = 0.98 <= 1");
    expect_converged(2, 4.0, 10.0, 0.96f, false, "I / mean = 0.98 > 0.96 (var divides by n - 1)");
}

static void test_adaptive_converged__rounding_below_zero_is_zero_variance(void **state)
{
    (void)state;
    expect_converged(3, 3.0, 3.0 - 1e-12, 0.0f, true, "s2 - s1^2 / n is -1e-12 by rounding: variance 0, I = 0");
}

/* ---- the framework's loop asking it after every batch ---------------------------------------- */

static void test_adaptive__flat_pixels_stop_after_the_first_batch(void **state)
{
    (void)state;
    mc_print_seed("adaptive flat", SEED);
    adaptive_run *run = run_stripes(true, TOL, SPP, SEED);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W / 2; x++) {
            int n = run->counts[y * W + x];
            if (n != BATCH)
                PL_FAIL("wrong: flat pixel (%d, %d) (radiance constant 1) took %d samples, expected %d (one batch)", x, y,
                        n, BATCH);
            assert_rgb_near(rgb_gray(1.0f), run->pixels[y * W + x], 1e-6f);
        }
    free_run(run);
}

static void test_adaptive__sample_counts_are_whole_batches_up_to_spp(void **state)
{
    (void)state;
    const int spp = 80;  /* not a multiple of the batch: the last batch is cut short */
    adaptive_run *run = run_stripes(true, TOL, spp, SEED + 1);
    for (int i = 0; i < W * H; i++) {
        int n = run->counts[i];
        if (n < 1 || n > spp || (n % BATCH != 0 && n != spp))
            PL_FAIL("wrong: pixel (%d, %d) took %d samples: expected a multiple of %d, or %d", i % W, i / W, n, BATCH, spp);
    }
    free_run(run);
}

static void test_adaptive__noisy_pixels_stop_where_the_luminance_rule_says(void **state)
{
    (void)state;
    mc_print_seed("adaptive stripes", SEED + 2);
    adaptive_run *run = run_stripes(true, TOL, SPP, SEED + 2);
    stats_acc acc = stats_acc_make();
    int batches = 0;  /* each count is a whole number of batches: SPP is a multiple of BATCH */
    for (int y = 0; y < H; y++)
        for (int x = W / 2; x < W; x++) {
            stats_acc_add(&acc, run->counts[y * W + x]);
            batches += (run->counts[y * W + x] + BATCH - 1) / BATCH;
        }
    free_run(run);
    double stop[STOPS], mean = 0.0, var = 0.0;
    count_distribution(TOL, stop);
    for (int j = 0; j < STOPS; j++) {
        double m = (double)(j + 1) * BATCH;
        mean += stop[j] * m;
        var += stop[j] * m * m;
    }
    var -= mean * mean;
    /* The exact distribution of the total over the pixels (a convolution), not a normal approximation. */
    double p = batches_p2(stop, (int)acc.n, batches);
    double z = (acc.mean - mean) / sqrt(var / (double)acc.n);
    print_message("striped pixels: mean count %.2f, the luminance rule gives %.2f +- %.2f\n", acc.mean, mean,
                  sqrt(var / (double)acc.n));
    double alpha = PART5_CHECK_ALPHA;
    if (p < alpha)
        PL_FAIL("wrong: striped pixels took %.2f samples on average; the rule on luminance gives %.2f +- %.2f "
                "(z = %.1f, exact p = %.3g < %.3g). Test I = 1.96 sqrt(var / n) <= T mean on the luminance "
                "of each sample (part5.h).", acc.mean, mean, sqrt(var / (double)acc.n), z, p, alpha);
    if (!(acc.mean > BATCH))
        PL_FAIL("wrong: noisy pixels took %.2f samples on average, no more than the first batch of %d", acc.mean, BATCH);
}

static void test_adaptive__zero_tolerance_is_the_fixed_rate_estimate(void **state)
{
    (void)state;
    mc_print_seed("adaptive T = 0", SEED + 3);
    adaptive_run *fixed = run_stripes(false, 0.0f, 64, SEED + 3);
    adaptive_run *adapt = run_stripes(true, 0.0f, 64, SEED + 3);
    /* Each pixel: a mean of 64 samples of a fair coin in red and green, so sd 0.0625 per channel,
     * and two independent such means (if the two draw their numbers differently) differ by
     * 0.088 sd. The bound is the Sidak-corrected normal quantile over the pixels. */
    double alpha_pixel = stats_sidak(PART5_CHECK_ALPHA, W * H / 2);  /* one check, split over the pixels */
    double zcrit = stats_t_quantile2(alpha_pixel, 1e9);
    double tol = zcrit * 0.5 * sqrt(2.0 / 64.0);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int i = y * W + x;
            if (x >= W / 2 && adapt->counts[i] != 64)
                PL_FAIL("wrong: pixel (%d, %d): with tolerance 0 a noisy pixel must take all 64 samples, took %d", x, y,
                        adapt->counts[i]);
            assert_rgb_near(fixed->pixels[i], adapt->pixels[i], (float)tol);
        }
    free_run(fixed);
    free_run(adapt);
}

int adaptive_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_adaptive_converged__one_sample_never_converges, test_setup),
        cmocka_unit_test_setup(test_adaptive_converged__constant_samples_converge, test_setup),
        cmocka_unit_test_setup(test_adaptive_converged__uses_the_standard_error_of_the_mean, test_setup),
        cmocka_unit_test_setup(test_adaptive_converged__sample_variance_divides_by_n_minus_1, test_setup),
        cmocka_unit_test_setup(test_adaptive_converged__rounding_below_zero_is_zero_variance, test_setup),
        cmocka_unit_test_setup(test_adaptive__flat_pixels_stop_after_the_first_batch, test_setup),
        cmocka_unit_test_setup(test_adaptive__sample_counts_are_whole_batches_up_to_spp, test_setup),
        cmocka_unit_test_setup(test_adaptive__noisy_pixels_stop_where_the_luminance_rule_says, test_setup),
        cmocka_unit_test_setup(test_adaptive__zero_tolerance_is_the_fixed_rate_estimate, test_setup),
    };
    return cmocka_run_group_tests_name("part5: adaptive_converged (task 5.1) and adaptive sampling", tests, NULL, NULL);
}
