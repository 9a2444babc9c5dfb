/* Test machinery: not part of any assignment. Task 1.3: ray-sphere hits from outside and inside. */
/* Hits start zeroed: with the task still a stub, link-time optimisation otherwise warns that a
 * check reads fields the stub never wrote (the check has failed by then; the compiler cannot tell). */
#include "../common/test.h"
#include "../../parts/part1_raygen/part1.h"
#include <math.h>

static const sphere unit_sphere_at_z5 = {{0, 0, -5}, 1.0f, 0};

static void test_sphere_intersect__from_outside_takes_near_root(void **state)
{
    ray r = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
    hit h = {0};
    bool found = sphere_intersect(&unit_sphere_at_z5, &r, &h);
    assert_implemented();
    if (!found) PL_FAIL("wrong: a ray from the origin down -z missed the unit sphere at (0, 0, -5), expected a hit at t = 4");
    assert_float_near(4.0, h.t, 1e-5);
    assert_float_near(4.0, r.max_t, 1e-5);
    assert_vec3_near(vec3_make(0, 0, 1), h.n, 1e-5f);
}

static void test_sphere_intersect__from_inside_takes_far_root_outward_normal(void **state)
{
    ray r = ray_make(vec3_make(0, 0, -5), vec3_make(1, 0, 0), 1e-4f, INFINITY);
    hit h = {0};
    assert_hit(sphere_intersect(&unit_sphere_at_z5, &r, &h));
    assert_implemented();
    assert_float_near(1.0, h.t, 1e-5);
    assert_vec3_near(vec3_make(1, 0, 0), h.n, 1e-5f);
}

static void test_sphere_intersect__off_centre_hit_at_known_t(void **state)
{
    /* Along -z at x = 0.6: the sphere surface is at z = -5 + 0.8, so t = 4.2. */
    ray r = ray_make(vec3_make(0.6f, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
    hit h = {0};
    assert_hit(sphere_intersect(&unit_sphere_at_z5, &r, &h));
    assert_implemented();
    assert_float_near(4.2, h.t, 1e-5);
    assert_vec3_near(vec3_make(0.6f, 0, 0.8f), h.n, 1e-5f);
}

static void test_sphere_intersect__unnormalised_direction(void **state)
{
    ray r = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -2), 0.0f, INFINITY);
    hit h = {0};
    assert_hit(sphere_intersect(&unit_sphere_at_z5, &r, &h));
    assert_implemented();
    assert_float_near(2.0, h.t, 1e-5);
}

static void test_sphere_intersect__tangent_ray_hits(void **state)
{
    ray r = ray_make(vec3_make(1, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
    hit h = {0};
    assert_hit(sphere_intersect(&unit_sphere_at_z5, &r, &h));
    assert_implemented();
    assert_float_near(5.0, h.t, 1e-3);
}

static void test_sphere_intersect__misses_beside_behind_and_out_of_range(void **state)
{
    hit h = {0};
    ray beside = ray_make(vec3_make(1.01f, 0, 0), vec3_make(0, 0, -1), 0.0f, INFINITY);
    assert_miss(sphere_intersect(&unit_sphere_at_z5, &beside, &h));
    assert_implemented();
    ray behind = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 0.0f, INFINITY);
    assert_miss(sphere_intersect(&unit_sphere_at_z5, &behind, &h));
    ray short_ray = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 0.0f, 3.9f);
    assert_miss(sphere_intersect(&unit_sphere_at_z5, &short_ray, &h));
    assert_float_near(3.9f, short_ray.max_t, 0);
    /* min_t past the near root: the far root at t = 6 counts. */
    ray late = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 4.5f, INFINITY);
    assert_hit(sphere_intersect(&unit_sphere_at_z5, &late, &h));
    assert_float_near(6.0, h.t, 1e-5);
    /* Past both roots: nothing. */
    ray past = ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 6.5f, INFINITY);
    assert_miss(sphere_intersect(&unit_sphere_at_z5, &past, &h));
}

int sphere_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_sphere_intersect__from_outside_takes_near_root, test_setup),
        cmocka_unit_test_setup(test_sphere_intersect__from_inside_takes_far_root_outward_normal, test_setup),
        cmocka_unit_test_setup(test_sphere_intersect__off_centre_hit_at_known_t, test_setup),
        cmocka_unit_test_setup(test_sphere_intersect__unnormalised_direction, test_setup),
        cmocka_unit_test_setup(test_sphere_intersect__tangent_ray_hits, test_setup),
        cmocka_unit_test_setup(test_sphere_intersect__misses_beside_behind_and_out_of_range, test_setup),
    };
    return cmocka_run_group_tests_name("part1: sphere_intersect (task 1.3)", tests, NULL, NULL);
}
