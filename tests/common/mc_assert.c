/* Test machinery: not part of any assignment. */
#include "test.h"
#include "mc_assert.h"
#include <stdio.h>
#include <stdlib.h>

void mc_check_radiance(rgb L, const char *what, const char *where, const char *file, int line)
{
    if (!rgb_is_finite(L) || L.r < 0.0f || L.g < 0.0f || L.b < 0.0f) {
        print_error("%s: invalid radiance at %s: rgb(%g, %g, %g) (NaN, Inf and negative values are "
                    "bugs: look for a division by a zero pdf or a negative cosine)\n",
                    what, where, L.r, L.g, L.b);
        check_fail(file, line);
    }
}

static void add_sample(stats_acc out[3], rgb L)
{
    stats_acc_add(&out[0], L.r);
    stats_acc_add(&out[1], L.g);
    stats_acc_add(&out[2], L.b);
}

void mc_run_at(const render_ctx *ctx, mc_estimator est, const char *what, const ray *r, const hit *h,
               uint64_t seed, int n, stats_acc out[3], const char *file, int line)
{
    for (int c = 0; c < 3; c++) out[c] = stats_acc_make();
    for (int i = 0; i < n; i++) {
        /* Each sample its own stream, seeded as the renderer seeds a pixel's samples (SplitMix64 over
         * the seed and the sample index). Not rng_seeded(seed, i): PCG32 streams that share a seed and
         * differ only in their increment are correlated (the n-th draws of samples 0, 1, 2, ... form
         * one arithmetic progression of LCG states, whatever the seed), so the samples were a shifted
         * lattice, not independent, and a t test passed or failed correct code by where in [0, 1) it
         * put a branch (a glass reflecting in [0.48, 0.52) instead of [0, 0.04)). */
        rng g = rng_for_sample(seed, 0, (uint64_t)i);
        rgb L = est(ctx, r, h, &g);
        if (pl_todo_count() > 0)
            check_implemented(file, line);
        char where[64];
        snprintf(where, sizeof where, "sample %d (seed 0x%llx)", i, (unsigned long long)seed);
        mc_check_radiance(L, what, where, file, line);
        add_sample(out, L);
    }
}

/* radiance_estimate in mc_estimator's shape: it needs no hit, and shrinks a copy of the ray. */
static rgb estimate_along_ray(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    ray copy = *r;
    return radiance_estimate(ctx, &copy, g);
}

void mc_run_ray(const render_ctx *ctx, const char *what, const ray *r, uint64_t seed, int n,
                stats_acc out[3], const char *file, int line)
{
    mc_run_at(ctx, estimate_along_ray, what, r, NULL, seed, n, out, file, line);
}

void mc_check_mean(const stats_acc *a, double expected, double alpha, const char *what, const char *file, int line)
{
    stats_result t = stats_ttest_mean(a, expected, alpha);
    if (t.reject) {
        print_error("%s: wrong mean: expected %.6g, got %.6g +- %.3g (standard error, %ld samples); "
                    "t = %.2f, p = %.3g < alpha = %.3g\n",
                    what, expected, a->mean, stats_acc_sem(a), a->n, t.stat, t.p, alpha);
        check_fail(file, line);
    }
}

void mc_print_seed(const char *test, uint64_t seed)
{
    print_message("%s: seed 0x%llx\n", test, (unsigned long long)seed);
}

uint64_t mc_seed(uint64_t fixed)
{
    const char *env = getenv("PL_TEST_SEED");
    return env ? fixed ^ strtoull(env, NULL, 0) : fixed;
}
