/* Test machinery: not part of any assignment. Task 1.4: the camera ray of one pixel sample, checked
 * exactly against camera_generate_ray at the film point it must use; then the framework's pixel
 * loop with it (coverage of the pixel), and a whole normal-shaded render against an independent
 * oracle.
 *
 * Statistics: each coverage test counts the covered samples and checks the proportion with an
 * exact two-sided binomial test (stats_binomial_p2) at the suite's per-check level
 * PART1_CHECK_ALPHA (family alpha and budget: part1_alpha.h). Seeds are fixed, printed, and
 * changed by PL_TEST_SEED (mc_seed). */
#include "../common/test.h"
#include "../common/mc_assert.h"
#include "../../framework/stats.h"
#include "part1_alpha.h"
#include "../../parts/part1_raygen/part1.h"
#include "../../framework/render.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* The fixed seed of the coverage tests, XORed with PL_TEST_SEED; each test adds its own offset. */
#define SEED_BASE 20261121u

/* A 1x1-pixel film looking down -Z with a 90-degree fov: film x in [0,1] maps to the plane
 * z = -1 at x in [-1, 1]. A quad on that plane covers x in [x0, 10], y in [y0, 10]. */
static void build_edge_scene(scene *s, float x0, float y0)
{
    memset(s, 0, sizeof *s);
    int m = scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(0)));
    vec3 a = {x0, y0, -1}, b = {10, y0, -1}, c = {10, 10, -1}, d = {x0, 10, -1};
    scene_add_triangle(s, triangle_make(a, b, c, m));
    scene_add_triangle(s, triangle_make(a, c, d, m));
    s->has_camera = true;
    s->camera.camera_to_world = mat4_identity();
    s->camera.hfov = s->camera.vfov = 90.0f;
    s->camera.znear = 1e-3f;
    s->camera.zfar = 100.0f;
}

/* Fraction of the pixel covered, estimated from the blue channel (normal (0,0,1) shades blue 1). */
static double covered_fraction(float x0, float y0, int spp, uint64_t seed, int *taken)
{
    scene s;
    build_edge_scene(&s, x0, y0);
    accel a;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, accel_build(&a, &s, false, 4, &d));
    options o = options_default();
    o.width = o.height = 1;
    o.spp = spp;
    o.normals = true;
    o.seed = seed;
    render_ctx ctx;
    render_ctx_init(&ctx, &s, &a, &o);
    film_pixel p = {0};
    render_pixel(&ctx, 0, 0, &p);
    *taken = (int)p.n;
    accel_free(&a);
    scene_free(&s);
    return film_pixel_mean(&p, 2);
}

/* One statistical check: the covered samples of spp, against a binomial of the covered area. */
static void expect_fraction(const char *name, uint64_t seed, float x0, float y0, double expected, int spp)
{
    mc_print_seed(name, seed);
    int taken = 0;
    double got = covered_fraction(x0, y0, spp, seed, &taken);
    assert_implemented();
    if (taken != spp) fail_msg("the pixel loop took %d samples, expected %d (the -s value)", taken, spp);
    long covered = lround(got * spp);  /* each sample is blue 1 (covered) or 0 */
    double alpha = PART1_CHECK_ALPHA, p = stats_binomial_p2(covered, spp, expected);
    if (!(p >= alpha))
        fail_msg("wrong: %ld of %d samples (%.4f) cover the pixel's area %.4f: p = %.3g < alpha %.3g (exact binomial "
                 "test, seed 0x%llx): are samples spread uniformly over the whole pixel?", covered, spp, got, expected,
                 p, alpha, (unsigned long long)seed);
}

/* ---- pixel_sample_ray alone: exact ---------------------------------------------------------- */

static camera tilted_camera(void)
{
    camera c;
    memset(&c, 0, sizeof c);
    c.camera_to_world = mat4_identity();
    c.hfov = 70.0f;
    c.vfov = 50.0f;
    c.znear = 1e-3f;
    c.zfar = 100.0f;
    return c;
}

/* pixel_sample_ray(x, y, u) must be the camera ray through ((x + u.x) / W, (y + u.y) / H). */
static void expect_ray_through(int x, int y, int w, int h, vec2 u)
{
    camera c = tilted_camera();
    ray got = pixel_sample_ray(&c, x, y, w, h, u);
    assert_implemented();
    float fx = (x + u.x) / (float)w, fy = (y + u.y) / (float)h;
    ray want = camera_generate_ray(&c, fx, fy);
    vec3 dg = got.d, dw = want.d;
    if (!(fabsf(dg.x - dw.x) <= 1e-5f && fabsf(dg.y - dw.y) <= 1e-5f && fabsf(dg.z - dw.z) <= 1e-5f))
        fail_msg("wrong: pixel (%d, %d) of %dx%d with u = (%g, %g) gave direction (%g, %g, %g); expected the ray "
                 "through film point (%g, %g) = ((x + u.x) / W, (y + u.y) / H): (%g, %g, %g)",
                 x, y, w, h, u.x, u.y, dg.x, dg.y, dg.z, fx, fy, dw.x, dw.y, dw.z);
}

static void test_pixel_sample_ray__centre_of_the_pixel(void **state)
{
    expect_ray_through(0, 0, 4, 3, vec2_make(0.5f, 0.5f));
    expect_ray_through(3, 1, 4, 3, vec2_make(0.5f, 0.5f));
}

static void test_pixel_sample_ray__u_spans_the_pixel(void **state)
{
    expect_ray_through(1, 2, 4, 3, vec2_make(0.0f, 0.0f));    /* bottom-left corner */
    expect_ray_through(1, 2, 4, 3, vec2_make(0.25f, 0.75f));  /* x and y not swapped */
    expect_ray_through(2, 0, 5, 7, vec2_make(0.9f, 0.1f));
}

/* ---- the framework's pixel loop with it ----------------------------------------------------- */

static void test_pixel_loop__one_sample_goes_through_the_centre(void **state)
{
    int taken = 0;
    double hit_left = covered_fraction(-0.2f, -10, 1, SEED_BASE, &taken);  /* the centre (x = 0) is covered */
    assert_implemented();
    if (taken != 1) PL_FAIL("wrong: the pixel loop took %d samples at -s 1, expected 1", taken);
    assert_float_near(1.0, hit_left, 1e-6);
    double miss = covered_fraction(0.2f, -10, 1, SEED_BASE, &taken);       /* the centre is not covered */
    assert_float_near(0.0, miss, 1e-6);
}

static void test_pixel_loop__samples_cover_the_pixel_uniformly_in_x(void **state)
{
    expect_fraction("coverage in x", mc_seed(SEED_BASE + 1), 0.2f, -10, 0.4, 4096);  /* x in [0.2, 1] of [-1, 1] */
}

static void test_pixel_loop__samples_cover_the_pixel_uniformly_in_y(void **state)
{
    /* y in [0.5, 1] of [-1, 1]: film y = 0 is the bottom */
    expect_fraction("coverage in y", mc_seed(SEED_BASE + 2), -10, 0.5f, 0.25, 4096);
}

static void test_pixel_loop__corner_quarter(void **state)
{
    expect_fraction("corner quarter", mc_seed(SEED_BASE + 3), 0.0f, 0.0f, 0.25, 4096);
}

/* ---- a whole render against an oracle written independently, in double precision ---------- */

static const struct { double c[3], r; } oracle_spheres[] = {{{-0.6, 0.1, -4.0}, 0.8}, {{0.9, -0.2, -5.0}, 1.0}};

/* Normal colour the oracle expects at film point (u, v), or black on a miss. */
static rgb oracle_normal(double u, double v, double tan_h, double tan_v)
{
    double d[3] = {tan_h * (2 * u - 1), tan_v * (2 * v - 1), -1};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++) d[k] /= len;
    double best = INFINITY;
    rgb colour = rgb_gray(0);
    for (int i = 0; i < 2; i++) {
        const double *c = oracle_spheres[i].c;
        double b = -(d[0] * c[0] + d[1] * c[1] + d[2] * c[2]);
        double cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - oracle_spheres[i].r * oracle_spheres[i].r;
        double disc = b * b - cc;
        if (disc < 0) continue;
        double t = -b - sqrt(disc);
        if (t > 0 && t < best) {
            best = t;
            double n[3];
            for (int k = 0; k < 3; k++) n[k] = (t * d[k] - c[k]) / oracle_spheres[i].r;
            colour = rgb_make((float)(0.5 * n[0] + 0.5), (float)(0.5 * n[1] + 0.5), (float)(0.5 * n[2] + 0.5));
        }
    }
    return colour;
}

static void test_render__normal_image_matches_oracle(void **state)
{
    scene s;
    memset(&s, 0, sizeof s);
    int m = scene_add_material(&s, material_make(rgb_gray(0.5f), rgb_gray(0)));
    for (int i = 0; i < 2; i++) {
        const double *c = oracle_spheres[i].c;
        scene_add_sphere(&s, (sphere){{(float)c[0], (float)c[1], (float)c[2]}, (float)oracle_spheres[i].r, m});
    }
    s.has_camera = true;
    s.camera.camera_to_world = mat4_identity();
    s.camera.hfov = 60.0f;
    s.camera.znear = 1e-3f;
    s.camera.zfar = 100.0f;
    options o = options_default();
    o.width = 64, o.height = 48, o.normals = true, o.threads = pl_test_threads(2);
    accel a;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, accel_build(&a, &s, true, 4, &d));
    render_ctx ctx;
    render_ctx_init(&ctx, &s, &a, &o);
    image img;
    assert_int_equal(PL_OK, image_alloc(&img, o.width, o.height));
    render_stats st;
    assert_int_equal(PL_OK, render_image(&ctx, &img, NULL, &st, &d));
    assert_implemented();

    double tan_h = tan(deg_to_rad(ctx.camera.hfov * 0.5f)), tan_v = tan(deg_to_rad(ctx.camera.vfov * 0.5f));
    image want_img;
    assert_int_equal(PL_OK, image_alloc(&want_img, o.width, o.height));
    int wrong = 0, first_x = -1, first_y = -1;
    for (int y = 0; y < o.height; y++)
        for (int x = 0; x < o.width; x++) {
            rgb want = oracle_normal((x + 0.5) / o.width, (y + 0.5) / o.height, tan_h, tan_v);
            rgb got = image_get(&img, x, o.height - 1 - y);
            image_set(&want_img, x, o.height - 1 - y, want);
            if (fabsf(want.r - got.r) + fabsf(want.g - got.g) + fabsf(want.b - got.b) > 3e-3f) {
                if (wrong++ == 0) first_x = x, first_y = y;
            }
        }
    /* Silhouette pixels may flip between hit and miss by rounding; a handful at most. */
    if (wrong > 4) {
        mkdir("build", 0777);
        mkdir("build/test-output", 0777);
        pl_diag quiet = pl_diag_default();
        image_write_png(&img, "build/test-output/part1_normals_yours.png", &quiet);
        image_write_png(&want_img, "build/test-output/part1_normals_expected.png", &quiet);
        fail_msg("wrong: %d of %d pixels differ from the expected normal image (first at x=%d y=%d from the bottom-left);\n"
                 "  pictures: build/test-output/part1_normals_yours.png and build/test-output/part1_normals_expected.png",
                 wrong, o.width * o.height, first_x, first_y);
    }
    image_free(&want_img);
    image_free(&img);
    accel_free(&a);
    scene_free(&s);
}

int pixel_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_pixel_sample_ray__centre_of_the_pixel, test_setup),
        cmocka_unit_test_setup(test_pixel_sample_ray__u_spans_the_pixel, test_setup),
        cmocka_unit_test_setup(test_pixel_loop__one_sample_goes_through_the_centre, test_setup),
        cmocka_unit_test_setup(test_pixel_loop__samples_cover_the_pixel_uniformly_in_x, test_setup),
        cmocka_unit_test_setup(test_pixel_loop__samples_cover_the_pixel_uniformly_in_y, test_setup),
        cmocka_unit_test_setup(test_pixel_loop__corner_quarter, test_setup),
        cmocka_unit_test_setup(test_render__normal_image_matches_oracle, test_setup),
    };
    return cmocka_run_group_tests_name("part1: pixel_sample_ray (task 1.4), the pixel loop and whole renders", tests, NULL, NULL);
}
