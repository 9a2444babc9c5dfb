/* Test machinery: not part of any assignment.
 * Rays leave the surface they start on (framework/spawn.h): a hit point is off the exact surface
 * by up to its error bound h->p_err, on either side, and a shadow or hemisphere ray started at
 * that raw point hits its own surface (shadow acne). Each test takes a sphere far from the origin
 * (where floats are coarse), puts the hit point half its error bound inside the sphere, as part 1
 * and the framework may, and lights it from outside: the light must arrive.
 * - a directional light at 60 degrees: exactly rho / pi * E * cos 60 (one sample, no noise);
 * - an emitter over the sphere's top by hemisphere sampling: rho Le F (the tangent plane's form
 *   factor: the sphere hides nothing above it), a t test at PART3_CHECK_ALPHA (part3_alpha.h).
 * Seeds fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part3_direct/part3.h"
#include "part3_alpha.h"

#define SEED mc_seed(0x5eed3303ull)
#define RHO 0.5f
#define RADIUS 100.0f
#define FAR 4000.0f   /* the sphere's centre is at (FAR, FAR, FAR): a float step there is 2.4e-4 */

static const char *const why =
    "its rays hit the sphere they start on. The hit point is off the surface by up to h->p_err (here "
    "half of it, inside): leave the surface with spawn_ray / spawn_ray_to_light (framework/spawn.h), "
    "never from the raw hit point (handout/part3.md, 3.4)";

/* The sphere alone plus `light` (its kind decides the test), and the hit at its top seen from
 * above, pushed half its error bound into the sphere. */
static void sphere_world(tiny_world *w, ray *r, hit *h, bool with_emitter)
{
    tiny_world_begin(w);
    int mat = scene_add_material(&w->s, material_make(rgb_gray(RHO), rgb_gray(0.0f)));
    sphere sp = {vec3_make(0, 0, 0), RADIUS, mat};
    assert_true(mat >= 0 && scene_add_sphere(&w->s, sp) >= 0);
    if (with_emitter) {
        assert_true(tiny_add_emitter(&w->s, vec3_make(0, RADIUS + 1.0f, 0), vec3_make(2, 0, 0), vec3_make(0, 0, 1.2f),
                                     vec3_make(0, -1, 0), rgb_gray(2.0f)));
    } else {
        light l = {0};
        l.kind = LIGHT_DIRECTIONAL;
        l.radiance = rgb_gray(3.0f);  /* irradiance facing it */
        l.direction = vec3_neg(vec3_make(sinf(PL_PI / 3), cosf(PL_PI / 3), 0));  /* arrives 60 deg from the top's normal */
        assert_true(scene_add_light(&w->s, l) >= 0);
    }
    tiny_scene_translate(&w->s, vec3_make(FAR, FAR, FAR));
    assert_int_equal(PL_OK, tiny_world_finish(w));
    *r = ray_make(vec3_make(FAR, FAR + RADIUS + 0.5f, FAR), vec3_make(0, -1, 0), 0.0f, INFINITY);  /* below the emitter */
    assert_hit(render_intersect(&w->ctx, r, h));
    tiny_hit_push_behind(r, h, 0.5f);
}

static void test_direct_importance__shadow_rays_leave_the_surface(void **state)
{
    tiny_world w;
    ray r;
    hit h;
    sphere_world(&w, &r, &h, false);
    rng g = rng_seeded(SEED, 0);
    rgb L = direct_importance(&w.ctx, &r, &h, &g);
    tiny_world_free(&w);
    assert_implemented();
    double expected = RHO / PL_PI * 3.0 * 0.5;
    if (!(L.r > 0.0f)) {
        print_error("direct_importance gave %g at a sphere point lit at 60 degrees (expected %g): %s\n", L.r, expected, why);
        fail();
    }
    assert_float_near(expected, L.r, 1e-4 * expected);
}

static void test_direct_hemisphere__rays_leave_the_surface(void **state)
{
    tiny_world w;
    ray r;
    hit h;
    sphere_world(&w, &r, &h, true);
    uint64_t seed = SEED + 1;
    mc_print_seed("direct_hemisphere from inside the error bound", seed);
    stats_acc acc[3];
    run_estimator(&w.ctx, direct_hemisphere, &r, &h, seed, 20000, acc);
    tiny_world_free(&w);
    if (!(acc[0].mean > 0.0)) {
        print_error("direct_hemisphere saw no light from an emitter over a sphere's top: %s\n", why);
        fail();
    }
    double expected = tiny_emitter_over_plane_direct(RHO, 2.0, 1.0, 0.6, 1.0, 0.0, 0.0);
    assert_mean_matches(&acc[0], expected, PART3_CHECK_ALPHA, "direct_hemisphere under an emitter, from inside the error bound");
}

int leaving_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_direct_importance__shadow_rays_leave_the_surface, test_setup),
        cmocka_unit_test_setup(test_direct_hemisphere__rays_leave_the_surface, test_setup),
    };
    return cmocka_run_group_tests_name("part3: rays leave the surface they start on", tests, NULL, NULL);
}
