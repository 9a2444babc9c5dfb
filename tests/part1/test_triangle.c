/* Test machinery: not part of any assignment. Task 1.2: ray-triangle hits at known t and barycentrics. */
/* Hits start zeroed: with the task still a stub, link-time optimisation otherwise warns that a
 * check reads fields the stub never wrote (the check has failed by then; the compiler cannot tell). */
#include "../common/test.h"
#include "../../parts/part1_raygen/part1.h"
#include <math.h>
#include <string.h>

/* The triangle (0,0,0) (1,0,0) (0,1,0) in the plane z = 0, with distinct vertex normals. */
static triangle unit_triangle(void)
{
    triangle t = triangle_make(vec3_make(0, 0, 0), vec3_make(1, 0, 0), vec3_make(0, 1, 0), 0);
    t.n0 = vec3_make(0, 0, 1);
    t.n1 = vec3_normalize(vec3_make(1, 0, 1));
    t.n2 = vec3_normalize(vec3_make(0, 1, 1));
    return t;
}

/* A ray straight down -z onto the point (x, y, 0) from height 2. */
static ray down_onto(float x, float y)
{
    return ray_make(vec3_make(x, y, 2), vec3_make(0, 0, -1), 0.0f, INFINITY);
}

static void test_triangle_intersect__hit_at_known_t_and_barycentrics(void **state)
{
    triangle t = unit_triangle();
    ray r = down_onto(0.25f, 0.5f);
    hit h = {0};
    bool found = triangle_intersect(&t, &r, &h);
    assert_implemented();
    if (!found) PL_FAIL("wrong: a ray straight down onto (0.25, 0.5, 0), inside the triangle, missed it; expected a hit");
    assert_float_near(2.0, h.t, 1e-6);
    assert_float_near(0.25, h.b1, 1e-6);
    assert_float_near(0.5, h.b2, 1e-6);
    assert_float_near(2.0, r.max_t, 1e-6);  /* the ray's interval shrinks to the hit */
}

static void test_triangle_intersect__normal_is_normalised_barycentric_blend(void **state)
{
    triangle t = unit_triangle();
    ray r = down_onto(0.25f, 0.5f);
    hit h = {0};
    assert_hit(triangle_intersect(&t, &r, &h));
    assert_implemented();
    vec3 expected = vec3_normalize(vec3_add(vec3_add(vec3_scale(t.n0, 0.25f), vec3_scale(t.n1, 0.25f)), vec3_scale(t.n2, 0.5f)));
    assert_vec3_near(expected, h.n, 1e-5f);
}

static void test_triangle_intersect__misses_outside(void **state)
{
    triangle t = unit_triangle();
    float outside[][2] = {{0.6f, 0.6f}, {-0.1f, 0.5f}, {0.5f, -0.1f}, {2, 2}, {-1, -1}};
    for (size_t i = 0; i < sizeof outside / sizeof outside[0]; i++) {
        ray r = down_onto(outside[i][0], outside[i][1]);
        hit h = {0};
        h.t = -7.0f;
        bool found = triangle_intersect(&t, &r, &h);
        assert_implemented();
        if (found) fail_msg("wrong: ray onto (%g, %g, 0) hit the triangle, expected a miss", outside[i][0], outside[i][1]);
        if (!isinf(r.max_t))  /* a miss leaves the ray alone */
            PL_FAIL("wrong: a ray that missed the triangle (onto (%g, %g, 0)) came back with max_t = %g; a miss leaves "
                    "the ray as it was (max_t = inf)", outside[i][0], outside[i][1], r.max_t);
        assert_float_near(-7.0, h.t, 0);          /* ... and the hit record */
    }
}

static void test_triangle_intersect__edges_and_vertices_count(void **state)
{
    triangle t = unit_triangle();
    float on_boundary[][2] = {{0.5f, 0.0f}, {0.0f, 0.5f}, {0.5f, 0.5f}, {0, 0}, {1, 0}, {0, 1}};
    for (size_t i = 0; i < sizeof on_boundary / sizeof on_boundary[0]; i++) {
        ray r = down_onto(on_boundary[i][0], on_boundary[i][1]);
        hit h = {0};
        bool found = triangle_intersect(&t, &r, &h);
        assert_implemented();
        if (!found) fail_msg("wrong: ray onto (%g, %g, 0), on the boundary, missed", on_boundary[i][0], on_boundary[i][1]);
    }
}

static void test_triangle_intersect__parallel_ray_misses(void **state)
{
    triangle t = unit_triangle();
    ray r = ray_make(vec3_make(-1, 0.2f, 0), vec3_make(1, 0, 0), 0.0f, INFINITY);  /* in the plane */
    hit h = {0};
    assert_miss(triangle_intersect(&t, &r, &h));
    assert_implemented();
    r = ray_make(vec3_make(-1, 0.2f, 1), vec3_make(1, 0, 0), 0.0f, INFINITY);      /* above the plane */
    assert_miss(triangle_intersect(&t, &r, &h));
}

static void test_triangle_intersect__respects_min_t_and_max_t(void **state)
{
    triangle t = unit_triangle();
    hit h = {0};
    ray r = down_onto(0.2f, 0.2f);
    r.max_t = 1.5f;  /* the hit at t = 2 is beyond max_t */
    assert_miss(triangle_intersect(&t, &r, &h));
    assert_implemented();
    r = down_onto(0.2f, 0.2f);
    r.min_t = 2.5f;  /* ... or before min_t */
    assert_miss(triangle_intersect(&t, &r, &h));
    r = ray_make(vec3_make(0.2f, 0.2f, -1), vec3_make(0, 0, -1), 0.0f, INFINITY);  /* behind the origin */
    assert_miss(triangle_intersect(&t, &r, &h));
    r = down_onto(0.2f, 0.2f);
    r.max_t = 2.0f;  /* exactly at max_t: inclusive */
    assert_hit(triangle_intersect(&t, &r, &h));
}

static void test_triangle_intersect__hit_from_behind_counts(void **state)
{
    /* Triangles are two-sided for intersection: shading decides what a back face means. */
    triangle t = unit_triangle();
    ray r = ray_make(vec3_make(0.2f, 0.2f, -3), vec3_make(0, 0, 1), 0.0f, INFINITY);
    hit h = {0};
    assert_hit(triangle_intersect(&t, &r, &h));
    assert_implemented();
    assert_float_near(3.0, h.t, 1e-6);
}

static void test_triangle_intersect__nearer_of_two_wins(void **state)
{
    triangle far = unit_triangle(), near = unit_triangle();
    near.p0.z = near.p1.z = near.p2.z = 1.0f;
    ray r = down_onto(0.2f, 0.2f);
    hit h = {0};
    assert_hit(triangle_intersect(&far, &r, &h));
    assert_hit(triangle_intersect(&near, &r, &h));
    assert_implemented();
    assert_float_near(1.0, h.t, 1e-6);
    assert_miss(triangle_intersect(&far, &r, &h));  /* now farther than max_t */
    assert_float_near(1.0, h.t, 1e-6);
}

static void test_triangle_intersect__degenerate_triangle_never_hits(void **state)
{
    triangle t = triangle_make(vec3_make(0, 0, 0), vec3_make(1, 1, 0), vec3_make(2, 2, 0), 0);
    ray r = down_onto(1, 1);
    hit h = {0};
    bool found = triangle_intersect(&t, &r, &h);
    assert_implemented();
    if (found) PL_FAIL("wrong: a degenerate triangle (three points on a line) was hit; expected a miss (no area, no hit)");
}

/* ---- precision: small triangles, far from the world origin, and near-parallel rays ---------------
 * A float routine is only as exact as its inputs: its answer is the exact answer for a ray moved by
 * about eps |p - o| (eps = 6e-8) and turned by about eps, which moves a grazing ray's crossing of the
 * plane by eps |p - o| / cos, cos the cosine between the ray and the normal. So these tests judge
 * each ray by its answer in double precision, and only when the ray is more than
 * PREC_MARGIN + 200 eps |p - o| / (size cos) barycentric units inside or outside the triangle
 * (200 times the rounding a correct Moller-Trumbore, watertight or Pluecker test makes), with the
 * ray origin a few triangle sizes away. A routine that first computes the hit point p = o + t d and
 * then tests p against the edges rounds p to its coordinates' float grid (1e-3 units at 1e4), which
 * is several percent of these triangles: it reports hits for rays that pass beside the triangle,
 * and these tests fail it. */
#define PREC_MARGIN 0.02
#define PREC_RAYS 128

typedef struct { double x, y, z; } dvec3;
static dvec3 dv(vec3 v) { dvec3 d = {v.x, v.y, v.z}; return d; }
static dvec3 dsub(dvec3 a, dvec3 b) { dvec3 d = {a.x - b.x, a.y - b.y, a.z - b.z}; return d; }
static double ddot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec3 dcross(dvec3 a, dvec3 b)
{
    dvec3 d = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return d;
}

/* The ray line's barycentrics (b0 = 1 - b1 - b2) and t on the triangle's plane, in double. */
static void exact_line_hit(const triangle *tri, const ray *r, double *b1, double *b2, double *t)
{
    dvec3 p0 = dv(tri->p0), e1 = dsub(dv(tri->p1), p0), e2 = dsub(dv(tri->p2), p0);
    dvec3 s1 = dcross(dv(r->d), e2), s = dsub(dv(r->o), p0), s2 = dcross(s, e1);
    double det = ddot(e1, s1);
    *b1 = ddot(s, s1) / det;
    *b2 = ddot(dv(r->d), s2) / det;
    *t = ddot(e2, s2) / det;
}

/* A small deterministic generator for the geometry (no statistics depend on it). */
static double prec_uniform(uint64_t *state)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}

static vec3 prec_unit(uint64_t *g)
{
    for (;;) {
        double x = 2 * prec_uniform(g) - 1, y = 2 * prec_uniform(g) - 1, z = 2 * prec_uniform(g) - 1;
        double l = sqrt(x * x + y * y + z * z);
        if (l > 0.1 && l < 1.0) return vec3_make((float)(x / l), (float)(y / l), (float)(z / l));
    }
}

/* One judged ray: the routine's answer must match the exact one whenever the ray is PREC_MARGIN
 * inside or outside; a hit's t must match to 1e-5 of the distance, plus 1e-4 of the triangle's
 * size along the ray (a grazing ray meets the plane at an ill-conditioned t). */
#define check_precise(tri, r, kind, size, where) check_precise_at((tri), (r), (kind), (size), (where), __FILE__, __LINE__)
static void check_precise_at(const triangle *tri, ray r, const char *kind, double size, double where, const char *file,
                             int line)
{
    double b1, b2, t;
    exact_line_hit(tri, &r, &b1, &b2, &t);
    dvec3 n = dcross(dsub(dv(tri->p1), dv(tri->p0)), dsub(dv(tri->p2), dv(tri->p0)));
    double cosine = fabs(ddot(n, dv(r.d))) / sqrt(ddot(n, n) * ddot(dv(r.d), dv(r.d)));
    dvec3 offset = dsub(dv(r.o), dv(tri->p0));
    double margin = PREC_MARGIN + 200 * 6e-8 * sqrt(ddot(offset, offset)) / (size * cosine);
    double inside = fmin(fmin(b1, b2), 1.0 - b1 - b2);  /* > 0 inside, in barycentric units */
    bool in = inside >= margin && t >= r.min_t && t <= r.max_t;
    bool out = inside <= -margin || t < r.min_t || t > r.max_t;
    if (!in && !out) return;  /* too near the boundary to judge */
    hit h;
    h.t = -7.0f;
    bool found = triangle_intersect(tri, &r, &h);
    check_implemented(file, line);
    if (found != in) {
        print_error("wrong: %s: triangle %.2g across at %.2g from the world origin, ray from (%.9g, %.9g, %.9g) "
                    "dir (%.9g, %.9g, %.9g): expected a %s (exact barycentrics b1 = %.4f, b2 = %.4f, plane at "
                    "t = %.6g), got a %s at t = %.9g. %s\n",
                    kind, size, where, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, in ? "hit" : "miss", b1, b2, t,
                    found ? "hit" : "miss", found ? h.t : 0.0,
                    "Is the inside-outside test computed from the hit point o + t d? Its coordinates are rounded to "
                    "their float grid, a few percent of this triangle: test the ray against the edges instead, as "
                    "Moller-Trumbore does.");
        check_fail(file, line);
    }
    if (found && !(fabs(h.t - t) <= 1e-5 * t + 1e-4 * size / cosine)) {
        print_error("wrong: %s: hit at t = %.9g, exactly %.9g (triangle %.2g across at %.2g)\n", kind, h.t, t, size,
                    where);
        check_fail(file, line);
    }
}

/* A triangle `size` across, centred near `where` from the world origin, in a random plane. */
static triangle prec_triangle(uint64_t *g, double where, double size, vec3 *normal)
{
    vec3 c = vec3_scale(prec_unit(g), (float)where);
    vec3 n = prec_unit(g);
    vec3 u = vec3_normalize(vec3_cross(n, prec_unit(g))), v = vec3_cross(n, u);
    float s = (float)size;
    vec3 p0 = vec3_add(c, vec3_scale(u, s * 0.5f));
    vec3 p1 = vec3_add(c, vec3_scale(vec3_add(vec3_scale(u, -0.3f), vec3_scale(v, 0.5f)), s));
    vec3 p2 = vec3_add(c, vec3_scale(vec3_add(vec3_scale(u, -0.2f), vec3_scale(v, -0.5f)), s));
    *normal = n;
    return triangle_make(p0, p1, p2, 0);
}

/* A point with barycentrics (1 - b1 - b2, b1, b2), in float. */
static vec3 prec_point(const triangle *tri, double b1, double b2)
{
    dvec3 p0 = dv(tri->p0), p1 = dv(tri->p1), p2 = dv(tri->p2);
    double b0 = 1.0 - b1 - b2;
    return vec3_make((float)(b0 * p0.x + b1 * p1.x + b2 * p2.x), (float)(b0 * p0.y + b1 * p1.y + b2 * p2.y),
                     (float)(b0 * p0.z + b1 * p1.z + b2 * p2.z));
}

/* Barycentrics for an aim point: every other one anywhere from just outside the triangle to well
 * inside, the others within 0.1 of an edge's line on either side, where rounding decides. */
static void prec_barycentrics(uint64_t *g, int i, double *b1, double *b2)
{
    if (i % 2 == 0) {
        *b1 = -0.3 + 1.6 * prec_uniform(g);
        *b2 = -0.3 + 1.6 * prec_uniform(g);
        return;
    }
    double along = prec_uniform(g), off = (prec_uniform(g) < 0.5 ? -1 : 1) * (0.02 + 0.08 * prec_uniform(g));
    switch ((int)(3 * prec_uniform(g))) {
    case 0: *b1 = off; *b2 = along; break;
    case 1: *b1 = along; *b2 = off; break;
    default: *b1 = along * (1 - off); *b2 = (1 - along) * (1 - off); break;
    }
}

static const double prec_cases[][2] = {  /* {distance from the world origin, size across} */
    {1e3, 1e-3}, {3e3, 4e-3}, {1e4, 1e-2}, {1e2, 1e-4}, {1.0, 1e-4},
};

static void test_triangle_intersect__small_triangles_far_from_the_origin(void **state)
{
    uint64_t g = 0x7219a1ull;
    for (size_t c = 0; c < sizeof prec_cases / sizeof prec_cases[0]; c++)
        for (int k = 0; k < 8; k++) {
            vec3 n;
            triangle tri = prec_triangle(&g, prec_cases[c][0], prec_cases[c][1], &n);
            for (int i = 0; i < PREC_RAYS; i++) {
                double b1, b2;
                prec_barycentrics(&g, i, &b1, &b2);
                vec3 aim = prec_point(&tri, b1, b2);
                vec3 o = vec3_add(aim, vec3_scale(prec_unit(&g), (float)(prec_cases[c][1] * (2 + 48 * prec_uniform(&g)))));
                ray r = ray_make(o, vec3_normalize(vec3_sub(aim, o)), 0.0f, INFINITY);
                check_precise(&tri, r, "small triangle, ray from nearby", prec_cases[c][1], prec_cases[c][0]);
            }
        }
}

static void test_triangle_intersect__near_parallel_rays(void **state)
{
    /* Rays at 1e-2 .. 1e-5 radians to the plane: through the triangle, or just above or below it,
     * where the plane is met far beyond (or before) the triangle. */
    uint64_t g = 0x9a7a11e1ull;
    for (size_t c = 0; c < sizeof prec_cases / sizeof prec_cases[0]; c++)
        for (int k = 0; k < 8; k++) {
            vec3 n;
            double size = prec_cases[c][1];
            triangle tri = prec_triangle(&g, prec_cases[c][0], size, &n);
            for (int i = 0; i < PREC_RAYS; i++) {
                double b1, b2;
                prec_barycentrics(&g, i, &b1, &b2);
                vec3 aim = prec_point(&tri, b1, b2);
                double angle = pow(10.0, -2.0 - 3.0 * prec_uniform(&g));
                double lift = (i % 3 - 1) * size * (0.05 + prec_uniform(&g));  /* below, on, above */
                aim = vec3_add(aim, vec3_scale(n, (float)lift));
                vec3 along = vec3_normalize(vec3_cross(n, prec_unit(&g)));
                vec3 d = vec3_normalize(vec3_add(along, vec3_scale(n, (float)(angle * (i % 2 ? 1 : -1)))));
                ray r = ray_make(vec3_sub(aim, vec3_scale(d, (float)(size * (2 + 48 * prec_uniform(&g))))), d, 0.0f,
                                 INFINITY);
                check_precise(&tri, r, "near-parallel ray", size, prec_cases[c][0]);
            }
        }
}

int triangle_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_triangle_intersect__hit_at_known_t_and_barycentrics, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__normal_is_normalised_barycentric_blend, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__misses_outside, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__edges_and_vertices_count, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__parallel_ray_misses, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__respects_min_t_and_max_t, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__hit_from_behind_counts, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__nearer_of_two_wins, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__degenerate_triangle_never_hits, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__small_triangles_far_from_the_origin, test_setup),
        cmocka_unit_test_setup(test_triangle_intersect__near_parallel_rays, test_setup),
    };
    return cmocka_run_group_tests_name("part1: triangle_intersect (task 1.2)", tests, NULL, NULL);
}
