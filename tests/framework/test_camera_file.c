/* Test machinery: not part of any assignment. CS184 camera settings files (-c). */
#include "../common/test.h"
#include "../../framework/camera_file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *write_file(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/pathlab-camera-XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

static void test_camera_file_load__reads_pose_and_lens(void **state)
{
    const char *path = write_file("50 40 1.333 0.1 100\n"
                                  "1 2 3  0 0 0\n"
                                  "0 0 3.7 0.1 10\n"
                                  "1 0 0 0 1 0 0 0 1\n"
                                  "800 600 1\n"
                                  "4.7 0\n");
    camera c;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, camera_file_load(path, &c, &d));
    assert_vec3_near(vec3_make(1, 2, 3), c.position, 0);
    assert_float_near(40.0, c.vfov, 1e-6);
    assert_true(c.fov_is_vertical);
    assert_float_near(0.1, c.znear, 1e-6);
    assert_vec3_near(vec3_make(0, 0, -1), mat4_dir(c.camera_to_world, vec3_make(0, 0, -1)), 0);
    remove(path);
}

static void test_camera_file_load__errors_name_file_line_and_field(void **state)
{
    struct { const char *text, *expect; } cases[] = {
        {"50 40 1.333 0.1\n", ":1: expected 5 numbers (hfov vfov aspect near far)"},
        {"50 40 1.333 0.1 100\n1 2 3 0 0\n", ":2: expected 6 numbers"},
        {"50 40 1.333 0.1 100\n1 2 3 0 0 0\n0 0 3.7 0.1 10\n1 0 0 0 1 0 0 0 x\n", ":4: expected 9 numbers"},
        {"50 40 1.333 0.1 100\n1 2 3 0 0 0\n0 0 3.7 0.1 10\n1 0 0 0 1 0 0 0 1\n800 600 1\n", ":6: expected 2 numbers"},
        {"50 40 1.333 0.1 100 7\n", ":1: expected 5 numbers (hfov vfov aspect near far), found more"},
        {"0 40 1.333 0.1 100\n1 2 3 0 0 0\n0 0 3.7 0.1 10\n1 0 0 0 1 0 0 0 1\n800 600 1\n4.7 0\n", ":1: expected fields of view"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = write_file(cases[i].text);
        camera c;
        pl_diag d = pl_diag_default();
        pl_status s = camera_file_load(path, &c, &d);
        if (s == PL_OK || !strstr(d.error, cases[i].expect) || !strstr(d.error, path))
            fail_msg("case %zu: expected an error with '%s' and the path, got status %d: '%s'", i, cases[i].expect, s, d.error);
        remove(path);
    }
    camera c;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, camera_file_load("/tmp/pathlab-no-such-camera", &c, &d));
}

/* Regression (issue 7, defect 11): values that cannot make a picture are refused with file:line,
 * instead of rendering an all-black image and exiting 0. */

/* Case i of a table: the camera file `text` must be refused with `expect` and its path in the
 * message; a failure names the table's case and the test's line (PL_AT). */
static void expect_refused(const char *text, const char *expect, size_t i)
{
    const char *path = write_file(text);
    camera c;
    pl_diag d = pl_diag_default();
    pl_status s = camera_file_load(path, &c, &d);
    if (s == PL_OK || !strstr(d.error, expect) || !strstr(d.error, path))
        PL_FAIL("case %zu: expected an error with '%s' and the path, got status %d: '%s'", i, expect, s, d.error);
    remove(path);
}
#define expect_refused(...) PL_AT(expect_refused(__VA_ARGS__))

static void test_camera_file_load__refuses_values_that_are_not_a_camera(void **state)
{
    static const char *const lines_after_1 = "1 2 3  0 0 0\n0 0 3.7 0.1 10\n";
    struct { const char *lens, *rot, *focus, *expect; } cases[] = {
        {"nan 40 1.333 0.1 100", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected finite numbers"},
        {"50 40 1.333 0.1 inf", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected finite numbers"},
        {"50 40 1.333 0.1 100", "1 0 0 0 nan 0 0 0 1", "4.7 0", ":4: expected finite numbers"},
        {"50 40 1.333 0.1 100", "0 0 0 0 0 0 0 0 0", "4.7 0", ":4: expected a rotation (orthonormal rows"},
        {"50 40 1.333 0.1 100", "2 0 0 0 2 0 0 0 2", "4.7 0", ":4: expected a rotation (orthonormal rows"},
        {"50 40 1.333 0.1 100", "1 0.01 0 0 1 0 0 0 1", "4.7 0", ":4: expected a rotation (orthonormal rows"},
        {"50 40 1.333 0.1 100", "-1 0 0 0 1 0 0 0 1", "4.7 0", ":4: expected a rotation (determinant +1)"},
        {"50 40 1.333 100 0.1", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected 0 < near < far"},
        {"50 40 1.333 0 100", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected 0 < near < far"},
        {"50 40 1.333 -1 100", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected 0 < near < far"},
        {"50 180 1.333 0.1 100", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected fields of view in (0, 180)"},
        {"50 40 0 0.1 100", "1 0 0 0 1 0 0 0 1", "4.7 0", ":1: expected a positive aspect ratio"},
        {"50 40 1.333 0.1 100", "1 0 0 0 1 0 0 0 1", "4.7 -1", ":6: expected a lens radius >= 0"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "%s\n%s%s\n800 600 1\n%s\n", cases[i].lens, lines_after_1, cases[i].rot,
                 cases[i].focus);
        expect_refused(text, cases[i].expect, i);
    }
}

/* Regression (issue 7 audit): a finite but huge position (1e38 rendered all black, exit 0), a focal
 * distance <= 0 and lines after the sixth were accepted. Each is refused with file:line. */
static void test_camera_file_load__refuses_far_positions_bad_focus_and_trailing_lines(void **state)
{
    static const char *const lens = "50 40 1.333 0.1 100\n";
    static const char *const middle = "0 0 3.7 0.1 10\n1 0 0 0 1 0 0 0 1\n800 600 1\n";
    struct { const char *pose, *focus, *after, *expect; } cases[] = {
        {"1e38 2 3  0 0 0", "4.7 0", "", ":2: expected coordinates within +-1e+18 (position xyz, target xyz), got 1e+38 as number 1"},
        {"1 2 3  0 0 -2e18", "4.7 0", "", ":2: expected coordinates within +-1e+18 (position xyz, target xyz), got -2e+18 as number 6"},
        {"1 2 3  0 0 0", "0 0", "", ":6: expected a focal distance in (0, 1e+18], got 0"},
        {"1 2 3  0 0 0", "-4.7 0", "", ":6: expected a focal distance in (0, 1e+18], got -4.7"},
        {"1 2 3  0 0 0", "1e30 0", "", ":6: expected a focal distance in (0, 1e+18], got 1e+30"},
        {"1 2 3  0 0 0", "4.7 0", "7 8\n", ":7: expected the end of the file after six lines, found '7 8'"},
        {"1 2 3  0 0 0", "4.7 0", "\n \r\n\tjunk", ":9: expected the end of the file after six lines, found 'junk'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "%s%s\n%s%s\n%s", lens, cases[i].pose, middle, cases[i].focus, cases[i].after);
        expect_refused(text, cases[i].expect, i);
    }
    /* Blank lines (and CRLF endings) after the sixth are not junk; coordinates at the cap are fine. */
    const char *path = write_file("50 40 1.333 0.1 100\r\n1e18 2 3  0 0 -1e18\r\n0 0 3.7 0.1 10\r\n"
                                  "1 0 0 0 1 0 0 0 1\r\n800 600 1\r\n4.7 0\r\n\r\n  \n");
    camera c;
    pl_diag d = pl_diag_default();
    if (camera_file_load(path, &c, &d) != PL_OK) fail_msg("expected the file to load: %s", d.error);
    remove(path);
}

/* A rotation as CS184 saves it (6 significant digits) and one typed by hand (0.7071) are accepted. */
static void test_camera_file_load__accepts_rounded_rotations(void **state)
{
    const char *rotations[] = {"0.707107 0 0.707107 0 1 0 -0.707107 0 0.707107",
                               "0.7071 -0.7071 0 0.7071 0.7071 0 0 0 1"};
    for (size_t i = 0; i < sizeof rotations / sizeof rotations[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "50 40 1.333 0.1 100\n1 2 3 0 0 0\n0 0 3.7 0.1 10\n%s\n800 600 1\n4.7 0\n",
                 rotations[i]);
        const char *path = write_file(text);
        camera c;
        pl_diag d = pl_diag_default();
        if (camera_file_load(path, &c, &d) != PL_OK) fail_msg("rotation %zu refused: %s", i, d.error);
        remove(path);
    }
}

/* Regression (issue 7, defects 9 and 11): the camera file is read through the size- and type-checked
 * reader, so a directory is refused as such (it used to be reported as an empty file); FIFOs and
 * devices go through the same check, tested with file_read_all itself. */
static void test_camera_file_load__refuses_non_regular_files(void **state)
{
    camera c;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, camera_file_load("/tmp", &c, &d));
    assert_non_null(strstr(d.error, "expected a regular file"));
}

/* The documented 64 KB cap: a valid camera followed by padding past it is refused before parsing. */
static void test_camera_file_load__refuses_files_over_the_cap(void **state)
{
    size_t n = 70 * 1024;
    char *text = malloc(n + 1);
    assert_non_null(text);
    const char *camera_text = "50 40 1.333 0.1 100\n1 2 3 0 0 0\n0 0 3.7 0.1 10\n1 0 0 0 1 0 0 0 1\n800 600 1\n4.7 0\n";
    memset(text, '\n', n);
    memcpy(text, camera_text, strlen(camera_text));
    text[n] = '\0';
    const char *path = write_file(text);
    free(text);
    camera c;
    pl_diag d = pl_diag_default();
    pl_status s = camera_file_load(path, &c, &d);
    remove(path);
    assert_int_equal(PL_ERR_IO, s);
    assert_non_null(strstr(d.error, "the limit is 65536"));
}

int camera_file_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera_file_load__reads_pose_and_lens),
        cmocka_unit_test(test_camera_file_load__errors_name_file_line_and_field),
        cmocka_unit_test(test_camera_file_load__refuses_values_that_are_not_a_camera),
        cmocka_unit_test(test_camera_file_load__refuses_far_positions_bad_focus_and_trailing_lines),
        cmocka_unit_test(test_camera_file_load__accepts_rounded_rotations),
        cmocka_unit_test(test_camera_file_load__refuses_non_regular_files),
        cmocka_unit_test(test_camera_file_load__refuses_files_over_the_cap),
    };
    return cmocka_run_group_tests_name("camera_file", tests, NULL, NULL);
}
