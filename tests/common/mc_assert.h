/* Test machinery: not part of any assignment.
 * Monte Carlo asserts for radiance estimators: run an estimator many times on its own random
 * streams, fail at once (naming the sample or pixel) on NaN, Inf or negative radiance, and compare
 * the mean with the answer from paper by a t test at a stated alpha. Include after test.h. */
#ifndef PL_MC_ASSERT_H
#define PL_MC_ASSERT_H

#include <stdint.h>
#include "../../framework/stats.h"
#include "../../framework/render.h"

typedef rgb (*mc_estimator)(const render_ctx *ctx, const ray *r, const hit *h, rng *g);

/* Fails naming `where` (e.g. "sample 12" or "pixel (3, 4)") unless L is finite and >= 0. */
void mc_check_radiance(rgb L, const char *what, const char *where, const char *file, int line);
#define assert_radiance_valid(L, what, where) mc_check_radiance((L), (what), (where), __FILE__, __LINE__)

/* Sample i (0 .. n-1) draws from rng_for_sample(seed, 0, i), independent streams; out[0..2] collect r, g, b. */
void mc_run_at(const render_ctx *ctx, mc_estimator est, const char *what, const ray *r, const hit *h,
               uint64_t seed, int n, stats_acc out[3], const char *file, int line);
/* The same for the whole radiance_estimate along r (a copy of r for every sample). */
void mc_run_ray(const render_ctx *ctx, const char *what, const ray *r, uint64_t seed, int n,
                stats_acc out[3], const char *file, int line);
#define run_estimator(ctx, est, r, h, seed, n, out) mc_run_at((ctx), (est), #est, (r), (h), (seed), (n), (out), __FILE__, __LINE__)
#define run_radiance(ctx, r, seed, n, out) mc_run_ray((ctx), "radiance_estimate", (r), (seed), (n), (out), __FILE__, __LINE__)

/* t test of the mean of a against expected at level alpha; on failure prints both values, the
 * standard error, t and p. */
void mc_check_mean(const stats_acc *a, double expected, double alpha, const char *what, const char *file, int line);
#define assert_mean_matches(acc, expected, alpha, what) mc_check_mean((acc), (expected), (alpha), (what), __FILE__, __LINE__)

/* The seed a test uses: `fixed`, or fixed XOR $PL_TEST_SEED when that is set (to check the
 * calibration of the suite over fresh seeds: a correct solution fails about alpha of the runs). */
uint64_t mc_seed(uint64_t fixed);
/* Prints "seed 0x..." for the log, so a failure can be replayed. */
void mc_print_seed(const char *test, uint64_t seed);

#endif
