/* Test machinery: not part of any assignment. The camera module (framework/camera.h): the fov rule,
 * the default framing, and which lens a render uses. */
#include "../common/test.h"
#include "../../framework/camera.h"
#include "../../framework/camera_file.h"
#include "../../framework/cli.h"
#include "../../framework/scene.h"
#include "../../framework/dae.h"
#include "../common/warn_log.h"
#include <math.h>
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

/* CS184's framing direction written out from its Application::load, independently of the loader:
 * c_dir = normalize(U M (0, 0, -1, 1)), M the camera node's matrix as the file writes it (row-major),
 * U the Z-up mapping (x, y, z) -> (-x, z, y). The eye sits at the bounds' centre + r c_dir
 * (Camera::place). With no camera c_dir is zero, and place() puts the eye at phi = acos(0) = pi/2,
 * theta = atan2(0, 0) = 0: along (0, 0, 1). */
static void cs184_c_dir(const double m[16], double out[3])
{
    if (!m) {
        out[0] = 0, out[1] = 0, out[2] = 1;
        return;
    }
    double p[3] = {m[3] - m[2], m[7] - m[6], m[11] - m[10]};  /* M (0, 0, -1, 1) */
    double world[3] = {-p[0], p[2], p[1]}, len = sqrt(world[0] * world[0] + world[1] * world[1] + world[2] * world[2]);
    for (int i = 0; i < 3; i++) out[i] = world[i] / len;
}

/* The opposite of the camera's view direction, U M (0, 0, 1, 0) normalised: the old framing's side. */
static void view_side(const double m[16], double out[3])
{
    double world[3] = {-m[2], m[10], m[6]}, len = sqrt(world[0] * world[0] + world[1] * world[1] + world[2] * world[2]);
    for (int i = 0; i < 3; i++) out[i] = world[i] / len;
}

static double angle_deg(const double a[3], const double b[3])
{
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return acos(d > 1 ? 1 : d < -1 ? -1 : d) * 180.0 / M_PI;
}

/* Every course-profile fixture, framed by default, has its eye on the side CS184's formula names,
 * the formula computed here from the matrix each file writes (the last camera node's, where there
 * are two); for the files whose camera is off its view axis the formula is checked to differ from
 * the view direction's, so framing along the view (the old rule) or by the first camera fails. */
static void test_camera_for_render__orbits_where_cs184s_point_formula_says(void **state)
{
    (void)state;
    static const double on_axis[16] = {-1, 0, 0, 0, 0, 0, 1, 3.1, 0, 1, 0, 0, 0, 0, 0, 1};
    static const double off_axis[16] = {-1, 0, 0, -0.5, 0, 0, 1, 3.1, 0, 1, 0, 0.5, 0, 0, 0, 1};
    static const double second[16] = {-0.83205, 0.14825, -0.534522, -1.6, -0.5547, -0.222375, 0.801784, 2.4,
                                      0, 0.963624, 0.267261, 1.4, 0, 0, 0, 1};
    static const struct { const char *path; const double *m; double off_view_deg; } cases[] = {
        {"tests/data/valid/cs184_cbempty_like.dae", on_axis, 0},
        {"tests/data/valid/cs184_layout.dae", NULL, 0},  /* no camera */
        {"tests/data/valid/cs184_cbspheres_hw2_like.dae", on_axis, 0},
        {"tests/data/valid/cs184_camera_off_axis.dae", off_axis, 18.6},
        {"tests/data/valid/cs184_two_cameras.dae", second, 15.0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        scene s;
        warn_log w;
        pl_diag d = warn_log_diag(&w);  /* the two cameras' warning is test_dae's */
        assert_int_equal(PL_OK, dae_load(cases[k].path, &s, &d));
        options o = options_default();
        if (!camera_uses_cs184_framing(&s, &o)) fail_msg("%s is not framed CS184's way", cases[k].path);
        camera c = camera_for_render(&s, &o);
        vec3 side = vec3_normalize(vec3_sub(c.position, aabb_centroid(scene_bounds(&s))));
        double want[3], got[3] = {side.x, side.y, side.z};
        cs184_c_dir(cases[k].m, want);
        if (angle_deg(want, got) > 1e-3)
            fail_msg("%s: the eye is %.4f degrees from CS184's c_dir (%.6f %.6f %.6f): along (%.6f %.6f %.6f)",
                     cases[k].path, angle_deg(want, got), want[0], want[1], want[2], got[0], got[1], got[2]);
        if (cases[k].m) {
            double old[3];
            view_side(cases[k].m, old);
            assert_float_near(cases[k].off_view_deg, angle_deg(want, old), 0.1);
        }
        scene_free(&s);
    }
    /* The two cameras differ, so keeping the first would fail above. */
    double first[3], last[3];
    cs184_c_dir(on_axis, first);
    cs184_c_dir(second, last);
    assert_true(angle_deg(first, last) > 40.0);
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
        cmocka_unit_test(test_camera_for_render__orbits_where_cs184s_point_formula_says),
        cmocka_unit_test(test_camera_for_render__keeps_pathlabs_own_scenes_literal),
    };
    return cmocka_run_group_tests_name("camera", tests, NULL, NULL);
}
