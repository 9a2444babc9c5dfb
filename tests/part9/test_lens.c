/* Test machinery: not part of any assignment.
 * Part 9, the thin lens. Task 9.1 (lens_sample_disk): every point inside the unit disc, and the
 * points uniform in area (Pearson's chi-square over 8 rings of equal area x 16 sectors). Task 9.2
 * (thin_lens_ray), on a camera turned and moved away from the origin, for film points from the
 * centre to the corners: a radius of 0 gives the pinhole ray; every lens ray starts on the lens
 * (in the camera's own XY plane, within its radius) and passes through the point where the
 * pinhole ray meets the plane of focus, the closed form that makes that plane sharp; and the
 * lens points are uniform over the lens (the same chi-square). Nothing depends on which mapping of
 * the square to the disc a solution uses (polar with sqrt, Shirley-Chiu's concentric map, ...),
 * nor on the order of its draws: each u is checked for its own ray, and the disc as a whole only
 * through the distribution.
 * alpha: two statistical checks, each at PART9_CHECK_ALPHA (family alpha 1e-3 and budget:
 * part9_alpha.h). Seeds are fixed, printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "part9_alpha.h"
#include "../../parts/part9_lens/part9.h"

#define SEED mc_seed(0x5eed9001ull)

/* ---- the disc's cells: rings of equal area (r^2 in [i/8, (i+1)/8)) by sectors of equal angle ---- */
#define RINGS 8
#define SECTORS 16
#define CELLS (RINGS * SECTORS)
#define DISC_SAMPLES (CELLS * 1000)
/* How far past the unit circle a point may lie: float rounding of a point on the rim, no more. */
#define RIM_SLACK 4e-6

typedef vec2 (*disc_sampler)(void *user, vec2 u);

/* Fails unless p (from u) lies in the unit disc; returns its cell. */
static int disc_cell(const char *name, vec2 u, vec2 p)
{
    double r2 = (double)p.x * p.x + (double)p.y * p.y;
    if (!(r2 <= 1.0 + RIM_SLACK))
        PL_FAIL("wrong: %s for u = (%.6f, %.6f) gave the lens point (%g, %g), at %g of the radius: outside the "
                "disc%s", name, (double)u.x, (double)u.y, (double)p.x, (double)p.y, sqrt(r2),
                fabs(p.x) <= 1.0f + 1e-6f && fabs(p.y) <= 1.0f + 1e-6f
                    ? " (inside the square [-1, 1]^2: a square lens has corners the disc has not; handout/part9.md, 9.1)" : "");
    int ring = (int)(r2 * RINGS);
    double angle = atan2(p.y, p.x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    int sector = (int)(angle / (2.0 * M_PI) * SECTORS);
    return (ring < RINGS ? ring : RINGS - 1) * SECTORS + (sector < SECTORS ? sector : SECTORS - 1);
}

/* DISC_SAMPLES points of sample(u), u uniform from rng_seeded(seed, 0): each in the unit disc, and
 * uniform over it at level alpha. On failure, the counts by ring (the usual mistake: r = u.x crowds
 * the centre) and by sector. */
static void check_uniform_disc(const char *name, disc_sampler sample, void *user, uint64_t seed, double alpha)
{
    static double observed[CELLS], expected[CELLS];
    memset(observed, 0, sizeof observed);
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < DISC_SAMPLES; i++) {
        vec2 u = rng_uniform2(&g);
        vec2 p = sample(user, u);
        if (i == 0) assert_implemented();
        observed[disc_cell(name, u, p)] += 1.0;
    }
    for (int k = 0; k < CELLS; k++) expected[k] = (double)DISC_SAMPLES / CELLS;
    stats_result res = stats_chi2_test(observed, expected, CELLS, 5.0, alpha);
    if (!res.reject) return;
    /* The counts by ring and by sector, and a hint only where the counts point to one. */
    char rings[512] = "", sectors[512] = "";
    double ring_count[RINGS] = {0}, sector_spread = 0.0;
    for (int i = 0; i < RINGS; i++) {
        for (int j = 0; j < SECTORS; j++) ring_count[i] += observed[i * SECTORS + j];
        snprintf(rings + strlen(rings), sizeof rings - strlen(rings), " %.0f", ring_count[i]);
    }
    for (int j = 0; j < SECTORS; j++) {
        double n = 0.0;
        for (int i = 0; i < RINGS; i++) n += observed[i * SECTORS + j];
        snprintf(sectors + strlen(sectors), sizeof sectors - strlen(sectors), " %.0f", n);
        sector_spread = fmax(sector_spread, fabs(n / (DISC_SAMPLES / SECTORS) - 1.0));
    }
    const double per_ring = DISC_SAMPLES / RINGS;
    const char *hint = ring_count[0] > 1.1 * per_ring && ring_count[RINGS - 1] < 0.9 * per_ring
                           ? "\n  More near the centre than the rim: is the radius u.x rather than sqrt(u.x)? (a ring's share "
                             "of the area grows with its radius; handout/part9.md, 9.1)"
                       : ring_count[0] < 0.9 * per_ring && ring_count[RINGS - 1] > 1.1 * per_ring
                           ? "\n  More near the rim than the centre: the radius grows too slowly with u.x (the area within "
                             "radius r is r^2 of the disc's; handout/part9.md, 9.1)"
                       : sector_spread > 0.1 ? "\n  Some directions get more points than others: is the angle 2 pi u.y? "
                                               "(handout/part9.md, 9.1)"
                                             : "";
    mc_print_seed(name, seed);
    PL_FAIL("wrong: %s's points are not uniform over the disc (chi-square %.1f with %.0f dof, p = %.3g < alpha %.3g).\n"
            "  Points in each of %d rings of equal area, the centre's first (%d each if uniform):%s\n"
            "  Points in each of %d sectors, counter-clockwise from +X (%d each if uniform):%s%s",
            name, res.stat, res.dof, res.p, alpha, RINGS, DISC_SAMPLES / RINGS, rings, SECTORS, DISC_SAMPLES / SECTORS,
            sectors, hint);
}

/* ---- task 9.1: lens_sample_disk ------------------------------------------------------------------ */
static vec2 disk_sample(void *user, vec2 u) { (void)user; return lens_sample_disk(u); }

static void test_lens_sample_disk__stays_in_the_unit_disc(void **state)
{
    (void)state;
    /* A grid over the square, its far edges as close to 1 as a float gets below it. */
    const float top = nextafterf(1.0f, 0.0f);
    for (int i = 0; i <= 32; i++)
        for (int j = 0; j <= 32; j++) {
            vec2 u = vec2_make(i == 32 ? top : i / 32.0f, j == 32 ? top : j / 32.0f);
            vec2 p = lens_sample_disk(u);
            assert_implemented();
            disc_cell("lens_sample_disk", u, p);
        }
}

static void test_lens_sample_disk__is_uniform_in_area(void **state)
{
    (void)state;
    check_uniform_disc("lens_sample_disk", disk_sample, NULL, SEED + 1, PART9_CHECK_ALPHA);
}

/* ---- task 9.2: thin_lens_ray ------------------------------------------------------------------ */

/* A camera turned 70 degrees about a slanted axis, 5.5 m from the origin: a lens in world X and Y,
 * or a lens at the origin, is off this one's plane. */
static camera lens_camera(float radius, float focal_distance)
{
    camera c;
    memset(&c, 0, sizeof c);
    c.camera_to_world = mat4_mul(mat4_translate(vec3_make(5.0f, 1.0f, -2.0f)), mat4_rotate(vec3_make(0.3f, 1.0f, 0.2f), 70.0f));
    c.position = mat4_point(c.camera_to_world, vec3_make(0, 0, 0));
    c.hfov = 70.0f;
    c.vfov = 55.0f;
    c.znear = 0.01f;
    c.zfar = 100.0f;
    c.lens_radius = radius;
    c.focal_distance = focal_distance;
    return c;
}

/* The pinhole ray through film point (x, y), made here (part 1's task, not part 9's). */
static ray pinhole_ray(const camera *c, float x, float y)
{
    vec3 sensor = vec3_make(tanf(deg_to_rad(0.5f * c->hfov)) * (2.0f * x - 1.0f),
                            tanf(deg_to_rad(0.5f * c->vfov)) * (2.0f * y - 1.0f), -1.0f);
    return ray_make(c->position, vec3_normalize(mat4_dir(c->camera_to_world, sensor)), c->znear, c->zfar);
}

/* The centre, the four corners and two points between: rays from 0 to 40 degrees off the axis. */
static const float FILM[][2] = {{0.5f, 0.5f}, {0.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}, {1.0f, 0.0f}, {0.9f, 0.2f}, {0.13f, 0.77f}};
#define NUM_FILM (int)(sizeof FILM / sizeof FILM[0])

static void test_thin_lens_ray__zero_radius_is_the_pinhole_ray(void **state)
{
    (void)state;
    camera c = lens_camera(0.0f, 2.5f);
    rng g = rng_seeded(SEED + 2, 0);
    for (int f = 0; f < NUM_FILM; f++) {
        ray pinhole = pinhole_ray(&c, FILM[f][0], FILM[f][1]);
        ray r = thin_lens_ray(&c, pinhole, rng_uniform2(&g));
        assert_implemented();
        assert_vec3_near(pinhole.o, r.o, 1e-5f);
        assert_vec3_near(pinhole.d, r.d, 1e-5f);
    }
}

/* Every lens ray: unit direction, the pinhole's [min_t, max_t], its origin on the lens (in the
 * camera's XY plane, within the radius) and through the pinhole ray's point on the plane of focus. */
static void test_thin_lens_ray__starts_on_the_lens_and_meets_the_plane_of_focus(void **state)
{
    (void)state;
    const float radius = 0.3f, focus = 2.5f;
    camera c = lens_camera(radius, focus);
    vec3 forward = mat4_dir(c.camera_to_world, vec3_make(0, 0, -1));
    rng g = rng_seeded(SEED + 3, 0);
    for (int f = 0; f < NUM_FILM; f++) {
        ray pinhole = pinhole_ray(&c, FILM[f][0], FILM[f][1]);
        float cos_theta = vec3_dot(pinhole.d, forward);
        vec3 sharp = ray_at(&pinhole, focus / cos_theta);   /* on the plane z = -D of camera space */
        vec3 on_sphere = ray_at(&pinhole, focus);              /* at distance D along the ray: not it */
        for (int i = 0; i < 200; i++) {
            vec2 u = rng_uniform2(&g);
            ray r = thin_lens_ray(&c, pinhole, u);
            assert_implemented();
            assert_float_near(1.0, vec3_length(r.d), 1e-5);
            assert_float_near(pinhole.min_t, r.min_t, 1e-6 * pinhole.min_t);
            assert_float_near(pinhole.max_t, r.max_t, 1e-6 * pinhole.max_t);
            vec3 offset = vec3_sub(r.o, c.position);
            float off_plane = vec3_dot(offset, forward);
            if (!(fabsf(off_plane) <= 1e-5f * (1.0f + vec3_length(c.position))) || !(vec3_length(offset) <= radius * (1.0f + 1e-5f)))
                PL_FAIL("wrong: for film point (%g, %g) and u = (%.6f, %.6f) the ray starts at (%g, %g, %g), %g from the "
                        "camera's position along its view axis and %g from it in all: the lens is the disc of radius %g "
                        "around the position in the camera's own X and Y (camera_to_world's, not the world's), "
                        "handout/part9.md, 9.2", FILM[f][0], FILM[f][1], (double)u.x, (double)u.y, (double)r.o.x,
                        (double)r.o.y, (double)r.o.z, (double)off_plane, (double)vec3_length(offset), (double)radius);
            /* Where the lens ray passes nearest the sharp point, and how far from it. */
            vec3 to_sharp = vec3_sub(sharp, r.o), to_sphere = vec3_sub(on_sphere, r.o);
            float along = vec3_dot(to_sharp, r.d);
            float miss = vec3_length(vec3_sub(to_sharp, vec3_scale(r.d, along)));
            float sphere_miss = vec3_length(vec3_sub(to_sphere, vec3_scale(r.d, vec3_dot(to_sphere, r.d))));
            if (!(along > 0.0f) || !(miss <= 2e-5f * vec3_length(to_sharp)))
                PL_FAIL("wrong: for film point (%g, %g) and u = (%.6f, %.6f) the lens ray misses the pinhole ray's point on "
                        "the plane of focus, (%g, %g, %g), by %g m%s; every lens ray of a film point must pass through "
                        "it (the plane z = -D of camera space, D = focal_distance = %g), handout/part9.md, 9.2",
                        FILM[f][0], FILM[f][1], (double)u.x, (double)u.y, (double)sharp.x, (double)sharp.y, (double)sharp.z,
                        (double)miss,
                        sphere_miss <= 2e-5f * vec3_length(to_sphere) && f > 0
                            ? ": it passes through the point at distance D ALONG the pinhole ray instead, which is sharp "
                              "on a sphere, not on a plane (D / cos theta along an off-centre ray)"
                            : along > 0.0f ? "" : " (it points away from it)",
                        (double)focus);
        }
    }
}

/* The lens point of a thin_lens_ray, as a point of the unit disc: (offset . X, offset . Y) / R. */
typedef struct { camera c; ray pinhole; vec3 x, y; } lens_fixture;
static vec2 lens_point(void *user, vec2 u)
{
    const lens_fixture *l = user;
    vec3 offset = vec3_sub(thin_lens_ray(&l->c, l->pinhole, u).o, l->c.position);
    return vec2_make(vec3_dot(offset, l->x) / l->c.lens_radius, vec3_dot(offset, l->y) / l->c.lens_radius);
}

static void test_thin_lens_ray__lens_points_are_uniform_over_the_lens(void **state)
{
    (void)state;
    lens_fixture l;
    l.c = lens_camera(0.25f, 3.0f);
    l.pinhole = pinhole_ray(&l.c, 0.3f, 0.6f);
    l.x = mat4_dir(l.c.camera_to_world, vec3_make(1, 0, 0));
    l.y = mat4_dir(l.c.camera_to_world, vec3_make(0, 1, 0));
    check_uniform_disc("thin_lens_ray (its lens point over the radius)", lens_point, &l, SEED + 4, PART9_CHECK_ALPHA);
}

int lens_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_lens_sample_disk__stays_in_the_unit_disc, test_setup),
        cmocka_unit_test_setup(test_lens_sample_disk__is_uniform_in_area, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__zero_radius_is_the_pinhole_ray, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__starts_on_the_lens_and_meets_the_plane_of_focus, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__lens_points_are_uniform_over_the_lens, test_setup),
    };
    return cmocka_run_group_tests_name("part9: lens_sample_disk (task 9.1) and thin_lens_ray (task 9.2)", tests, NULL, NULL);
}
