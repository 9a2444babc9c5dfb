/* Test machinery: not part of any assignment. The point of a BVH: the nodes a ray visits grow like
 * log N with the number of triangles N, not like N. Counted (bvh_count_visits), never timed. */
#include "../common/test.h"
#include "../common/procmesh.h"
#include "../../parts/part2_bvh/part2.h"
#include "../../framework/heatmap.h"
#include "../../framework/rng.h"
#include "../../framework/sampler.h"
#include <stdio.h>

#define COMPLEXITY_RAYS 2000
#define COMPLEXITY_SEED 42
/* From 10^4 to 10^6 triangles, log2 N grows by 1.5x; N^(1/2) would grow 10x and N 100x. A good
 * tree stays near 1.5x; 3x leaves room for a simpler but sound one and still rejects sqrt(N). */
#define MAX_GROWTH 3.0

/* Mean nodes visited per ray for camera-like rays at a bumpy sphere of about n triangles. */
static double mean_visits(long n)
{
    scene s = {0};
    scene_add_material(&s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&s, procmesh_rows_for(n), vec3_make(0, 0, 0), 1.0f, 0), PL_OK);
    bvh b;
    pl_status st = bvh_build(&b, &s, 4);
    assert_implemented();
    if (st != PL_OK) fail_msg("bvh_build returned %s", pl_status_name(st));

    /* From a sphere of radius 3 towards points near the centre: every ray hits, as camera rays
     * on a close-up would. The same rays for every n. */
    rng g = rng_seeded(COMPLEXITY_SEED, 0);
    uint64_t visits = 0;
    bvh_take_visits();
    for (int i = 0; i < COMPLEXITY_RAYS; i++) {
        vec3 o = vec3_scale(sample_uniform_sphere(rng_uniform2(&g)), 3.0f);
        vec3 target = vec3_scale(sample_uniform_sphere(rng_uniform2(&g)), 0.5f);
        ray r = ray_make(o, vec3_normalize(vec3_sub(target, o)), 0.0f, INFINITY);
        hit h;
        bvh_intersect(&b, &s, &r, &h);
        visits += bvh_take_visits();
    }
    assert_implemented();
    bvh_free(&b);
    int triangles = s.num_triangles;
    scene_free(&s);
    if (visits == 0) fail_msg("bvh_intersect reported no node visits: call bvh_count_visits once per ray (part2.h)");
    double mean = (double)visits / COMPLEXITY_RAYS;
    print_message("      %d triangles: %.1f nodes visited per ray (%d rays, seed %d)\n", triangles, mean,
                  COMPLEXITY_RAYS, COMPLEXITY_SEED);
    return mean;
}

static void test_bvh_intersect__visits_grow_like_log_n(void **state)
{
    double small = mean_visits(10000);
    double medium = mean_visits(100000);
    double large = mean_visits(1000000);
    (void)medium;  /* printed, for the table in the handout */
    if (large > MAX_GROWTH * small)
        fail_msg("from 10^4 to 10^6 triangles the nodes visited per ray grew %.1fx (%.1f -> %.1f); log N grows 1.5x, "
                 "more than %.0fx means the tree or its traversal does not prune", large / small, small, large, MAX_GROWTH);
}

int complexity_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_intersect__visits_grow_like_log_n, test_setup),
    };
    return cmocka_run_group_tests_name("part2: nodes visited grow like log N", tests, NULL, NULL);
}
