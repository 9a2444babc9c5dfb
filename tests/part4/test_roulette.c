/* Test machinery: not part of any assignment.
 * Russian roulette: it must end paths (fewer rays) and change the noise, but never the mean.
 * - the rule alone: E[beta after, 0 when ended] = beta before, per channel (t test);
 * - in the furnace at -m 12: the estimate with roulette and without (--no-rr: settings.roulette false) both match
 *   Le (1 - rho^13) / (1 - rho) (direct light by -H, see test_furnace.c), and roulette traces fewer rays. The two variances are printed
 *   (roulette's is the larger: E[(X / q)^2 q] >= E[X^2]) but not judged: how much larger depends
 *   on the rule a student picks.
 * alpha: each t test runs at PART4_CHECK_ALPHA (part4_alpha.h: Sidak share of the suite's 1e-3).
 * Seeds fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part4_global/part4.h"
#include "part4_alpha.h"
#include "../../framework/counters.h"
#include <stdlib.h>

#define SEED mc_seed(0x5eed4002ull)
#define RHO 0.5
#define LE 1.0
#define DEPTH 12
#define N 20000

static void check_rule_keeps_mean(int next_depth, rgb beta0, uint64_t seed)
{
    mc_print_seed("russian_roulette", seed);
    stats_acc acc[3] = {stats_acc_make(), stats_acc_make(), stats_acc_make()};
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < 100000; i++) {
        rgb beta = beta0;
        bool go_on = russian_roulette(&beta, next_depth, &g);
        assert_implemented();
        rgb kept = go_on ? beta : rgb_gray(0.0f);
        char where[32];
        snprintf(where, sizeof where, "call %d", i);
        assert_radiance_valid(kept, "russian_roulette: beta", where);
        stats_acc_add(&acc[0], kept.r);
        stats_acc_add(&acc[1], kept.g);
        stats_acc_add(&acc[2], kept.b);
    }
    char what[96];
    snprintf(what, sizeof what, "mean throughput after roulette before bounce %d (red)", next_depth);
    assert_mean_matches(&acc[0], beta0.r, PART4_CHECK_ALPHA, what);
    assert_mean_matches(&acc[1], beta0.g, PART4_CHECK_ALPHA, what);
    assert_mean_matches(&acc[2], beta0.b, PART4_CHECK_ALPHA, what);
}
#define check_rule_keeps_mean(...) PL_AT(check_rule_keeps_mean(__VA_ARGS__))  /* failures name the calling test's line */

static void test_russian_roulette__compensates_the_paths_it_ends(void **state)
{
    (void)state;
    check_rule_keeps_mean(3, rgb_make(0.3f, 0.2f, 0.1f), SEED);
    check_rule_keeps_mean(8, rgb_make(0.05f, 0.4f, 0.02f), SEED + 1);
}

static void test_russian_roulette__ends_some_long_faint_paths(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED + 2, 0);
    int ended = 0;
    for (int i = 0; i < 1000; i++) {
        rgb beta = rgb_gray(0.05f);
        if (!russian_roulette(&beta, 20, &g))
            ended++;
        assert_implemented();
    }
    if (ended == 0) PL_FAIL("wrong: russian_roulette never ended a path of throughput 0.05 before bounce 20");
}

typedef struct { stats_acc acc[3]; uint64_t rays; } furnace_run;

static furnace_run run_furnace(bool roulette, uint64_t seed)
{
    furnace_run out;
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    assert_true(tiny_scene_furnace(&w->s, (float)RHO, (float)LE));
    w->o.max_depth = DEPTH;
    w->o.no_roulette = !roulette;
    w->o.hemisphere = true;  /* bounded variance: see test_furnace.c */
    assert_int_equal(PL_OK, tiny_world_finish(w));
    ray r = ray_make(vec3_make(0, 0, 0), vec3_normalize(vec3_make(-0.4f, 0.1f, -0.9f)), 0.0f, INFINITY);
    const char *name = roulette ? "furnace -m 12, roulette" : "furnace -m 12, no roulette";
    mc_print_seed(name, seed);
    (void)counters_take();
    mc_run_ray(&w->ctx, name, &r, seed, N, out.acc, __FILE__, __LINE__);
    out.rays = counters_take().rays;
    tiny_world_destroy(w);
    return out;
}

static void test_roulette__saves_work_without_changing_the_mean(void **state)
{
    (void)state;
    double expected = LE * (1 - pow(RHO, DEPTH + 1)) / (1 - RHO);
    furnace_run all = run_furnace(false, SEED + 3);
    furnace_run rr = run_furnace(true, SEED + 4);
    assert_mean_matches(&all.acc[0], expected, PART4_CHECK_ALPHA, "furnace -m 12 without roulette");
    assert_mean_matches(&rr.acc[0], expected, PART4_CHECK_ALPHA, "furnace -m 12 with roulette");
    /* Efficiency = 1 / (variance x rays): the noise a fixed time budget leaves. Printed, never
     * judged (every compensated rule is correct). In this furnace every vertex emits, so ending
     * paths costs more variance than elsewhere: the throughput rule of handout/part4.md 4.2 reaches
     * about 0.35 of no roulette's efficiency, a constant q = 0.65 about 0.33, a constant q = 0.3
     * about 0.08 (ten times the variance for an eighth of the rays). */
    double var_all = stats_acc_var(&all.acc[0]), var_rr = stats_acc_var(&rr.acc[0]);
    double efficiency = (var_all * (double)all.rays) / (var_rr * (double)rr.rays);
    print_message("rays: %llu without roulette, %llu with; variance %.4g without, %.4g with\n",
                  (unsigned long long)all.rays, (unsigned long long)rr.rays, var_all, var_rr);
    print_message("roulette efficiency, (variance x rays) without / with: %.2f (the throughput rule of "
                  "handout 4.2: about 0.35 here)%s\n", efficiency,
                  efficiency < 0.2 ? "\n  below 0.2: your rule ends paths that still carry much light; a constant low "
                                     "continue probability does, a throughput-based one ends the faint ones"
                                   : "");
    if (!(rr.rays < all.rays))
        PL_FAIL("wrong: roulette should end paths early: %llu rays with it, %llu without (does the path loop "
                "honour ctx->settings.roulette?)", (unsigned long long)rr.rays, (unsigned long long)all.rays);
}

int roulette_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_russian_roulette__compensates_the_paths_it_ends, test_setup),
        cmocka_unit_test_setup(test_russian_roulette__ends_some_long_faint_paths, test_setup),
        cmocka_unit_test_setup(test_roulette__saves_work_without_changing_the_mean, test_setup),
    };
    return cmocka_run_group_tests_name("part4: Russian roulette", tests, NULL, NULL);
}
