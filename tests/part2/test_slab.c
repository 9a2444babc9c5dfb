/* Test machinery: not part of any assignment. Task 2.1: the slab test on cases with exact answers. */
#include "../common/test.h"
#include "../../parts/part2_bvh/part2.h"
#include <math.h>
#include <stdio.h>

static const aabb UNIT_BOX = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};

static ray ray_from(float ox, float oy, float oz, float dx, float dy, float dz)
{
    return ray_make(vec3_make(ox, oy, oz), vec3_make(dx, dy, dz), 0.0f, INFINITY);
}

/* The query, for a message: "aabb_intersect(box [(0, 0, 0), (1, 1, 1)], ray o = (...), d = (...), t in [0, inf])". */
static void describe_query(char *out, size_t len, const aabb *b, const ray *r)
{
    snprintf(out, len, "aabb_intersect(box [(%g, %g, %g), (%g, %g, %g)], ray o = (%g, %g, %g), d = (%g, %g, %g), "
             "t in [%g, %g])", b->min.x, b->min.y, b->min.z, b->max.x, b->max.y, b->max.z, r->o.x, r->o.y, r->o.z,
             r->d.x, r->d.y, r->d.z, r->min_t, r->max_t);
}

/* Expects a hit with exactly [t_enter, t_exit] (every case here is exact in float). */
static void expect_hit(const aabb *b, ray r, float t_enter, float t_exit)
{
    float t0 = NAN, t1 = NAN;
    char query[256];
    describe_query(query, sizeof query, b, &r);
    bool is_hit = aabb_intersect(b, &r, &t0, &t1);
    assert_implemented();
    if (!is_hit) PL_FAIL("wrong: %s: expected a hit with [t_enter, t_exit] = [%g, %g], got a miss", query, t_enter, t_exit);
    if (!(t0 == t_enter && t1 == t_exit))
        PL_FAIL("wrong: %s: expected [t_enter, t_exit] = [%g, %g], got [%g, %g]", query, t_enter, t_exit, t0, t1);
}
#define expect_hit(...) PL_AT(expect_hit(__VA_ARGS__))  /* failures name the calling test's line */

static void expect_miss(const aabb *b, ray r)
{
    float t0 = NAN, t1 = NAN;
    char query[256];
    describe_query(query, sizeof query, b, &r);
    bool is_hit = aabb_intersect(b, &r, &t0, &t1);
    assert_implemented();
    if (is_hit) PL_FAIL("wrong: %s: expected a miss, got a hit with [t_enter, t_exit] = [%g, %g]", query, t0, t1);
}
#define expect_miss(...) PL_AT(expect_miss(__VA_ARGS__))  /* failures name the calling test's line */

static void test_aabb_intersect__ray_through_box_enters_and_leaves(void **state)
{
    expect_hit(&UNIT_BOX, ray_from(-1.0f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(0.5f, 3.0f, 0.5f, 0.0f, -1.0f, 0.0f), 2.0f, 3.0f);
    expect_hit(&UNIT_BOX, ray_from(0.5f, 0.5f, -3.0f, 0.0f, 0.0f, 2.0f), 1.5f, 2.0f);  /* d not unit */
    expect_hit(&UNIT_BOX, ray_from(-1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f), 1.0f, 2.0f); /* diagonal */
}

static void test_aabb_intersect__misses_beside_behind_and_beyond(void **state)
{
    expect_miss(&UNIT_BOX, ray_from(-1.0f, 2.0f, 0.5f, 1.0f, 0.0f, 0.0f));   /* passes beside */
    expect_miss(&UNIT_BOX, ray_from(-1.0f, 0.5f, 0.5f, -1.0f, 0.0f, 0.0f));  /* box behind */
    expect_miss(&UNIT_BOX, ray_from(-1.5f, 0.0f, 0.5f, 1.0f, 1.0f, 0.0f));  /* passes the corner */
    ray short_ray = ray_from(-1.0f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f);
    short_ray.max_t = 0.5f;  /* ends before the box */
    expect_miss(&UNIT_BOX, short_ray);
    ray late_ray = ray_from(-1.0f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f);
    late_ray.min_t = 3.0f;   /* starts after it */
    expect_miss(&UNIT_BOX, late_ray);
}

static void test_aabb_intersect__clips_to_min_t_and_max_t(void **state)
{
    ray r = ray_from(-1.0f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f);
    r.min_t = 1.5f;
    r.max_t = 1.75f;
    expect_hit(&UNIT_BOX, r, 1.5f, 1.75f);
    r.min_t = 0.0f;
    r.max_t = 1.0f;  /* ends exactly on the face: touching counts */
    expect_hit(&UNIT_BOX, r, 1.0f, 1.0f);
}

static void test_aabb_intersect__origin_inside_enters_at_min_t(void **state)
{
    expect_hit(&UNIT_BOX, ray_from(0.5f, 0.5f, 0.5f, 0.0f, 0.0f, 1.0f), 0.0f, 0.5f);
    expect_hit(&UNIT_BOX, ray_from(0.25f, 0.5f, 0.5f, -1.0f, 0.0f, 0.0f), 0.0f, 0.25f);
    ray r = ray_from(0.5f, 0.5f, 0.5f, 0.0f, 1.0f, 0.0f);
    r.min_t = 0.125f;
    expect_hit(&UNIT_BOX, r, 0.125f, 0.5f);
}

static void test_aabb_intersect__axis_parallel_rays_with_zero_components(void **state)
{
    /* Two zero direction components: 1/d is infinite, and nothing may turn into NaN. */
    expect_hit(&UNIT_BOX, ray_from(0.5f, 0.5f, -1.0f, 0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(0.5f, 0.5f, 2.0f, -0.0f, 0.0f, -1.0f), 1.0f, 2.0f);   /* -0 */
    expect_hit(&UNIT_BOX, ray_from(0.5f, 0.5f, 2.0f, 0.0f, -0.0f, -1.0f), 1.0f, 2.0f);
    expect_miss(&UNIT_BOX, ray_from(1.5f, 0.5f, -1.0f, 0.0f, 0.0f, 1.0f));  /* parallel, outside the x slab */
    expect_miss(&UNIT_BOX, ray_from(0.5f, -0.5f, -1.0f, -0.0f, 0.0f, 1.0f));
}

static void test_aabb_intersect__ray_in_a_face_plane_hits(void **state)
{
    /* The origin lies on the planes x = 0 or x = 1 and d.x is 0: (0 - 0) * inf is NaN in a naive test. */
    expect_hit(&UNIT_BOX, ray_from(0.0f, 0.5f, -1.0f, 0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(1.0f, 0.5f, -1.0f, 0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(0.0f, 0.5f, -1.0f, -0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(1.0f, 0.5f, -1.0f, -0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
}

static void test_aabb_intersect__rays_along_an_edge_hit(void **state)
{
    expect_hit(&UNIT_BOX, ray_from(0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 1.0f), 1.0f, 2.0f);
    expect_hit(&UNIT_BOX, ray_from(1.0f, 1.0f, 3.0f, -0.0f, -0.0f, -1.0f), 2.0f, 3.0f);
    expect_hit(&UNIT_BOX, ray_from(-2.0f, 1.0f, 0.0f, 1.0f, 0.0f, 0.0f), 2.0f, 3.0f);
    /* Crossing an edge diagonally touches the box at one point: t_enter == t_exit. */
    expect_hit(&UNIT_BOX, ray_from(-1.0f, 0.0f, 0.5f, 1.0f, 1.0f, 0.0f), 1.0f, 1.0f);
}

static void test_aabb_intersect__flat_box_is_hit_through_its_plane(void **state)
{
    aabb flat = {{0.0f, 0.5f, 0.0f}, {1.0f, 0.5f, 1.0f}};  /* a triangle's box in the plane y = 0.5 */
    expect_hit(&flat, ray_from(0.5f, 0.0f, 0.5f, 0.0f, 1.0f, 0.0f), 0.5f, 0.5f);
    expect_hit(&flat, ray_from(0.5f, 2.0f, 0.5f, 0.0f, -2.0f, 0.0f), 0.75f, 0.75f);
    expect_miss(&flat, ray_from(1.5f, 0.0f, 0.5f, 0.0f, 1.0f, 0.0f));
}

static void test_aabb_intersect__empty_box_and_zero_direction(void **state)
{
    aabb empty = aabb_empty();
    expect_miss(&empty, ray_from(0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f));
    expect_miss(&empty, ray_from(0.5f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f));
    /* A zero direction stays where it is: inside for all t, or never inside. */
    ray still = ray_from(0.5f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f);
    still.max_t = 10.0f;
    expect_hit(&UNIT_BOX, still, 0.0f, 10.0f);
    expect_miss(&UNIT_BOX, ray_from(2.0f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f));
}

int slab_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_aabb_intersect__ray_through_box_enters_and_leaves, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__misses_beside_behind_and_beyond, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__clips_to_min_t_and_max_t, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__origin_inside_enters_at_min_t, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__axis_parallel_rays_with_zero_components, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__ray_in_a_face_plane_hits, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__rays_along_an_edge_hit, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__flat_box_is_hit_through_its_plane, test_setup),
        cmocka_unit_test_setup(test_aabb_intersect__empty_box_and_zero_direction, test_setup),
    };
    return cmocka_run_group_tests_name("part2: slab test (task 2.1)", tests, NULL, NULL);
}
