/* Test machinery: not part of any assignment. The camera module (framework/camera.h): the fov rule,
 * the default framing, and which lens a render uses. */
#include "../common/test.h"
#include "../../framework/camera.h"
#include "../../framework/camera_file.h"
#include "../../framework/cli.h"
#include "../../framework/scene.h"
#include <stdio.h>
#include <stdlib.h>

static void test_camera_set_aspect__the_free_fov_follows_the_fixed_one(void **state)
{
    (void)state;
    /* A 90 degree horizontal fov spans tan 45 = 1; at aspect 2 the height spans 1/2. */
    camera c = {0};
    c.hfov = 90.0f;
    camera_set_aspect(&c, 2.0f);
    assert_float_near(90.0, c.hfov, 0);
    assert_float_near(2.0 * atan(0.5) * 180.0 / M_PI, c.vfov, 1e-4);
    /* fov_is_vertical: the vertical one stays, the horizontal one follows. */
    c.fov_is_vertical = true;
    c.vfov = 90.0f;
    camera_set_aspect(&c, 2.0f);
    assert_float_near(90.0, c.vfov, 0);
    assert_float_near(2.0 * atan(2.0) * 180.0 / M_PI, c.hfov, 1e-4);
}

static void test_camera_default_framing__looks_at_the_centre_from_plus_z(void **state)
{
    (void)state;
    aabb b = {vec3_make(1, 2, 3), vec3_make(3, 4, 5)};
    camera c = camera_default_framing(b);
    assert_vec3_near(vec3_make(2, 3, 4 + 1.5f * sqrtf(12.0f)), c.position, 1e-5f);
    assert_vec3_near(vec3_make(0, 0, -1), mat4_dir(c.camera_to_world, vec3_make(0, 0, -1)), 1e-6f);
    assert_vec3_near(c.position, mat4_point(c.camera_to_world, vec3_make(0, 0, 0)), 0);
    assert_float_near(CAMERA_DEFAULT_FOCAL_DISTANCE, c.focal_distance, 0);
}

/* A -c settings file's lens survives into the render unless -b / -d replace it. */
static void test_camera_for_render__keeps_the_settings_files_lens_unless_flags_are_given(void **state)
{
    (void)state;
    char path[] = "/tmp/pathlab-camera-lens-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs("50 40 1.333 0.1 100\n0 0 3  0 0 0\n0 0 3 0.1 10\n1 0 0 0 1 0 0 0 1\n800 600 1\n3.9 0.07\n", f);
    fclose(f);
    scene s = {0};
    pl_diag d = pl_diag_default();
    pl_status st = camera_file_load(path, &s.camera, &d);
    remove(path);
    assert_int_equal(PL_OK, st);
    s.has_camera = true;

    options o = options_default();
    camera c = camera_for_render(&s, &o);
    assert_float_near(0.07f, c.lens_radius, 0);
    assert_float_near(3.9f, c.focal_distance, 0);

    o.lens_radius = 0.2f;  /* -b 0.2 */
    o.lens_radius_given = true;
    c = camera_for_render(&s, &o);
    assert_float_near(0.2f, c.lens_radius, 0);
    assert_float_near(3.9f, c.focal_distance, 0);

    o.focal_distance = 2.0f;  /* -d 2 */
    o.focal_distance_given = true;
    c = camera_for_render(&s, &o);
    assert_float_near(2.0, c.focal_distance, 0);
    scene_free(&s);
}

int camera_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera_set_aspect__the_free_fov_follows_the_fixed_one),
        cmocka_unit_test(test_camera_default_framing__looks_at_the_centre_from_plus_z),
        cmocka_unit_test(test_camera_for_render__keeps_the_settings_files_lens_unless_flags_are_given),
    };
    return cmocka_run_group_tests_name("camera", tests, NULL, NULL);
}
