/* Test machinery: not part of any assignment.
 * Part 6 in the renderer: what the framework does with a delta BSDF (it lights a mirror or glass
 * vertex by following the BSDF's sample, framework/render.c), on two scenes whose answers are known
 * on paper.
 * - A mirror tilted 45 degrees sends the camera ray sideways onto an emitter (which reflects
 *   nothing): the pixel is reflectance x Le exactly, at -m 1 (the light seen in a mirror is bounce
 *   1) and at -m 4 (counted once, not again when the path's next vertex lands on the emitter).
 * - A glass sphere on the axis between the camera and an emitter: the central ray crosses it
 *   without bending, so at -m 2 the pixel is (1 - R0)^2 T^2 Le (in, then out; the radiance scales of
 *   the two crossings cancel whatever their convention), by a t test.
 * alpha: one statistical check (the t test), at PART6_CHECK_ALPHA (part6_alpha.h). Seeds are fixed,
 * printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <math.h>
#include "../common/test.h"
#include "../common/tiny_scenes.h"
#include "../common/mc_assert.h"
#include "part6_alpha.h"
#include "../../parts/part6_specular/part6.h"

#define SEED mc_seed(0x5eed6002ull)

static const rgb LE = {2.0f, 3.0f, 4.0f};

/* The mirror: a 1 x 1 quad at (0, 0, -1) facing (1, 0, 1), reflecting the ray down -z onto +x,
 * where a 2 x 2 emitter at x = 2 faces back. */
static tiny_world *mirror_world(int max_depth, rgb reflectance)
{
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    material mirror = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    mirror.kind = MATERIAL_MIRROR;
    mirror.reflectance = reflectance;
    int mm = scene_add_material(&w->s, mirror);
    vec3 n = vec3_normalize(vec3_make(1, 0, 1));
    assert_true(tiny_add_quad(&w->s, vec3_make(0, 0, -1), vec3_make(0, 1, 0), vec3_cross(vec3_make(0, 1, 0), n), n, mm));
    assert_true(tiny_add_emitter(&w->s, vec3_make(2, 0, -1), vec3_make(0, 2, 0), vec3_make(0, 0, 2), vec3_make(-1, 0, 0), LE));
    w->o.max_depth = max_depth;
    assert_int_equal(PL_OK, tiny_world_finish(w));
    return w;
}

static void test_render__a_mirror_shows_the_light_once(void **state)
{
    (void)state;
    const rgb R = {0.9f, 0.5f, 0.25f};
    const int depths[] = {1, 4};
    for (int k = 0; k < 2; k++) {
        tiny_world *w = mirror_world(depths[k], R);
        ray r = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
        stats_acc acc[3];
        run_radiance(&w->ctx, &r, SEED, 64, acc);
        assert_implemented();
        double want[3] = {R.r * LE.r, R.g * LE.g, R.b * LE.b};
        for (int c = 0; c < 3; c++)
            if (!(fabs(acc[c].mean - want[c]) <= 1e-4 * want[c]) || stats_acc_var(&acc[c]) > 1e-8)
                PL_FAIL("wrong: a mirror of reflectance (0.9, 0.5, 0.25) facing an emitter of radiance (2, 3, 4) shows "
                        "(%g, %g, %g) at -m %d, expected reflectance x Le = (%g, %g, %g) in every sample%s "
                        "(handout/part6.md, 6.2)", acc[0].mean, acc[1].mean, acc[2].mean, depths[k], want[0], want[1],
                        want[2], fabs(acc[0].mean - 2 * want[0]) < 1e-3 ? " (twice: the light is counted again)" : "");
        tiny_world_destroy(w);
    }
}

static void test_render__light_through_a_glass_sphere(void **state)
{
    (void)state;
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    material glass = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    glass.kind = MATERIAL_GLASS;
    glass.reflectance = rgb_gray(1.0f);
    glass.transmittance = rgb_make(0.9f, 0.8f, 0.7f);
    glass.ior = 1.5f;
    int gm = scene_add_material(&w->s, glass);
    assert_true(scene_add_sphere(&w->s, (sphere){vec3_make(0, 0, -3), 1.0f, gm}) >= 0);
    assert_true(tiny_add_emitter(&w->s, vec3_make(0, 0, -6), vec3_make(4, 0, 0), vec3_make(0, 4, 0), vec3_make(0, 0, 1), LE));
    w->o.max_depth = 2;
    w->o.no_roulette = true;
    assert_int_equal(PL_OK, tiny_world_finish(w));
    ray r = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
    uint64_t seed = SEED;
    mc_print_seed("glass sphere", seed);
    stats_acc acc[3];
    run_radiance(&w->ctx, &r, seed, 20000, acc);
    assert_implemented();
    double r0 = 0.04, t = 0.9, want = (1 - r0) * (1 - r0) * t * t * LE.r;
    char what[200];
    snprintf(what, sizeof what, "the light through a glass sphere at -m 2, red: (1 - R0)^2 T^2 Le with R0 = 0.04, T = 0.9, "
             "Le = 2 (handout/part6.md, 6.5)");
    assert_mean_matches(&acc[0], want, PART6_CHECK_ALPHA, what);
    tiny_world_destroy(w);
}

int render_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_render__a_mirror_shows_the_light_once, test_setup),
        cmocka_unit_test_setup(test_render__light_through_a_glass_sphere, test_setup),
    };
    return cmocka_run_group_tests_name("part6: mirror and glass in the renderer", tests, NULL, NULL);
}
