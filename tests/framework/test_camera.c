/* Test machinery: not part of any assignment. The camera module (framework/camera.h): the fov rule,
 * the default framing, and which lens a render uses. */
#include "../common/test.h"
#include "../../framework/camera.h"
#include "../../framework/camera_file.h"
#include "../../framework/cli.h"
#include "../../framework/scene.h"
#include "../../framework/dae.h"
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

/* ---- framing a course file ---------------------------------------------------------------------- */

/* How many of the 8 corners of b lie in front of c and inside its frame (the fovs it renders with);
 * *below, how many of them in the lower half of the frame. */
static int corners_in_frame(const camera *c, aabb b, int *below)
{
    vec3 right = mat4_dir(c->camera_to_world, vec3_make(1, 0, 0)), up = mat4_dir(c->camera_to_world, vec3_make(0, 1, 0));
    vec3 back = mat4_dir(c->camera_to_world, vec3_make(0, 0, 1));
    float tx = tanf(c->hfov * 0.5f * (float)M_PI / 180.0f), ty = tanf(c->vfov * 0.5f * (float)M_PI / 180.0f);
    int inside = 0;
    *below = 0;
    for (int k = 0; k < 8; k++) {
        vec3 p = vec3_make(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z);
        vec3 d = vec3_sub(p, c->position);
        float depth = -vec3_dot(d, back);  /* along the view direction */
        if (depth > 0.0f && fabsf(vec3_dot(d, right)) <= tx * depth && fabsf(vec3_dot(d, up)) <= ty * depth) {
            inside++;
            if (vec3_dot(d, up) < -1e-3f * depth) (*below)++;
        }
    }
    return inside;
}

static options options_with(camera_framing framing)
{
    options o = options_default();
    o.framing = framing;
    return o;
}

/* A course-profile Cornell box whose camera sits at floor height (like CS184's CBempty.dae): by
 * default the whole box is in the frame and fills both its halves (CS184's framing); --camera
 * literal keeps the file's camera, under which the box sits in the upper half, the lower half of
 * the frame left black. */
static void test_camera_for_render__frames_a_course_file_as_cs184_by_default(void **state)
{
    (void)state;
    scene s;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, dae_load("tests/data/valid/cs184_cbempty_like.dae", &s, &d));
    assert_true(s.course_profile);
    aabb b = scene_bounds(&s);
    options o = options_default();
    assert_true(camera_uses_cs184_framing(&s, &o));
    camera c = camera_for_render(&s, &o);
    int below;
    assert_int_equal(8, corners_in_frame(&c, b, &below));
    assert_int_equal(4, below);  /* centred: the orbit's target is the bounds' centre */
    camera literal = camera_for_render(&s, (o = options_with(FRAMING_LITERAL), &o));
    assert_vec3_near(vec3_make(0, 0, 3.1f), literal.position, 1e-6f);  /* the file's, at floor height */
    assert_vec3_near(s.camera.position, literal.position, 0);
    corners_in_frame(&literal, b, &below);
    assert_int_equal(0, below);
    /* (At another -r CS184's framing keeps the pixel scale: 160x120 is the centre fifth of the view.) */
    /* A -c settings file's camera is taken as it is, as CS184 takes it. */
    o = options_default();
    o.camera_file = "x.cam";
    assert_false(camera_uses_cs184_framing(&s, &o));
    scene_free(&s);
}

/* Every course-profile fixture, framed by default: all eight corners of its bounds project inside
 * the frame. */
static void test_camera_for_render__every_course_fixture_has_its_bounds_in_the_frame(void **state)
{
    (void)state;
    static const char *fixtures[] = {"tests/data/valid/cs184_cbempty_like.dae", "tests/data/valid/cs184_layout.dae"};
    for (size_t k = 0; k < sizeof fixtures / sizeof fixtures[0]; k++) {
        scene s;
        pl_diag d = pl_diag_default();
        assert_int_equal(PL_OK, dae_load(fixtures[k], &s, &d));
        if (!s.course_profile) fail_msg("%s is not in the course's profile", fixtures[k]);
        options o = options_default();
        camera c = camera_for_render(&s, &o);
        int below;
        int in = corners_in_frame(&c, scene_bounds(&s), &below);
        if (in != 8) fail_msg("%s: %d of the 8 corners of its bounds project inside the frame", fixtures[k], in);
        scene_free(&s);
    }
}

/* pathlab's own scenes are written in CS184's dialect too, but their cameras are meant literally:
 * none of them is in the course's profile, so no reference or grading case changes framing. */
static void test_camera_for_render__keeps_pathlabs_own_scenes_literal(void **state)
{
    (void)state;
    static const char *own[] = {"scenes/cornell_empty.dae", "scenes/cornell_spheres.dae", "scenes/cornell_bunny.dae",
                                "scenes/cornell_grazing.dae", "scenes/cornell_two_lights.dae", "scenes/lights_point_dir.dae",
                                "scenes/analytic/furnace.dae"};
    for (size_t k = 0; k < sizeof own / sizeof own[0]; k++) {
        scene s;
        pl_diag d = pl_diag_default();
        assert_int_equal(PL_OK, dae_load(own[k], &s, &d));
        options o = options_default();
        if (s.course_profile || camera_uses_cs184_framing(&s, &o)) fail_msg("%s is taken for a course file", own[k]);
        camera c = camera_for_render(&s, &o);
        assert_vec3_near(s.camera.position, c.position, 0);
        scene_free(&s);
    }
}

int camera_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera_set_aspect__the_free_fov_follows_the_fixed_one),
        cmocka_unit_test(test_camera_default_framing__looks_at_the_centre_from_plus_z),
        cmocka_unit_test(test_camera_for_render__keeps_the_settings_files_lens_unless_flags_are_given),
        cmocka_unit_test(test_camera_for_render__frames_a_course_file_as_cs184_by_default),
        cmocka_unit_test(test_camera_for_render__every_course_fixture_has_its_bounds_in_the_frame),
        cmocka_unit_test(test_camera_for_render__keeps_pathlabs_own_scenes_literal),
    };
    return cmocka_run_group_tests_name("camera", tests, NULL, NULL);
}
