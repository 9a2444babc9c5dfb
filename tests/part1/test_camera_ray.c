/* Test machinery: not part of any assignment. Task 1.1: camera rays through known film points. */
#include "../common/test.h"
#include "../../parts/part1_raygen/part1.h"
#include <math.h>
#include <string.h>

static camera make_camera(mat4 c2w, float hfov, float vfov)
{
    camera c;
    memset(&c, 0, sizeof c);
    c.camera_to_world = c2w;
    c.position = mat4_point(c2w, vec3_make(0, 0, 0));
    c.hfov = hfov;
    c.vfov = vfov;
    c.znear = 0.01f;
    c.zfar = 50.0f;
    return c;
}

static void test_camera_generate_ray__centre_looks_down_minus_z(void **state)
{
    camera c = make_camera(mat4_identity(), 90.0f, 60.0f);
    ray r = camera_generate_ray(&c, 0.5f, 0.5f);
    assert_implemented();
    assert_vec3_near(vec3_make(0, 0, 0), r.o, 1e-6f);
    assert_vec3_near(vec3_make(0, 0, -1), r.d, 1e-6f);
}

static void test_camera_generate_ray__corners_span_the_field_of_view(void **state)
{
    /* hfov 90: tan(45) = 1, so the right edge is at x = 1 on the plane z = -1.
     * vfov 60: tan(30) = 0.57735 at the top edge. */
    camera c = make_camera(mat4_identity(), 90.0f, 60.0f);
    float ty = tanf(deg_to_rad(30.0f));
    struct { float x, y; vec3 through; } cases[] = {
        {1, 1, {1, ty, -1}}, {0, 0, {-1, -ty, -1}}, {1, 0, {1, -ty, -1}}, {0, 1, {-1, ty, -1}}, {0.75f, 0.5f, {0.5f, 0, -1}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ray r = camera_generate_ray(&c, cases[i].x, cases[i].y);
        assert_implemented();
        assert_vec3_near(vec3_normalize(cases[i].through), r.d, 1e-5f);
    }
}

static void test_camera_generate_ray__unit_direction_and_clip_range(void **state)
{
    camera c = make_camera(mat4_identity(), 70.0f, 50.0f);
    ray r = camera_generate_ray(&c, 0.1f, 0.9f);
    assert_implemented();
    assert_float_near(1.0, vec3_length(r.d), 1e-5);
    assert_float_near(0.01, r.min_t, 1e-7);
    assert_float_near(50.0, r.max_t, 1e-5);
}

static void test_camera_generate_ray__uses_the_camera_pose(void **state)
{
    /* A camera at (5, 1, 0) looking down -X (rotated 90 degrees about +Y). */
    mat4 c2w = mat4_mul(mat4_translate(vec3_make(5, 1, 0)), mat4_rotate(vec3_make(0, 1, 0), 90.0f));
    camera c = make_camera(c2w, 90.0f, 90.0f);
    ray r = camera_generate_ray(&c, 0.5f, 0.5f);
    assert_implemented();
    assert_vec3_near(vec3_make(5, 1, 0), r.o, 1e-5f);
    assert_vec3_near(vec3_make(-1, 0, 0), r.d, 1e-5f);
    /* The top edge leans towards world +Y, the right edge towards world -Z. */
    r = camera_generate_ray(&c, 0.5f, 1.0f);
    assert_vec3_near(vec3_normalize(vec3_make(-1, 1, 0)), r.d, 1e-5f);
    r = camera_generate_ray(&c, 1.0f, 0.5f);
    assert_vec3_near(vec3_normalize(vec3_make(-1, 0, -1)), r.d, 1e-5f);
}

int camera_ray_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_camera_generate_ray__centre_looks_down_minus_z, test_setup),
        cmocka_unit_test_setup(test_camera_generate_ray__corners_span_the_field_of_view, test_setup),
        cmocka_unit_test_setup(test_camera_generate_ray__unit_direction_and_clip_range, test_setup),
        cmocka_unit_test_setup(test_camera_generate_ray__uses_the_camera_pose, test_setup),
    };
    return cmocka_run_group_tests_name("part1: camera_generate_ray (task 1.1)", tests, NULL, NULL);
}
