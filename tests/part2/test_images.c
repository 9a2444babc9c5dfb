/* Test machinery: not part of any assignment. Part 2 as the renderer uses it: normal-shaded images
 * through the BVH equal those through the linear scan, for every shipped scene. */
#include "../common/test.h"
#include "fixtures.h"
#include "../../framework/render.h"
#include "../../framework/heatmap.h"
#include "../../framework/procmesh.h"
#include <stdlib.h>
#include <unistd.h>
#include <stdio.h>
#include <string.h>

#define IMAGE_WIDTH 160
#define IMAGE_HEIGHT 120
/* Pixels on an edge two triangles share may take either triangle's normal, which agree to
 * rounding; a wrong hit changes the colour by far more than this. */
#define SHARED_EDGE_TOL 1e-3f

/* accel_build falls back to the linear scan when bvh_build is a stub, and takes the stub's report
 * back (the renderer still works). Part 2's own tests want the report: call the stub again. */
static void report_stubbed_build(const accel *a, const scene *s)
{
    if (a->use_bvh) return;
    bvh b;
    (void)bvh_build(&b, s, 4);
    bvh_free(&b);
}

/* Out: *diag says why, when it fails (the framework's reason: bvh_validate's rule for a bad tree). */
static pl_status render_normals(const scene *s, bool use_bvh, image *out, pl_diag *diag)
{
    options o = options_default();
    o.normals = true;
    o.threads = pl_test_threads(2);
    o.width = IMAGE_WIDTH;
    o.height = IMAGE_HEIGHT;
    *diag = pl_diag_default();
    accel a;
    pl_status st = accel_build(&a, s, use_bvh, o.max_leaf_size, diag);
    if (st != PL_OK) return st;
    if (use_bvh && !a.use_bvh) {
        report_stubbed_build(&a, s);
        accel_free(&a);
        return PL_ERR_TODO;  /* part 2 fell back to the linear scan: a stub ran */
    }
    render_ctx ctx;
    render_ctx_init(&ctx, s, &a, &o);
    render_stats stats;
    st = image_alloc(out, o.width, o.height);
    if (st == PL_OK) st = render_image(&ctx, out, NULL, &stats, diag);
    accel_free(&a);
    return st;
}

static void compare_images_of_scene(const scene *s, const char *path)
{
    image with = {0}, without = {0};
    pl_diag diag;
    pl_status st = render_normals(s, true, &with, &diag);
    assert_implemented();
    if (st != PL_OK) PL_FAIL("%s: rendering through the BVH failed: %s", path, diag.error[0] ? diag.error : pl_status_name(st));
    st = render_normals(s, false, &without, &diag);
    if (st != PL_OK)
        PL_FAIL("%s: rendering through the linear scan failed: %s", path, diag.error[0] ? diag.error : pl_status_name(st));

    int differ = 0, first = -1;
    for (int p = 0; p < IMAGE_WIDTH * IMAGE_HEIGHT; p++) {
        rgb a = with.pixels[p], b = without.pixels[p];
        float d = fmaxf(fabsf(a.r - b.r), fmaxf(fabsf(a.g - b.g), fabsf(a.b - b.b)));
        if (!(d <= SHARED_EDGE_TOL) && differ++ == 0) first = p;
    }
    rgb a = first >= 0 ? with.pixels[first] : rgb_gray(0), b = first >= 0 ? without.pixels[first] : rgb_gray(0);
    image_free(&with);
    image_free(&without);
    if (differ)
        PL_FAIL("%s: %d of %d pixels differ; first at x=%d y=%d (from the bottom-left, like the grader's pixels): "
                "BVH rgb(%g, %g, %g), linear scan rgb(%g, %g, %g)", path, differ, IMAGE_WIDTH * IMAGE_HEIGHT,
                first % IMAGE_WIDTH, IMAGE_HEIGHT - 1 - first / IMAGE_WIDTH, a.r, a.g, a.b, b.r, b.g, b.b);
}

static void test_bvh__normal_images_equal_the_linear_scan_on_shipped_scenes(void **state)
{
    PL_AT(fixture_for_each_scene(compare_images_of_scene));  /* failures name this line */
}

static void test_heatmap__colours_visits_and_adds_a_legend(void **state)
{
    scene s = {0};
    scene_add_material(&s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&s, procmesh_rows_for(2000), vec3_make(0, 0, 0), 1.0f, 0), PL_OK);
    options o = options_default();
    o.width = 64;
    o.height = 48;
    pl_diag diag = pl_diag_default();
    accel a;
    if (accel_build(&a, &s, true, o.max_leaf_size, &diag) != PL_OK)
        PL_FAIL("the heat map's scene: building the BVH failed: %s", diag.error);
    report_stubbed_build(&a, &s);
    assert_implemented();
    render_ctx ctx;
    render_ctx_init(&ctx, &s, &a, &o);
    /* In memory: the graded half of a split suite may write no file (grader/sandbox.h); the PNG
     * writer itself is the framework suite's to test. */
    heatmap map;
    pl_status st = heatmap_render(&ctx, "the heat map", &map, &diag);
    assert_implemented();
    if (st != PL_OK) fail_msg("heatmap_render failed: %s", diag.error);
    /* The picture, then the legend strip; a sphere in the middle of the frame is hotter than the
     * empty corner, where rays miss the root box (0 visits beyond it: the darkest blue). Rows run
     * from the top. */
    assert_true(map.width == 64 && map.height > 48);
    const uint8_t *corner = map.rgb8, *centre = map.rgb8 + 3 * (24 * 64 + 32);
    if (!(centre[0] + centre[1] > corner[0] + corner[1]))
        fail_msg("the centre (on the mesh) should be warmer than the corner: centre rgb8(%d, %d, %d), corner rgb8(%d, %d, %d)",
                 centre[0], centre[1], centre[2], corner[0], corner[1], corner[2]);
    heatmap_free(&map);
    accel_free(&a);

    /* Without the BVH there is nothing to count: a clear error, no picture. */
    assert_int_equal(accel_build(&a, &s, false, o.max_leaf_size, &diag), PL_OK);
    render_ctx_init(&ctx, &s, &a, &o);
    assert_int_equal(heatmap_render(&ctx, "the heat map", &map, &diag), PL_ERR_INVALID);
    assert_null(map.rgb8);
    accel_free(&a);
    scene_free(&s);
}

int images_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh__normal_images_equal_the_linear_scan_on_shipped_scenes, test_setup),
        cmocka_unit_test_setup(test_heatmap__colours_visits_and_adds_a_legend, test_setup),
    };
    return cmocka_run_group_tests_name("part2: images with and without the BVH, the heat map", tests, NULL, NULL);
}
