/* Test machinery: not part of any assignment.
 * Part 9, the thin lens. Task 9.1 (lens_sample_disk): every point inside the unit disc, and the
 * points uniform in area (Pearson's chi-square over 8 rings of equal area x 16 sectors). Task 9.2
 * (thin_lens_ray), on a camera turned and moved away from the origin, for film points from the
 * centre to the corners: a radius of 0 gives the pinhole ray; every lens ray starts in the camera's
 * own XY plane and passes through the point where the pinhole ray meets the plane of focus, the
 * closed form that makes that plane sharp; and its lens point is the one the contract names, R
 * lens_sample_disk(u) in the camera's X and Y. That last check compares each ray with what the
 * solution's own lens_sample_disk returns for the same u, right or wrong: task 9.2 calls task 9.1 in
 * the same file, so no test can give it the course's disc, but judged this way a bug of 9.1 (a
 * half disc, a disc of the wrong radius) costs 9.2 nothing, and 9.1's own tests name it. Nothing
 * depends on which mapping of the square to the disc a solution uses (polar with sqrt,
 * Shirley-Chiu's concentric map, ...), nor on the order of its draws: each u is checked for its
 * own ray, and the disc as a whole only through the distribution.
 * alpha: one statistical check, at PART9_CHECK_ALPHA (family alpha 1e-3 and budget: part9_alpha.h).
 * Seeds are fixed, printed, and changed by PL_TEST_SEED (mc_seed). */
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

/* Fails unless p (from u) lies in the unit disc; returns its cell. */
static int disc_cell(vec2 u, vec2 p)
{
    double r2 = (double)p.x * p.x + (double)p.y * p.y;
    if (!(r2 <= 1.0 + RIM_SLACK))
        PL_FAIL("wrong: lens_sample_disk for u = (%.6f, %.6f) gave the lens point (%g, %g), at %g of the radius: outside "
                "the disc%s", (double)u.x, (double)u.y, (double)p.x, (double)p.y, sqrt(r2),
                fabs(p.x) <= 1.0f + 1e-6f && fabs(p.y) <= 1.0f + 1e-6f
                    ? " (inside the square [-1, 1]^2: a square lens has corners the disc has not; handout/part9.md, 9.1)"
                    : " (handout/part9.md, 9.1)");
    int ring = (int)(r2 * RINGS);
    double angle = atan2(p.y, p.x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    int sector = (int)(angle / (2.0 * M_PI) * SECTORS);
    return (ring < RINGS ? ring : RINGS - 1) * SECTORS + (sector < SECTORS ? sector : SECTORS - 1);
}

/* The cells' counts summed by ring and by sector. */
typedef struct { double ring[RINGS], sector[SECTORS]; int empty_cells; } disc_counts;

static disc_counts count_disc(const double *observed)
{
    disc_counts n;
    memset(&n, 0, sizeof n);
    for (int i = 0; i < RINGS; i++)
        for (int j = 0; j < SECTORS; j++) {
            n.ring[i] += observed[i * SECTORS + j], n.sector[j] += observed[i * SECTORS + j];
            n.empty_cells += observed[i * SECTORS + j] == 0.0;
        }
    return n;
}

/* A hint only where the counts point to one mistake; "" otherwise. Each pattern is one no correct
 * disc comes near: about 1000 points per cell, so no empty cell and no ring or sector 10% off. */
static const char *disc_hint(const disc_counts *n)
{
    const double per_ring = DISC_SAMPLES / RINGS, per_sector = DISC_SAMPLES / SECTORS;
    double outer = 0.0, upper_half = 0.0, lower_half = 0.0, ring_spread = 0.0, sector_spread = 0.0;
    for (int i = 2; i < RINGS; i++) outer += n->ring[i];  /* r^2 >= 1/4: beyond half the radius */
    for (int j = 0; j < SECTORS; j++) *(j < SECTORS / 2 ? &upper_half : &lower_half) += n->sector[j];
    for (int i = 0; i < RINGS; i++) ring_spread = fmax(ring_spread, fabs(n->ring[i] / per_ring - 1.0));
    for (int j = 0; j < SECTORS; j++) sector_spread = fmax(sector_spread, fabs(n->sector[j] / per_sector - 1.0));
    if (outer == 0.0)
        return "\n  Every point lies within half the radius (the rings from the third on are empty): the disc is half "
               "the size it should be. Is the radius halved, or the unit disc's diameter taken for its radius? (its "
               "radius is 1; handout/part9.md, 9.1)";
    if (upper_half == 0.0 || lower_half == 0.0)
        return "\n  Every point lies in one half of the disc (the other half's sectors are empty): the angle covers pi, "
               "not 2 pi. Is it pi u.y rather than 2 pi u.y? (handout/part9.md, 9.1)";
    if (n->empty_cells > CELLS / 2)
        return "\n  Most cells get no point at all, so the points lie on a curve, not over the disc: its two coordinates "
               "come from one number. Is one of u.x and u.y used for both the radius and the angle? (handout/part9.md, "
               "9.1)";
    if (n->ring[0] > 1.1 * per_ring && n->ring[RINGS - 1] < 0.9 * per_ring)
        return "\n  More near the centre than the rim: is the radius u.x rather than sqrt(u.x)? (a ring's share of the "
               "area grows with its radius; handout/part9.md, 9.1)";
    if (n->ring[0] < 0.9 * per_ring && n->ring[RINGS - 1] > 1.1 * per_ring)
        return "\n  More near the rim than the centre: the radius grows too slowly with u.x (the area within radius r is "
               "r^2 of the disc's; handout/part9.md, 9.1)";
    if (sector_spread > 0.1 && ring_spread <= 0.1)
        return "\n  Some directions get more points than others: is the angle 2 pi u.y? (handout/part9.md, 9.1)";
    return "";
}

/* DISC_SAMPLES points of lens_sample_disk(u), u uniform from rng_seeded(seed, 0): each in the unit
 * disc, and uniform over it at level alpha. On failure, the counts by ring and by sector, and what
 * they point to. */
static void check_uniform_disc(uint64_t seed, double alpha)
{
    static double observed[CELLS], expected[CELLS];
    memset(observed, 0, sizeof observed);
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < DISC_SAMPLES; i++) {
        vec2 u = rng_uniform2(&g);
        vec2 p = lens_sample_disk(u);
        if (i == 0) assert_implemented();
        observed[disc_cell(u, p)] += 1.0;
    }
    for (int k = 0; k < CELLS; k++) expected[k] = (double)DISC_SAMPLES / CELLS;
    stats_result res = stats_chi2_test(observed, expected, CELLS, 5.0, alpha);
    if (!res.reject) return;
    disc_counts n = count_disc(observed);
    char rings[512] = "", sectors[512] = "";
    for (int i = 0; i < RINGS; i++) snprintf(rings + strlen(rings), sizeof rings - strlen(rings), " %.0f", n.ring[i]);
    for (int j = 0; j < SECTORS; j++)
        snprintf(sectors + strlen(sectors), sizeof sectors - strlen(sectors), " %.0f", n.sector[j]);
    mc_print_seed("lens_sample_disk", seed);
    PL_FAIL("wrong: lens_sample_disk's points are not uniform over the disc (chi-square %.1f with %.0f dof, p = %.3g < "
            "alpha %.3g; task 9.1).\n"
            "  Points in each of %d rings of equal area, the centre's first (%d each if uniform):%s\n"
            "  Points in each of %d sectors, counter-clockwise from +X (%d each if uniform):%s%s",
            res.stat, res.dof, res.p, alpha, RINGS, DISC_SAMPLES / RINGS, rings, SECTORS, DISC_SAMPLES / SECTORS,
            sectors, disc_hint(&n));
}

/* ---- task 9.1: lens_sample_disk ------------------------------------------------------------------ */

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
            disc_cell(u, p);
        }
}

static void test_lens_sample_disk__is_uniform_in_area(void **state)
{
    (void)state;
    check_uniform_disc(SEED + 1, PART9_CHECK_ALPHA);
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

/* Every lens ray: unit direction, the pinhole's [min_t, max_t], its origin in the camera's XY plane
 * and through the pinhole ray's point on the plane of focus. Where on the lens it starts is the next
 * test's. */
static void test_thin_lens_ray__starts_in_the_lens_plane_and_meets_the_plane_of_focus(void **state)
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
            if (!(fabsf(off_plane) <= 1e-5f * (1.0f + vec3_length(c.position))))
                PL_FAIL("wrong: for film point (%g, %g) and u = (%.6f, %.6f) the ray starts at (%g, %g, %g), %g from the "
                        "camera's position along its view axis: the lens is a disc around the position in the camera's "
                        "own X and Y (camera_to_world's, not the world's), so every lens point is 0 along the view axis "
                        "(task 9.2, handout/part9.md)", FILM[f][0], FILM[f][1], (double)u.x, (double)u.y, (double)r.o.x,
                        (double)r.o.y, (double)r.o.z, (double)off_plane);
            /* Where the lens ray passes nearest the sharp point, and how far from it. */
            vec3 to_sharp = vec3_sub(sharp, r.o), to_sphere = vec3_sub(on_sphere, r.o);
            float along = vec3_dot(to_sharp, r.d);
            float miss = vec3_length(vec3_sub(to_sharp, vec3_scale(r.d, along)));
            float sphere_miss = vec3_length(vec3_sub(to_sphere, vec3_scale(r.d, vec3_dot(to_sphere, r.d))));
            if (!(along > 0.0f) || !(miss <= 2e-5f * vec3_length(to_sharp)))
                PL_FAIL("wrong: for film point (%g, %g) and u = (%.6f, %.6f) the lens ray misses the pinhole ray's point on "
                        "the plane of focus, (%g, %g, %g), by %g m%s; every lens ray of a film point must pass through "
                        "it (the plane z = -D of camera space, D = focal_distance = %g; task 9.2, handout/part9.md)",
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

/* The camera's axes in the world, for reading a lens point. */
typedef struct { camera c; vec3 x, y; } lens_axes;

/* What an offset from the camera's position is, when it is not R p in the camera's X and Y: the
 * usual mistakes, each known by the offset it gives. "" when none fits. */
static const char *offset_hint(const lens_axes *l, vec2 p, vec3 got, float tol)
{
    float R = l->c.lens_radius;
    vec3 want = vec3_add(vec3_scale(l->x, R * p.x), vec3_scale(l->y, R * p.y));
    struct { vec3 offset; const char *says; } usual[] = {
        {vec3_scale(want, 0.5f), " (half of it: a lens radius read as a diameter; lens_radius is the radius, R, not twice "
                                 "it)"},
        {vec3_scale(want, 2.0f), " (twice it: lens_radius is the lens's radius already)"},
        {vec3_make(R * p.x, R * p.y, 0.0f), " (this is R p along the world's X and Y: turn it into the camera's with "
                                            "mat4_dir(camera_to_world, ...))"},
        {vec3_make(0.0f, 0.0f, 0.0f), " (the ray starts at the camera's position itself: no lens point)"},
    };
    for (size_t i = 0; i < sizeof usual / sizeof usual[0]; i++)
        if (vec3_length(vec3_sub(got, usual[i].offset)) <= tol) return usual[i].says;
    return "";
}

/* The lens point of each ray is R lens_sample_disk(u) in the camera's X and Y, with the disc this
 * very solution's 9.1 gives for u: so a disc that is wrong in 9.1 is 9.1's alone. */
static void test_thin_lens_ray__starts_at_its_lens_point_in_the_camera_plane(void **state)
{
    (void)state;
    lens_axes l;
    l.c = lens_camera(0.25f, 3.0f);
    l.x = mat4_dir(l.c.camera_to_world, vec3_make(1, 0, 0));
    l.y = mat4_dir(l.c.camera_to_world, vec3_make(0, 1, 0));
    /* Float rounding of a point 5.5 m from the origin, with room: far below any lens point's error. */
    const float tol = 1e-5f * (1.0f + vec3_length(l.c.position));
    rng g = rng_seeded(SEED + 4, 0);
    for (int f = 0; f < NUM_FILM; f++) {
        ray pinhole = pinhole_ray(&l.c, FILM[f][0], FILM[f][1]);
        for (int i = 0; i < 200; i++) {
            vec2 u = rng_uniform2(&g);
            vec2 p = lens_sample_disk(u);  /* task 9.1's point for u, right or wrong */
            ray r = thin_lens_ray(&l.c, pinhole, u);
            assert_implemented();
            if (!isfinite(p.x) || !isfinite(p.y)) continue;  /* no lens point to compare with: 9.1's tests say so */
            float R = l.c.lens_radius;
            vec3 want = vec3_add(vec3_scale(l.x, R * p.x), vec3_scale(l.y, R * p.y)), got = vec3_sub(r.o, l.c.position);
            if (!(vec3_length(vec3_sub(got, want)) <= tol))
                PL_FAIL("wrong: for u = (%.6f, %.6f), lens_sample_disk gives p = (%g, %g), so the lens ray must start at "
                        "the camera's position + R (p.x X + p.y Y) = (%g, %g, %g) off it (R = lens_radius = %g, X and Y "
                        "the camera's axes); thin_lens_ray's starts (%g, %g, %g) off it%s (task 9.2, handout/part9.md; "
                        "its disc is your task 9.1's, whatever that gives)", (double)u.x, (double)u.y, (double)p.x,
                        (double)p.y, (double)want.x, (double)want.y, (double)want.z, (double)R, (double)got.x,
                        (double)got.y, (double)got.z, offset_hint(&l, p, got, tol));
        }
    }
}

int lens_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_lens_sample_disk__stays_in_the_unit_disc, test_setup),
        cmocka_unit_test_setup(test_lens_sample_disk__is_uniform_in_area, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__zero_radius_is_the_pinhole_ray, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__starts_in_the_lens_plane_and_meets_the_plane_of_focus, test_setup),
        cmocka_unit_test_setup(test_thin_lens_ray__starts_at_its_lens_point_in_the_camera_plane, test_setup),
    };
    return cmocka_run_group_tests_name("part9: lens_sample_disk (task 9.1) and thin_lens_ray (task 9.2)", tests, NULL, NULL);
}
