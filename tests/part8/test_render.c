/* Test machinery: not part of any assignment.
 * Part 8 in the framework's renders: light_add_environment makes -e's map a light that part 3's
 * light sampling reaches through light_sample_L, at infinity and not a delta light; and the closed
 * form of a diffuse floor (albedo rho) under a constant sky of radiance L: with direct light alone
 * (-m 1) it reflects rho L, by importance sampling (tasks 8.2-8.4) and by uniform sampling (task
 * 8.1, --env-uniform) alike. The floor is 40 x 40 m: from its centre it hides the lower half of the
 * sky and nothing of the upper.
 * alpha: two statistical checks (one t test of each render's mean), each at PART8_CHECK_ALPHA
 * (part8_alpha.h). Seeds are fixed, printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "../common/test.h"
#include "../common/tiny_scenes.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../../framework/light.h"
#include "part8_alpha.h"
#include "../../parts/part8_envlight/part8.h"

#define SEED mc_seed(0x5eed8002ull)
#define RHO 0.6f
#define SKY 0.8f

/* The floor of tiny_scene_point_over_plane without its point light, under a constant sky. */
static tiny_world *sky_world(bool uniform)
{
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    assert_true(tiny_scene_point_over_plane(&w->s, RHO, 1.0f, 1.0f, NULL));
    w->s.num_lights = 0;
    w->s.env = calloc(1, sizeof *w->s.env);
    assert_non_null(w->s.env);
    assert_int_equal(PL_OK, envmap_make_constant(w->s.env, 32, 16, rgb_gray(SKY)));
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, light_add_environment(&w->s, uniform, &d));
    w->o.max_depth = 1;
    w->o.env_uniform = uniform;
    assert_int_equal(PL_OK, tiny_world_finish(w));
    return w;
}

static void test_light_add_environment__a_light_at_infinity(void **state)
{
    (void)state;
    tiny_world *w = sky_world(false);
    assert_int_equal(1, w->s.num_lights);
    const light *l = &w->s.lights[0];
    assert_int_equal(LIGHT_ENVIRONMENT, l->kind);
    assert_false(light_is_delta(l));
    assert_non_null(l->env_dist);
    light_sample ls = {0};  /* zeroed: with part 8 stubbed, link-time optimisation cannot see it set */
    bool ok = light_sample_L(l, vec3_make(0, 0, 0), vec2_make(0.3f, 0.6f), &ls);
    assert_implemented();
    assert_true(ok);
    assert_true(isinf(ls.dist) && !ls.is_delta && ls.pdf > 0.0f);
    assert_true(fabsf(ls.L.r - SKY) < 1e-6f);
    tiny_world_destroy(w);
    w = sky_world(true);
    assert_null(w->s.lights[0].env_dist);  /* --env-uniform: no tables */
    tiny_world_destroy(w);
}

/* n radiance estimates of the camera ray that looks straight down at the floor's centre. */
static void check_floor(bool uniform, uint64_t seed, const char *what)
{
    tiny_world *w = sky_world(uniform);
    ray r = ray_make(vec3_make(0.1f, 1.0f, 0.2f), vec3_make(0, -1, 0), 0.0f, INFINITY);
    stats_acc acc[3];
    run_radiance(&w->ctx, &r, seed, 20000, acc);
    mc_print_seed(what, seed);
    assert_mean_matches(&acc[0], RHO * SKY, PART8_CHECK_ALPHA, what);
    tiny_world_destroy(w);
}

static void test_render__a_floor_under_a_constant_sky_reflects_rho_L(void **state)
{
    (void)state;
    check_floor(false, SEED + 1, "a floor of albedo 0.6 under a sky of 0.8, importance sampled (expected 0.48)");
}

static void test_render__the_same_floor_by_uniform_sampling(void **state)
{
    (void)state;
    check_floor(true, SEED + 2, "a floor of albedo 0.6 under a sky of 0.8, --env-uniform (expected 0.48)");
}

int render_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_light_add_environment__a_light_at_infinity),
        cmocka_unit_test(test_render__a_floor_under_a_constant_sky_reflects_rho_L),
        cmocka_unit_test(test_render__the_same_floor_by_uniform_sampling),
    };
    return cmocka_run_group_tests_name("part8: the environment map as a light in the renderer", tests, NULL, NULL);
}
