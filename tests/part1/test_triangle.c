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
    assert_true(found);
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
        assert_true(isinf(r.max_t));              /* a miss leaves the ray alone */
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
    assert_false(found);
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
    };
    return cmocka_run_group_tests_name("part1: triangle_intersect (task 1.2)", tests, NULL, NULL);
}
