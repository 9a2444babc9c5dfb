/* Test machinery: not part of any assignment.
 * Where a scene sits in space does not change its image (framework/dae.c: positions are stored
 * relative to the scene's origin, the first camera's position, computed in double). The Cornell box
 * with spheres is wrapped in a node that scales it by s (its camera's clip range too) and moves it
 * by T, for s from 10^-3 to 10^3 and |T| up to 10^6, and rendered through the real binary at the same
 * seed as the untransformed file, with direct and global light (-m 3). Each 8x8 block and channel of
 * the two renders is compared by z = (sum a - sum b) / sqrt(var a + var b), the variances of the
 * means from each film: the renders share their random numbers, so the true spread of the
 * difference is smaller and the test is conservative. Each configuration is one check at
 * FRAMEWORK_CHECK_ALPHA (framework_alpha.h), Sidak-corrected over its blocks and channels.
 * Before the fix, the same box moved by 10^4 had shadows 3% dark (z -54) and moved by 10^6 lost its
 * geometry to float's 1/16 m steps. The trace reports positions in the file's coordinates. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../framework/exr.h"
#include "../../framework/file.h"
#include "../../framework/stats.h"
#include "framework_alpha.h"
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

SCRATCH_FOLDER(scratch, "placement")

#define RENDER "bin/pathtracer -q -t 2 -r 64 48 -s 32 -m 3 -l 1 --seed 11"
#define BLOCK 8

/* scenes/cornell_spheres.dae scaled by s and moved by T (in the file's own axes), into path. */
static void write_placed(const char *path, double s, double tx, double ty, double tz)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all("scenes/cornell_spheres.dae", "scene", 1 << 20, &text, &len, &d));
    const char *open = "<visual_scene id=\"Scene\" name=\"Scene\">", *close = "</visual_scene>";
    char *a = strstr(text, open), *b = strstr(text, close), *near = strstr(text, "<znear sid=\"znear\">0.1</znear>"),
         *far = strstr(text, "<zfar sid=\"zfar\">100</zfar>");
    assert_true(a && b && near && far && near < a && far < a);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    /* The clip range scales with the scene, or a box 2 mm wide would sit inside the near plane. */
    fprintf(f, "%.*s<znear sid=\"znear\">%.17g</znear>%.*s<zfar sid=\"zfar\">%.17g</zfar>", (int)(near - text), text,
            0.1 * s, (int)(far - near - strlen("<znear sid=\"znear\">0.1</znear>")),
            near + strlen("<znear sid=\"znear\">0.1</znear>"), 100 * s);
    const char *after_far = far + strlen("<zfar sid=\"zfar\">100</zfar>");
    fprintf(f, "%.*s\n<node id=\"Placed\" name=\"Placed\" type=\"NODE\"><matrix sid=\"transform\">%.17g 0 0 %.17g  0 %.17g 0 "
            "%.17g  0 0 %.17g %.17g  0 0 0 1</matrix>", (int)(a + strlen(open) - after_far), after_far, s, tx, s, ty, s, tz);
    fprintf(f, "%.*s</node>\n%s", (int)(b - (a + strlen(open))), a + strlen(open), b);
    assert_int_equal(0, fclose(f));
    free(text);
}

static void render(const char *scene, const char *exr)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, RENDER " -f %s %s >/dev/null 2>&1", exr, scene);
    if (system(cmd) != 0) fail_msg("this render failed: %s", cmd);
}

/* The smallest p of the blocks' z tests between the films a and b, Sidak-corrected over them. */
static double placement_p(const char *a_path, const char *b_path, double *worst_z)
{
    film a = {0}, b = {0};
    exr_info ia, ib;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, exr_read(a_path, &a, &ia, &d));
    assert_int_equal(PL_OK, exr_read(b_path, &b, &ib, &d));
    assert_int_equal(a.width, b.width);
    assert_int_equal(a.height, b.height);
    double p_min = 1.0;
    int tests = 0;
    *worst_z = 0.0;
    for (int by = 0; by < a.height; by += BLOCK)
        for (int bx = 0; bx < a.width; bx += BLOCK)
            for (int ch = 0; ch < 3; ch++) {
                double diff = 0.0, var = 0.0;
                for (int y = by; y < by + BLOCK && y < a.height; y++)
                    for (int x = bx; x < bx + BLOCK && x < a.width; x++) {
                        const film_pixel *pa = &a.pixels[y * a.width + x], *pb = &b.pixels[y * b.width + x];
                        diff += film_pixel_mean(pa, ch) - film_pixel_mean(pb, ch);
                        var += film_pixel_variance_of_mean(pa, ch) + film_pixel_variance_of_mean(pb, ch);
                    }
                tests++;
                /* A black block in both renders holds nothing to compare. */
                double z = var > 0.0 ? diff / sqrt(var) : (fabs(diff) > 1e-6 ? INFINITY : 0.0);
                double p = erfc(fabs(z) / sqrt(2.0));
                if (p < p_min) p_min = p, *worst_z = z;
            }
    film_free(&a);
    film_free(&b);
    return 1.0 - pow(1.0 - p_min, tests);
}

static void check_placed(double s, double tx, double ty, double tz)
{
    char scene[512], base[512], placed[512];
    snprintf(base, sizeof base, "%s/base.exr", scratch);
    snprintf(scene, sizeof scene, "%s/placed.dae", scratch);
    snprintf(placed, sizeof placed, "%s/placed.exr", scratch);
    render("scenes/cornell_spheres.dae", base);
    write_placed(scene, s, tx, ty, tz);
    render(scene, placed);
    double z, p = placement_p(base, placed, &z);
    if (p < FRAMEWORK_CHECK_ALPHA)
        fail_msg("the Cornell box scaled by %g and moved by (%g, %g, %g) renders differently from where it was: a block "
                 "differs at z = %+.3g (Sidak p = %.3g < alpha = %.3g)", s, tx, ty, tz, z, p, FRAMEWORK_CHECK_ALPHA);
}
#define check_placed(...) PL_AT(check_placed(__VA_ARGS__))

static void test_placement__a_box_moved_by_up_to_a_million_renders_the_same(void **state)
{
    (void)state;
    check_placed(1, 1e6, -1e6, 1e6);
    check_placed(1, 1e4, -1e4, 1e4);
    check_placed(1, -1e3, 0, 2e3);
    check_placed(1, 500, 500, 500);  /* within a km: the file's own coordinates are kept */
}

static void test_placement__a_box_scaled_and_moved_renders_the_same(void **state)
{
    (void)state;
    check_placed(1e-3, 1e6, 1e6, -1e6);
    check_placed(1e3, -1e6, 1e6, 1e6);
    check_placed(1e-2, 1e4, 1e4, 1e4);
    check_placed(1e-3, 10, -10, 10);
}

/* --trace-pixel reports positions in the file's coordinates: the camera ray of the box moved by
 * (1e6, -1e6, 1e6) (file axes, Z up: world (-1e6, 1e6, -1e6)) starts at the camera, (0, 0.75, 3.1) moved. */
static void test_placement__the_trace_speaks_in_the_files_coordinates(void **state)
{
    (void)state;
    char scene[512], cmd[1024];
    snprintf(scene, sizeof scene, "%s/placed.dae", scratch);
    write_placed(scene, 1, 1e6, -1e6, 1e6);
    snprintf(cmd, sizeof cmd, "bin/pathtracer -q -r 64 48 -s 1 -m 1 --trace-pixel 32 24 --trace-format json %s", scene);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    json_error_t err;
    json_t *doc = json_loadf(p, 0, &err);
    pclose(p);
    if (!doc) fail_msg("the trace is not JSON: %s", err.text);
    json_t *events = json_object_get(json_array_get(json_object_get(doc, "samples"), 0), "events"), *origin = NULL;
    for (size_t i = 0; i < json_array_size(events) && !origin; i++) {
        const char *kind = json_string_value(json_object_get(json_array_get(events, i), "kind"));
        if (kind && !strcmp(kind, "camera_ray")) origin = json_object_get(json_array_get(events, i), "origin");
    }
    if (!json_is_array(origin)) fail_msg("the trace has no camera ray with an origin");
    double want[3] = {-1e6, 1e6 + 0.75, -1e6 + 3.1};
    for (int i = 0; i < 3; i++) assert_float_equal(want[i], json_number_value(json_array_get(origin, i)), 1e-3);
    json_decref(doc);
}

int placement_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_placement__a_box_moved_by_up_to_a_million_renders_the_same),
        cmocka_unit_test(test_placement__a_box_scaled_and_moved_renders_the_same),
        cmocka_unit_test(test_placement__the_trace_speaks_in_the_files_coordinates),
    };
    return cmocka_run_group_tests_name("placement", tests, scratch_setup, scratch_teardown);
}
