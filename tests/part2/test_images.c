/* Test machinery: not part of any assignment. Part 2 as the renderer uses it: normal-shaded images
 * through the BVH equal those through the linear scan, for every shipped scene. */
#include "../common/test.h"
#include "fixtures.h"
#include "../../framework/render.h"
#include <stdio.h>
#include <string.h>

#define IMAGE_WIDTH 160
#define IMAGE_HEIGHT 120
/* Pixels on an edge two triangles share may take either triangle's normal, which agree to
 * rounding; a wrong hit changes the colour by far more than this. */
#define SHARED_EDGE_TOL 1e-3f

static pl_status render_normals(const scene *s, bool use_bvh, image *out)
{
    options o = options_default();
    o.normals = true;
    o.threads = 2;
    o.width = IMAGE_WIDTH;
    o.height = IMAGE_HEIGHT;
    pl_diag diag = pl_diag_default();
    accel a;
    pl_status st = accel_build(&a, s, use_bvh, o.max_leaf_size, &diag);
    if (st != PL_OK) return st;
    if (use_bvh && !a.use_bvh) {
        accel_free(&a);
        return PL_ERR_TODO;  /* part 2 fell back to the linear scan: a stub ran */
    }
    render_ctx ctx;
    render_ctx_init(&ctx, s, &a, &o);
    render_stats stats;
    st = image_alloc(out, o.width, o.height);
    if (st == PL_OK) st = render_image(&ctx, out, NULL, &stats, &diag);
    accel_free(&a);
    return st;
}

static void test_bvh__normal_images_equal_the_linear_scan_on_shipped_scenes(void **state)
{
    char paths[FIXTURE_MAX_SCENES][512];
    int n = fixture_scene_paths(paths, FIXTURE_MAX_SCENES);
    if (n == 0) fail_msg("no scenes found under scenes/ (run the tests from the repository root)");
    for (int i = 0; i < n; i++) {
        scene s;
        fixture_load_scene(paths[i], &s);
        image with = {0}, without = {0};
        pl_status st = render_normals(&s, true, &with);
        assert_implemented();
        if (st != PL_OK) fail_msg("%s: rendering through the BVH failed: %s", paths[i], pl_status_name(st));
        st = render_normals(&s, false, &without);
        if (st != PL_OK) fail_msg("%s: rendering through the linear scan failed: %s", paths[i], pl_status_name(st));

        int differ = 0, first = -1;
        for (int p = 0; p < IMAGE_WIDTH * IMAGE_HEIGHT; p++) {
            rgb a = with.pixels[p], b = without.pixels[p];
            float d = fmaxf(fabsf(a.r - b.r), fmaxf(fabsf(a.g - b.g), fabsf(a.b - b.b)));
            if (!(d <= SHARED_EDGE_TOL) && differ++ == 0) first = p;
        }
        rgb a = first >= 0 ? with.pixels[first] : rgb_gray(0), b = first >= 0 ? without.pixels[first] : rgb_gray(0);
        image_free(&with);
        image_free(&without);
        scene_free(&s);
        if (differ)
            fail_msg("%s: %d of %d pixels differ; first at column %d, row %d from the top: BVH rgb(%g, %g, %g), "
                     "linear scan rgb(%g, %g, %g)", paths[i], differ, IMAGE_WIDTH * IMAGE_HEIGHT,
                     first % IMAGE_WIDTH, first / IMAGE_WIDTH, a.r, a.g, a.b, b.r, b.g, b.b);
    }
}

int images_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh__normal_images_equal_the_linear_scan_on_shipped_scenes, test_setup),
    };
    return cmocka_run_group_tests_name("part2: images with and without the BVH", tests, NULL, NULL);
}
