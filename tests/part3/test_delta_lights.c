/* Test machinery: not part of any assignment.
 * Delta lights (point, directional) at several light samples (-l): a delta light needs one sample,
 * and its contribution must not change with -l. A point light and a directional light over a
 * diffuse floor: rho / pi * E, with E = I cos / d^2 for the point and E = irradiance * cos for the
 * directional light, exact (no randomness reaches a delta light's sample), at -l 1, 4 and 16.
 * Caught: a delta light divided by the light-sample count, or summed over it without dividing.
 * A point or spot light inside a non-emissive quad at its own height (CS184's CBempty.dae) lights
 * the floor exactly as without the quad: the shadow ray (spawn_ray_to_light) stops short of it.
 * No statistics: no alpha. */
#include <stdio.h>
#include <string.h>
#include "../common/test.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part3_direct/part3.h"

#define SEED mc_seed(0x5eed3d17ull)
#define RHO 0.5f

/* direct_importance at floor point (px, 0, pz) of w at light_samples, over a few camera samples. */
static double direct_at(tiny_world *w, int light_samples, float px, float pz)
{
    w->o.light_samples = light_samples;
    tiny_world_refresh(w);
    ray r;
    hit h;
    assert_hit(tiny_floor_hit(&w->ctx, px, pz, &r, &h));
    stats_acc acc[3];
    run_estimator(&w->ctx, direct_importance, &r, &h, SEED, 8, acc);
    return acc[0].mean;
}

static void check_light_samples(tiny_world *w, double expected, const char *kind)
{
    static const int counts[] = {1, 4, 16};
    for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++) {
        double got = direct_at(w, counts[k], 0.7f, -0.4f);
        if (!(fabs(got - expected) <= 1e-4 * expected))
            fail_msg("wrong: a %s light at -l %d gives %.6g, expected %.6g (%.3g x): a delta light takes one sample "
                     "whatever -l says, and its result is not divided by -l", kind, counts[k], got, expected,
                     got / expected);
    }
}

static void test_delta_lights__point_light_ignores_light_samples(void **state)
{
    (void)state;
    tiny_world w;
    tiny_world_begin(&w);
    assert_true(tiny_scene_point_over_plane(&w.s, RHO, 5.0f, 1.5f, NULL));
    assert_int_equal(PL_OK, tiny_world_finish(&w));
    check_light_samples(&w, tiny_point_over_plane_direct(RHO, 5.0, 1.5, NULL, 0.7, -0.4), "point");
    tiny_world_free(&w);
}

static void test_delta_lights__directional_light_ignores_light_samples(void **state)
{
    (void)state;
    tiny_world w;
    tiny_world_begin(&w);
    assert_true(tiny_scene_point_over_plane(&w.s, RHO, 5.0f, 1.5f, NULL));
    /* The point light becomes a directional one travelling down and sideways: cos = 0.8. */
    w.s.lights[0].kind = LIGHT_DIRECTIONAL;
    w.s.lights[0].direction = vec3_make(0.6f, -0.8f, 0.0f);
    w.s.lights[0].radiance = rgb_gray(2.0f);
    assert_int_equal(PL_OK, tiny_world_finish(&w));
    check_light_samples(&w, RHO / 3.14159265358979323846 * 2.0 * 0.8, "directional");
    tiny_world_free(&w);
}

/* The light of tiny_scene_point_over_plane inside a non-emissive 0.6 x 0.6 m quad through it,
 * turned into a spot light pointing down (a 80 degree cone, no falloff inside) when spot is set:
 * the floor gets what it gets without the quad, at -l 1, at points under the quad and far off to
 * the side. Exact: no randomness reaches a delta light's sample. */
static void check_light_inside_quad(bool spot)
{
    tiny_world w;
    tiny_world_begin(&w);
    assert_true(tiny_scene_point_over_plane(&w.s, RHO, 5.0f, 1.5f, NULL));
    int grey = scene_add_material(&w.s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_true(grey >= 0 && tiny_add_quad(&w.s, vec3_make(0, 1.5f, 0), vec3_make(0.6f, 0, 0), vec3_make(0, 0, 0.6f),
                                           vec3_make(0, -1, 0), grey));
    if (spot) {
        w.s.lights[0].kind = LIGHT_SPOT;
        w.s.lights[0].direction = vec3_make(0, -1, 0);
        w.s.lights[0].falloff_deg = 80.0f;
        w.s.lights[0].falloff_exp = 0.0f;
    }
    assert_int_equal(PL_OK, tiny_world_finish(&w));
    static const float at[][2] = {{0.0f, 0.0f}, {0.7f, -0.4f}, {0.1f, 0.2f}, {3.0f, 1.0f}};
    for (size_t k = 0; k < sizeof at / sizeof at[0]; k++) {
        double expected = tiny_point_over_plane_direct(RHO, 5.0, 1.5, NULL, at[k][0], at[k][1]);
        double got = direct_at(&w, 1, at[k][0], at[k][1]);
        if (!(fabs(got - expected) <= 1e-4 * expected))
            fail_msg("wrong: a %s light inside a quad at its own height gives %.6g at floor point (%g, 0, %g), expected "
                     "%.6g as without the quad (%.3g x): its shadow ray must stop short of the light",
                     spot ? "spot" : "point", got, (double)at[k][0], (double)at[k][1], expected, got / expected);
    }
    tiny_world_free(&w);
}

static void test_delta_lights__point_light_inside_a_quad_lights_as_without_it(void **state)
{
    (void)state;
    check_light_inside_quad(false);
}

static void test_delta_lights__spot_light_inside_a_quad_lights_as_without_it(void **state)
{
    (void)state;
    check_light_inside_quad(true);
}

int delta_light_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_delta_lights__point_light_ignores_light_samples, test_setup),
        cmocka_unit_test_setup(test_delta_lights__directional_light_ignores_light_samples, test_setup),
        cmocka_unit_test_setup(test_delta_lights__point_light_inside_a_quad_lights_as_without_it, test_setup),
        cmocka_unit_test_setup(test_delta_lights__spot_light_inside_a_quad_lights_as_without_it, test_setup),
    };
    return cmocka_run_group_tests_name("part3: delta lights at several light samples", tests, NULL, NULL);
}
