/* Test machinery: not part of any assignment. Command-line parsing: CS184's flags and defaults;
 * what a run says about its scene and flags (cli_warn_noops, camera_framing_line). */
#include "../common/test.h"
#include "../common/warn_log.h"
#include "../../framework/camera.h"
#include "../../framework/cli.h"
#include "../../framework/dae.h"
#include "../../framework/envmap.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Parses a NULL-terminated list of arguments (after the program name). */
static pl_status parse(options *o, pl_diag *d, const char **args)
{
    char *argv[64] = {"pathtracer"};
    int argc = 1;
    while (args[argc - 1]) {
        assert_true(argc < 64);
        argv[argc] = (char *)args[argc - 1];
        argc++;
    }
    cli_action action;
    return cli_parse(argc, argv, o, &action, d);
}

static void test_cli__defaults_are_cs184s(void **state)
{
    options o;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, parse(&o, &d, (const char *[]){"s.dae", NULL}));
    assert_int_equal(1, o.spp);
    assert_int_equal(1, o.light_samples);
    assert_int_equal(1, o.threads);
    assert_int_equal(1, o.max_depth);
    assert_true(o.accumulate);
    assert_int_equal(800, o.width);
    assert_int_equal(600, o.height);
    assert_int_equal(32, o.adaptive_batch);
    assert_float_near(0.05, o.adaptive_tol, 1e-7);
    assert_float_near(4.7, o.focal_distance, 1e-6);
    assert_false(o.lens_radius_given);  /* the camera's own lens stays (camera_for_render) */
    assert_false(o.focal_distance_given);
    assert_false(o.adaptive);
    assert_false(o.hemisphere);
    assert_int_equal(FRAMING_AUTO, o.framing);  /* decided by the scene's profile (camera.h) */
    assert_string_equal("s.dae", o.scene_path);
    cli_free(&o);
}

static void test_cli__every_flag_is_read(void **state)
{
    options o;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, parse(&o, &d, (const char *[]){"-s", "64", "-l", "4", "-t", "2", "-m", "5", "-o", "0", "-b", "0.1",
                                                           "-d", "3", "-f", "x.png", "-r", "480", "360", "-a", "16", "0.1",
                                                           "-H", "--seed", "99", "--normals", "--cs184-camera",
                                                           "--no-bvh", "--no-rr", "--leaf-size", "8", "--max-primitives", "300",
                                                           "--max-instances", "400", "-v", "scene.dae", NULL}));
    assert_int_equal(64, o.spp);
    assert_int_equal(4, o.light_samples);
    assert_int_equal(2, o.threads);
    assert_int_equal(5, o.max_depth);
    assert_false(o.accumulate);
    assert_float_near(0.1, o.lens_radius, 1e-6);
    assert_float_near(3.0, o.focal_distance, 1e-6);
    assert_true(o.lens_radius_given && o.focal_distance_given);
    assert_string_equal("x.png", o.output);
    assert_int_equal(480, o.width);
    assert_int_equal(360, o.height);
    assert_true(o.adaptive);
    assert_int_equal(16, o.adaptive_batch);
    assert_float_near(0.1, o.adaptive_tol, 1e-6);
    assert_true(o.hemisphere && o.normals && o.linear_scan && o.no_roulette && o.verbose);
    assert_int_equal(FRAMING_CS184, o.framing);
    assert_int_equal(99, (int)o.seed);
    assert_int_equal(8, o.max_leaf_size);
    assert_int_equal(300, o.max_primitives);
    assert_int_equal(400, o.max_instances);
    assert_non_null(strstr(o.command_line, "-r 480 360"));
    cli_free(&o);
}

/* Each bad command line fails with PL_ERR_INVALID and a message containing `expect`. */
static void expect_error(const char **args, const char *expect)
{
    options o;
    pl_diag d = pl_diag_default();
    pl_status s = parse(&o, &d, args);
    if (s != PL_ERR_INVALID || !strstr(d.error, expect))
        fail_msg("expected an error containing '%s', got status %d: '%s'", expect, s, d.error);
}

static void test_cli__bad_values_are_named(void **state)
{
    expect_error((const char *[]){"-s", "abc", "s.dae", NULL}, "-s: expected an integer");
    expect_error((const char *[]){"-s", "0", "s.dae", NULL}, "-s: expected an integer from 1");
    expect_error((const char *[]){"-s", NULL}, "-s: expected an integer");
    expect_error((const char *[]){"-r", "100", NULL}, "-r H");
    expect_error((const char *[]){"-r", "100", "x", "s.dae", NULL}, "-r H");
    expect_error((const char *[]){"-a", "32", NULL}, "-a T");
    expect_error((const char *[]){"-o", "2", "s.dae", NULL}, "-o");
    expect_error((const char *[]){"-b", "-1", "s.dae", NULL}, "-b");
    expect_error((const char *[]){"--seed", "-3", "s.dae", NULL}, "--seed");
    expect_error((const char *[]){"--max-instances", "0", "s.dae", NULL}, "--max-instances: expected an integer from 1");
    expect_error((const char *[]){"--bogus", "s.dae", NULL}, "unknown option '--bogus'");
    expect_error((const char *[]){NULL}, "expected a scene file");
    expect_error((const char *[]){"a.dae", "b.dae", NULL}, "expected one scene file");
    expect_error((const char *[]){"--camera", "orbit", "s.dae", NULL}, "--camera: expected literal or cs184, got 'orbit'");
    expect_error((const char *[]){"s.dae", "--camera", NULL}, "--camera: expected literal or cs184, got 'nothing'");
}

/* --camera literal|cs184, --cs184-camera as a synonym of cs184; the last one given wins. */
static void test_cli__camera_option_selects_the_framing(void **state)
{
    static const struct { const char *args[4]; camera_framing want; } cases[] = {
        {{"--camera", "literal", "s.dae", NULL}, FRAMING_LITERAL},
        {{"--camera", "cs184", "s.dae", NULL}, FRAMING_CS184},
        {{"--cs184-camera", "s.dae", NULL}, FRAMING_CS184},
        {{"--cs184-camera", "--camera", "literal", "s.dae"}, FRAMING_LITERAL},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *args[5] = {0};
        memcpy(args, cases[k].args, sizeof cases[k].args);
        options o;
        pl_diag d = pl_diag_default();
        assert_int_equal(PL_OK, parse(&o, &d, args));
        assert_int_equal(cases[k].want, o.framing);
        cli_free(&o);
    }
}

/* ---- what a run says -------------------------------------------------------------------------- */

/* The warnings cli_warn_noops gives for the command line args and the scene s. */
static warn_log noops(const char **args, const scene *s)
{
    warn_log w;
    pl_diag d = warn_log_diag(&w);
    options o;
    assert_int_equal(PL_OK, parse(&o, &d, args));
    int said = cli_warn_noops(&o, s, &d);
    assert_int_equal(w.count, said);
    cli_free(&o);
    return w;
}

/* A diffuse floor, and a point light over it unless lit is false; named like a file. */
static void floor_scene(scene *s, bool lit, bool emissive)
{
    memset(s, 0, sizeof *s);
    int m = scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(emissive ? 1.0f : 0.0f)));
    assert_true(m >= 0);
    assert_true(scene_add_triangle(s, triangle_make(vec3_make(-1, 0, -1), vec3_make(1, 0, -1), vec3_make(0, 0, 1), m)) >= 0);
    if (lit) {
        light l;
        memset(&l, 0, sizeof l);
        l.kind = LIGHT_POINT;
        l.radiance = rgb_gray(1.0f);
        l.position = vec3_make(0, 1, 0);
        l.attenuation[0] = 1.0f;
        assert_true(scene_add_light(s, l) >= 0);
    }
    snprintf(s->path, sizeof s->path, "CBspheres_unlit.dae");
}

/* No lights: one line naming the file; not when the scene is lit, nor under --normals. */
static void test_cli_warn_noops__a_scene_without_lights_says_its_image_is_black(void **state)
{
    scene s;
    floor_scene(&s, false, false);
    warn_log w = noops((const char *[]){"s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "CBspheres_unlit.dae has no lights: the image will be black"));
    assert_int_equal(0, noops((const char *[]){"--normals", "s.dae", NULL}, &s).count);
    scene_free(&s);

    floor_scene(&s, false, true);  /* emitters but no lights: black but for them */
    w = noops((const char *[]){"s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "CBspheres_unlit.dae has no lights: the image will be black but for its emitters"));
    scene_free(&s);

    floor_scene(&s, true, false);
    assert_int_equal(0, noops((const char *[]){"s.dae", NULL}, &s).count);
    scene_free(&s);
}

#ifdef PL_HAS_PART9
/* With part 9: -b gives the camera a lens, so it is no no-op; -d is one only where there is no lens. */
static void test_cli_warn_noops__lens_flags_that_change_nothing(void **state)
{
    scene s;
    floor_scene(&s, true, false);
    assert_int_equal(0, noops((const char *[]){"-b", "0.3", "-d", "2.0", "s.dae", NULL}, &s).count);
    assert_int_equal(0, noops((const char *[]){"-b", "0.3", "s.dae", NULL}, &s).count);
    warn_log w = noops((const char *[]){"-d", "2.5", "s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "-d 2.5 has no effect: the lens radius is 0"));
    scene_free(&s);
}
#else
/* -b / -d: accepted, and said to be unused, in one line whichever of them is given. */
static void test_cli_warn_noops__lens_flags_that_change_nothing(void **state)
{
    scene s;
    floor_scene(&s, true, false);
    warn_log w = noops((const char *[]){"-b", "0.3", "-d", "2.0", "s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "-b 0.3 and -d 2 accepted but not used: this course has no thin lens part"));
    w = noops((const char *[]){"-d", "2.5", "s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "-d 2.5 accepted but not used"));
    scene_free(&s);
    floor_scene(&s, false, false);  /* both at once: two lines, one each */
    assert_int_equal(2, noops((const char *[]){"-b", "0.3", "s.dae", NULL}, &s).count);
    scene_free(&s);
}
#endif

/* -e in a course without part 8: the map is seen, and the warning says it lights nothing; not with
 * --normals, where no map is seen either. */
static void test_cli_warn_noops__an_environment_map_without_its_part(void **state)
{
    (void)state;
#ifdef PL_HAS_PART8
    skip();
#else
    scene s;
    floor_scene(&s, true, false);
    s.env = calloc(1, sizeof *s.env);
    assert_int_equal(PL_OK, envmap_make_constant(s.env, 4, 2, rgb_gray(1.0f)));
    snprintf(s.env->path, sizeof s.env->path, "sky.exr");
    warn_log w = noops((const char *[]){"-e", "sky.exr", "s.dae", NULL}, &s);
    assert_int_equal(1, w.count);
    assert_non_null(strstr(w.all, "-e sky.exr: this course has no environment light part, so the map is seen where rays "
                                  "leave the scene but lights nothing"));
    assert_int_equal(0, noops((const char *[]){"--normals", "-e", "sky.exr", "s.dae", NULL}, &s).count);
    scene_free(&s);
#endif
}

/* The status line names the framing in use and the option that gives the other. */
static void test_camera_framing_line__names_the_framing_and_the_other(void **state)
{
    scene s;
    floor_scene(&s, true, false);
    s.has_camera = true;
    options o = options_default();
    char line[256];
    camera_framing_line(&o, &s, line, sizeof line);
    assert_non_null(strstr(line, "camera: the file's camera, as written"));
    assert_non_null(strstr(line, "--camera cs184"));
    s.course_profile = true;
    camera_framing_line(&o, &s, line, sizeof line);
    assert_non_null(strstr(line, "camera: CS184's framing"));
    assert_non_null(strstr(line, "course's profile"));
    assert_non_null(strstr(line, "--camera literal"));
    o.framing = FRAMING_LITERAL;
    camera_framing_line(&o, &s, line, sizeof line);
    assert_non_null(strstr(line, "as asked"));
    assert_non_null(strstr(line, "--camera cs184"));
    scene_free(&s);
}

static void test_cli__help_wins(void **state)
{
    options o;
    char *argv[] = {"pathtracer", "-s", "4", "-h"};
    cli_action action;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, cli_parse(4, argv, &o, &action, &d));
    assert_int_equal(CLI_HELP, action);
}

int cli_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli__defaults_are_cs184s),
        cmocka_unit_test(test_cli__every_flag_is_read),
        cmocka_unit_test(test_cli__bad_values_are_named),
        cmocka_unit_test(test_cli__help_wins),
        cmocka_unit_test(test_cli__camera_option_selects_the_framing),
        cmocka_unit_test(test_cli_warn_noops__a_scene_without_lights_says_its_image_is_black),
        cmocka_unit_test(test_cli_warn_noops__lens_flags_that_change_nothing),
        cmocka_unit_test(test_cli_warn_noops__an_environment_map_without_its_part),
        cmocka_unit_test(test_camera_framing_line__names_the_framing_and_the_other),
    };
    return cmocka_run_group_tests_name("cli", tests, NULL, NULL);
}
