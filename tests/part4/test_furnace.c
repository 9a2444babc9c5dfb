/* Test machinery: not part of any assignment.
 * The furnace (tests/common/tiny_scenes.h): inside a closed box whose walls all have albedo rho
 * and emit Le, the radiance in every direction is known on paper:
 *   k-th bounce alone (-m k -o 0):       rho^k Le
 *   bounces 0..m (-m m -o 1):            Le (1 - rho^(m+1)) / (1 - rho)
 *   everything (-m 64):                  Le / (1 - rho)
 * Task 4.1's furnace runs with --no-rr (ctx->settings.roulette false): it judges the path loop alone, so a
 * roulette bug costs task 4.2's share, not 4.1's (test_roulette.c plays roulette in the furnace).
 * Each case is a t test on radiance_estimate from the centre of the box. Paths of two bounces or
 * more use hemisphere sampling (-H) for their direct light: sampling the box's area lights from a
 * vertex near an edge of the box has a 1/d^2 singularity (the light on the neighbouring face is
 * arbitrarily close), so that estimator's variance is unbounded and no t test of it holds its
 * alpha. Light sampling is t-tested where the shading point is fixed (the first hit, -m 1); part 3
 * tests it thoroughly. Any NaN, Inf or negative sample fails naming the sample.
 * alpha: each t test runs at PART4_CHECK_ALPHA (part4_alpha.h: Sidak share of the suite's 1e-3).
 * The cases set the options as the command line would and make the context from them
 * (tiny_world_refresh: render_ctx_init), which hands part 4 its settings (render.h).
 * Seeds fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part4_global/part4.h"
#include "part4_alpha.h"
#include <stdlib.h>

#define SEED mc_seed(0x5eed4001ull)
#define RHO 0.5
#define LE 1.0
#define N 20000

static int furnace_setup(void **state)
{
    test_setup(state);
    tiny_world *w = tiny_world_new();
    if (!w) return -1;
    if (!tiny_scene_furnace(&w->s, (float)RHO, (float)LE) || tiny_world_finish(w) != PL_OK) {
        tiny_world_destroy(w);
        return -1;
    }
    *state = w;
    return 0;
}

static void check_furnace(tiny_world *w, int max_depth, bool accumulate, bool hemisphere, double expected,
                          uint64_t seed, const char *what)
{
    w->o.max_depth = max_depth;
    w->o.accumulate = accumulate;
    w->o.hemisphere = hemisphere;
    w->o.light_samples = 1;
    w->o.no_roulette = true;
    tiny_world_refresh(w);
    /* An oblique ray from the centre: any direction sees the same radiance. */
    ray r = ray_make(vec3_make(0, 0, 0), vec3_normalize(vec3_make(0.3f, -0.5f, 0.8f)), 0.0f, INFINITY);
    char name[160];
    snprintf(name, sizeof name, "%s (-m %d -o %d%s --no-rr)", what, max_depth, accumulate ? 1 : 0, hemisphere ? " -H" : "");
    mc_print_seed(name, seed);
    stats_acc acc[3];
    mc_run_ray(&w->ctx, name, &r, seed, N, acc, __FILE__, __LINE__);
    assert_mean_matches(&acc[0], expected, PART4_CHECK_ALPHA, name);
}
#define check_furnace(...) PL_AT(check_furnace(__VA_ARGS__))  /* failures name the calling test's line */

static void test_furnace__kth_bounce_alone_is_rho_to_the_k(void **state)
{
    for (int k = 2; k <= 4; k++)
        check_furnace(*state, k, false, true, pow(RHO, k) * LE, SEED + (uint64_t)k, "k-th bounce only");
}

static void test_furnace__bounces_up_to_m_sum_a_geometric_series(void **state)
{
    for (int m = 2; m <= 3; m++)
        check_furnace(*state, m, true, true, LE * (1 - pow(RHO, m + 1)) / (1 - RHO), SEED + 20 + (uint64_t)m,
                      "bounces 0..m");
}

static void test_furnace__deep_paths_converge_to_le_over_one_minus_rho(void **state)
{
    /* rho^65 is far below any noise: -m 64 is the full solution. */
    check_furnace(*state, 64, true, true, LE / (1 - RHO), SEED + 30, "full solution");
}

/* Bounce rays leave the surface they start on (framework/spawn.h). The furnace far from the
 * origin, where floats are coarse; the first hit (on the floor) pushed half its error bound out of
 * the box, as part 1 and the framework may give it. The second bounce alone is still rho^2 Le; a
 * bounce ray from the raw hit point hits the floor it starts on, from outside, and sees nothing. */
static void test_furnace__bounce_rays_leave_the_surface(void **state)
{
    tiny_world *w = *state;
    const float far = 4000.0f;  /* a float step there is 2.4e-4 */
    tiny_scene_translate(&w->s, vec3_make(far, far, far));
    w->o.max_depth = 2, w->o.accumulate = false, w->o.hemisphere = true, w->o.light_samples = 1, w->o.no_roulette = true;
    accel_free(&w->a);  /* made again for the moved box */
    assert_int_equal(PL_OK, tiny_world_finish(w));
    ray r = ray_make(vec3_make(far, far, far), vec3_normalize(vec3_make(0.3f, -1.0f, 0.2f)), 0.0f, INFINITY);
    hit h;
    assert_hit(render_intersect(&w->ctx, &r, &h));
    tiny_hit_push_behind(&r, &h, 0.5f);
    uint64_t seed = SEED + 40;
    const char *what = "second bounce alone from a hit point just outside the floor (-m 2 -o 0 -H)";
    mc_print_seed(what, seed);
    stats_acc acc[3];
    run_estimator(&w->ctx, at_least_one_bounce_radiance, &r, &h, seed, N, acc);
    assert_implemented();
    if (!(acc[0].mean > 0.0)) {
        print_error("%s: no light at all: the bounce rays hit the floor they start on. The hit point is off the "
                    "surface by up to h->p_err (here half of it, outside the box): spawn bounce rays with spawn_ray "
                    "(framework/spawn.h), never from the raw hit point (handout/part4.md, 4.1)\n", what);
        fail();
    }
    assert_mean_matches(&acc[0], RHO * RHO * LE, PART4_CHECK_ALPHA, what);
}

/* -m 0 (emission) and -m 1 (direct light) never reach part 4: part 3's suite tests them. A test of
 * them here would pass with part 4 stubbed, and give a stub points. */

int furnace_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_furnace__kth_bounce_alone_is_rho_to_the_k, furnace_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_furnace__bounces_up_to_m_sum_a_geometric_series, furnace_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_furnace__deep_paths_converge_to_le_over_one_minus_rho, furnace_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_furnace__bounce_rays_leave_the_surface, furnace_setup, tiny_world_teardown),
    };
    return cmocka_run_group_tests_name("part4: the furnace", tests, NULL, NULL);
}
