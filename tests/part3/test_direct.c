/* Test machinery: not part of any assignment.
 * Direct light on analytic scenes (tests/common/tiny_scenes.h):
 * - a diffuse floor under a uniform rectangular emitter: reflected radiance rho Le F, F the form
 *   factor in closed form; hemisphere sampling and light sampling must both agree with it;
 * - a point light over the floor: rho / pi * I cos / d^2 (inverse square law and cosine), exact;
 * - shadows, one-sided emission, and NaN/Inf/negative radiance as explicit failures.
 * alpha: each t test runs at PART3_CHECK_ALPHA (part3_alpha.h: Sidak share of the suite's 1e-3).
 * Seeds are fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part3_direct/part3.h"
#include "part3_alpha.h"
#include <stdlib.h>
#include <string.h>

#define SEED mc_seed(0x5eed3003ull)
#define N 40000
#define RHO 0.5f
#define LE 2.0f
#define HALF_X 1.0f
#define HALF_Z 0.6f
#define HEIGHT 1.2f

static int emitter_setup(void **state)
{
    test_setup(state);
    tiny_world *w = tiny_world_new();
    if (!w) return -1;
    if (!tiny_scene_emitter_over_plane(&w->s, RHO, LE, HALF_X, HALF_Z, HEIGHT) || tiny_world_finish(w) != PL_OK) {
        tiny_world_destroy(w);
        return -1;
    }
    *state = w;
    return 0;
}

static void check_direct(tiny_world *w, mc_estimator est, const char *name, int light_samples, float px, float pz,
                         uint64_t seed)
{
    w->o.light_samples = light_samples;
    tiny_world_refresh(w);
    ray r;
    hit h;
    assert_hit(tiny_floor_hit(&w->ctx, px, pz, &r, &h));
    mc_print_seed(name, seed);
    stats_acc acc[3];
    mc_run_at(&w->ctx, est, name, &r, &h, seed, N, acc, __FILE__, __LINE__);
    double expected = tiny_emitter_over_plane_direct(RHO, LE, HALF_X, HALF_Z, HEIGHT, px, pz);
    char what[160];
    snprintf(what, sizeof what, "%s (-l %d) at floor point (%g, 0, %g), expected rho Le F", name, light_samples, px, pz);
    assert_mean_matches(&acc[0], expected, PART3_CHECK_ALPHA, what);
}
#define check_direct(...) PL_AT(check_direct(__VA_ARGS__))  /* failures name the calling test's line */

static void test_zero_bounce__emitter_is_Le_from_the_front_only(void **state)
{
    tiny_world *w = *state;
    ray up = ray_make(vec3_make(0.1f, 0.3f, 0.2f), vec3_make(0, 1, 0), 0.0f, INFINITY);
    hit h;
    assert_hit(render_intersect(&w->ctx, &up, &h));
    rgb L = zero_bounce_radiance(&w->ctx, &up, &h);
    assert_implemented();
    assert_rgb_near(rgb_gray(LE), L, 0.0f);
    ray down = ray_make(vec3_make(0.1f, 3.0f, 0.2f), vec3_make(0, -1, 0), 0.0f, INFINITY);
    assert_hit(render_intersect(&w->ctx, &down, &h));
    assert_rgb_near(rgb_gray(0.0f), zero_bounce_radiance(&w->ctx, &down, &h), 0.0f);
}

static void test_zero_bounce__diffuse_floor_is_black(void **state)
{
    tiny_world *w = *state;
    ray r;
    hit h;
    assert_hit(tiny_floor_hit(&w->ctx, 3.0f, 1.0f, &r, &h));
    rgb L = zero_bounce_radiance(&w->ctx, &r, &h);
    assert_implemented();
    assert_rgb_near(rgb_gray(0.0f), L, 0.0f);
}

static void test_direct_importance__matches_form_factor_under_the_emitter(void **state)
{
    check_direct(*state, direct_importance, "direct_importance", 1, 0.0f, 0.0f, SEED + 1);
}

static void test_direct_importance__matches_form_factor_beside_the_emitter(void **state)
{
    check_direct(*state, direct_importance, "direct_importance", 1, 1.6f, -0.9f, SEED + 2);
}

static void test_direct_importance__several_light_samples_agree(void **state)
{
    check_direct(*state, direct_importance, "direct_importance", 4, 0.4f, 0.3f, SEED + 3);
}

static void test_direct_hemisphere__matches_form_factor_under_the_emitter(void **state)
{
    check_direct(*state, direct_hemisphere, "direct_hemisphere", 1, 0.0f, 0.0f, SEED + 4);
}

static void test_direct_hemisphere__matches_form_factor_beside_the_emitter(void **state)
{
    check_direct(*state, direct_hemisphere, "direct_hemisphere", 2, 1.6f, -0.9f, SEED + 5);
}

/* ---- two lights of different sizes and radiance: the estimate is the sum of both -------------- */
/* Emitter k over the floor: centre (cx, height, cz), half sides, radiance. A large dim light and a
 * small bright one, so that an estimator that averages over the lights instead of summing them, or
 * that splits its samples between them and divides by the light samples only, misses the sum. */
static const struct { float cx, cz, half_x, half_z, height, Le; } two_lights[2] = {
    {-1.0f, 0.0f, 0.8f, 0.5f, 1.2f, 2.0f},
    {1.2f, 0.3f, 0.2f, 0.15f, 1.0f, 12.0f},
};

static void check_two_lights(mc_estimator est, const char *name, int light_samples, float px, float pz, uint64_t seed)
{
    tiny_world w;
    tiny_world_begin(&w);
    int floor_mat = scene_add_material(&w.s, material_make(rgb_gray(RHO), rgb_gray(0.0f)));
    vec3 up = vec3_make(0, 1, 0);
    assert_true(floor_mat >= 0 && tiny_add_quad(&w.s, vec3_make(0, 0, 0), vec3_make(40, 0, 0), vec3_make(0, 0, 40), up,
                                                floor_mat));
    double expected = 0.0;
    for (int k = 0; k < 2; k++) {
        assert_true(tiny_add_emitter(&w.s, vec3_make(two_lights[k].cx, two_lights[k].height, two_lights[k].cz),
                                     vec3_make(2 * two_lights[k].half_x, 0, 0), vec3_make(0, 0, 2 * two_lights[k].half_z),
                                     vec3_neg(up), rgb_gray(two_lights[k].Le)));
        expected += tiny_emitter_over_plane_direct(RHO, two_lights[k].Le, two_lights[k].half_x, two_lights[k].half_z,
                                                   two_lights[k].height, px - two_lights[k].cx, pz - two_lights[k].cz);
    }
    assert_int_equal(PL_OK, tiny_world_finish(&w));
    w.o.light_samples = light_samples;
    tiny_world_refresh(&w);
    ray r;
    hit h;
    assert_hit(tiny_floor_hit(&w.ctx, px, pz, &r, &h));
    mc_print_seed(name, seed);
    stats_acc acc[3];
    mc_run_at(&w.ctx, est, name, &r, &h, seed, N, acc, __FILE__, __LINE__);
    tiny_world_free(&w);
    char what[200];
    snprintf(what, sizeof what, "%s (-l %d) at floor point (%g, 0, %g) under two lights of different sizes, expected the "
             "sum of rho Le F over both", name, light_samples, px, pz);
    assert_mean_matches(&acc[0], expected, PART3_CHECK_ALPHA, what);
}
#define check_two_lights(...) PL_AT(check_two_lights(__VA_ARGS__))  /* failures name the calling test's line */

static void test_direct_importance__two_lights_of_different_sizes_add_up(void **state)
{
    (void)state;
    check_two_lights(direct_importance, "direct_importance", 3, 0.3f, 0.1f, SEED + 9);
}

static void test_direct_hemisphere__two_lights_of_different_sizes_add_up(void **state)
{
    (void)state;
    check_two_lights(direct_hemisphere, "direct_hemisphere", 2, 0.3f, 0.1f, SEED + 10);
}

/* An opaque quad between the floor point and the whole emitter: both estimators must see nothing. */
static void test_direct__occluder_casts_a_full_shadow(void **state)
{
    tiny_world *w = *state;
    tiny_world_free(w);
    tiny_world_begin(w);
    assert_true(tiny_scene_emitter_over_plane(&w->s, RHO, LE, HALF_X, HALF_Z, HEIGHT));
    int mat = scene_add_material(&w->s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_true(tiny_add_quad(&w->s, vec3_make(0, 0.8f, 0), vec3_make(8, 0, 0), vec3_make(0, 0, 8), vec3_make(0, 1, 0), mat));
    assert_int_equal(PL_OK, tiny_world_finish(w));
    ray r;
    hit h;
    r = ray_make(vec3_make(0.2f, 0.5f, 0.1f), vec3_make(0, -1, 0), 0.0f, INFINITY);
    assert_hit(render_intersect(&w->ctx, &r, &h));
    stats_acc acc[3];
    run_estimator(&w->ctx, direct_importance, &r, &h, SEED + 6, 2000, acc);
    assert_float_near(0.0, acc[0].mean, 0.0);
    run_estimator(&w->ctx, direct_hemisphere, &r, &h, SEED + 7, 2000, acc);
    assert_float_near(0.0, acc[0].mean, 0.0);
}

/* ---- point light: exact, since a delta light needs one sample ------------------------------- */
static void check_point(const float *att, float px, float pz)
{
    tiny_world w;
    tiny_world_begin(&w);
    assert_true(tiny_scene_point_over_plane(&w.s, RHO, 5.0f, 1.5f, att));
    assert_int_equal(PL_OK, tiny_world_finish(&w));
    ray r;
    hit h;
    assert_hit(tiny_floor_hit(&w.ctx, px, pz, &r, &h));
    stats_acc acc[3];
    run_estimator(&w.ctx, direct_importance, &r, &h, SEED + 8, 16, acc);
    double expected = tiny_point_over_plane_direct(RHO, 5.0, 1.5, att, px, pz);
    tiny_world_free(&w);
    assert_float_near(expected, acc[0].mean, 1e-4 * expected);
}
#define check_point(...) PL_AT(check_point(__VA_ARGS__))  /* failures name the calling test's line */

static void test_direct_importance__point_light_follows_inverse_square_and_cosine(void **state)
{
    (void)state;
    check_point(NULL, 0.0f, 0.0f);
    check_point(NULL, 2.0f, 1.0f);
    check_point(NULL, -0.5f, 3.0f);
}

static void test_direct_importance__point_light_applies_attenuation(void **state)
{
    (void)state;
    const float att[3] = {0.5f, 0.2f, 0.1f};
    check_point(att, 1.0f, -1.0f);
}

int direct_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_zero_bounce__emitter_is_Le_from_the_front_only, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_zero_bounce__diffuse_floor_is_black, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct_importance__matches_form_factor_under_the_emitter, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct_importance__matches_form_factor_beside_the_emitter, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct_importance__several_light_samples_agree, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct_hemisphere__matches_form_factor_under_the_emitter, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct_hemisphere__matches_form_factor_beside_the_emitter, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup_teardown(test_direct__occluder_casts_a_full_shadow, emitter_setup, tiny_world_teardown),
        cmocka_unit_test_setup(test_direct_importance__two_lights_of_different_sizes_add_up, test_setup),
        cmocka_unit_test_setup(test_direct_hemisphere__two_lights_of_different_sizes_add_up, test_setup),
        cmocka_unit_test_setup(test_direct_importance__point_light_follows_inverse_square_and_cosine, test_setup),
        cmocka_unit_test_setup(test_direct_importance__point_light_applies_attenuation, test_setup),
    };
    return cmocka_run_group_tests_name("part3: direct light on analytic scenes", tests, NULL, NULL);
}
