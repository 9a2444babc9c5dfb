/* Test machinery: not part of any assignment.
 * Delta lights (point, directional) at several light samples (-l): a delta light needs one sample,
 * and its contribution must not change with -l. A point light and a directional light over a
 * diffuse floor: rho / pi * E, with E = I cos / d^2 for the point and E = irradiance * cos for the
 * directional light, exact (no randomness reaches a delta light's sample), at -l 1, 4 and 16.
 * Caught: a delta light divided by the light-sample count, or summed over it without dividing.
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

int delta_light_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_delta_lights__point_light_ignores_light_samples, test_setup),
        cmocka_unit_test_setup(test_delta_lights__directional_light_ignores_light_samples, test_setup),
    };
    return cmocka_run_group_tests_name("part3: delta lights at several light samples", tests, NULL, NULL);
}
