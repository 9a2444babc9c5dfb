/* Test machinery: not part of any assignment.
 * Part 9 in the framework's pixel loop (render_pixel with a lens radius above 0), on the stripes
 * scene (tests/common/tiny_scenes.h): an emissive wall at distance 1, its right half in stripes a
 * quarter of a pixel wide, rendered with emission only (-m 0), so every sample's colour is the
 * colour of the wall point its ray hits. The closed form: the wall on the plane of focus (D = 1) is
 * sharp, so each lens sample hits the point its pinhole sample hits, whatever the lens point, and
 * the image is the pinhole image of the same seed (the loop draws the pixel position first, then
 * the lens point). With the plane of focus elsewhere (D = 0.5) a lens of radius 0.2 spreads each
 * film point over a disc of radius 0.2 on the wall, thirteen stripes wide: most striped pixels
 * change. No statistics: a sample differs from its pinhole twin only if rounding carries its hit
 * across a stripe's edge (about 1e-5 of them; 1 pixel in 100 is allowed), and an out-of-focus
 * pixel keeps its pinhole value only when its count of red samples happens to be the same
 * (about 1 in 7; half the pixels are allowed). */
#include <stdio.h>
#include <stdlib.h>
#include "../common/test.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part9_lens/part9.h"

#define W 32
#define H 8
#define SPP 16

/* The stripes rendered at seed 7 through a lens of this radius and focal distance (0: a pinhole),
 * pixel means into out[W * H]. */
static void render_stripes(float radius, float focal_distance, rgb *out)
{
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    assert_true(tiny_scene_stripes(&w->s));
    w->o.width = W;
    w->o.height = H;
    w->o.max_depth = 0;
    w->o.spp = SPP;
    w->o.seed = 7;
    w->o.lens_radius = radius;
    w->o.lens_radius_given = true;
    w->o.focal_distance = focal_distance;
    w->o.focal_distance_given = true;
    assert_int_equal(PL_OK, tiny_world_finish(w));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            film_pixel p = {0};
            render_pixel(&w->ctx, x, y, &p);
            assert_implemented();
            out[y * W + x] = film_pixel_rgb(&p);
        }
    tiny_world_destroy(w);
}

static bool same_rgb(rgb a, rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

static void test_render__the_plane_of_focus_is_sharp(void **state)
{
    (void)state;
    static rgb pinhole[W * H], lens[W * H];
    render_stripes(0.0f, 1.0f, pinhole);
    render_stripes(0.2f, 1.0f, lens);
    int differ = 0, first = -1;
    for (int i = 0; i < W * H; i++)
        if (!same_rgb(pinhole[i], lens[i])) {
            differ++;
            if (first < 0) first = i;
        }
    if (differ > W * H / 100)
        PL_FAIL("wrong: the stripes on the plane of focus (D = 1) come out blurred through a lens of radius 0.2: %d of "
                "%d pixels differ from the pinhole render of the same seed, pixel (%d, %d) first, (%g, %g, %g) against "
                "(%g, %g, %g). Every lens ray of a film point must pass through the pinhole ray's point on the plane "
                "of focus (handout/part9.md, 9.2)", differ, W * H, first % W, first / W, (double)lens[first].r,
                (double)lens[first].g, (double)lens[first].b, (double)pinhole[first].r, (double)pinhole[first].g,
                (double)pinhole[first].b);
}

static void test_render__off_the_plane_of_focus_is_blurred(void **state)
{
    (void)state;
    static rgb pinhole[W * H], lens[W * H];
    render_stripes(0.0f, 0.5f, pinhole);
    render_stripes(0.2f, 0.5f, lens);
    int striped = 0, same = 0;
    for (int y = 0; y < H; y++)
        for (int x = W / 2; x < W; x++) {  /* the right half: the stripes */
            striped++;
            same += same_rgb(pinhole[y * W + x], lens[y * W + x]);
        }
    if (same > striped / 2)
        PL_FAIL("wrong: through a lens of radius 0.2 focused at 0.5, the stripes at distance 1 look as the pinhole sees "
                "them: %d of %d striped pixels are unchanged. A lens point off the centre must move the ray's origin "
                "(handout/part9.md, 9.2)", same, striped);
}

int render_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_render__the_plane_of_focus_is_sharp, test_setup),
        cmocka_unit_test_setup(test_render__off_the_plane_of_focus_is_blurred, test_setup),
    };
    return cmocka_run_group_tests_name("part9: thin_lens_ray in the pixel loop (task 9.2)", tests, NULL, NULL);
}
