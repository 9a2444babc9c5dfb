/* Test machinery: not part of any assignment. Task 2.2: the BVH's invariants on the shipped scenes
 * and on random soups, with several leaf sizes. */
#include "../common/test.h"
#include "fixtures.h"
#include <stdio.h>
#include <string.h>

/* Builds a BVH over s and checks every invariant, failing with the first violation. */
static void build_and_check(const scene *s, int max_leaf_size, const char *what)
{
    bvh b;
    pl_status st = bvh_build(&b, s, max_leaf_size);
    assert_implemented();
    if (st != PL_OK) PL_FAIL("%s: bvh_build returned %s", what, pl_status_name(st));
    pl_diag why = pl_diag_default();
    pl_status valid = bvh_validate(&b, s, max_leaf_size, true, NULL, &why);
    bvh_free(&b);
    if (valid != PL_OK) PL_FAIL("%s (max_leaf_size %d): %s", what, max_leaf_size, why.error);
}
#define build_and_check(...) PL_AT(build_and_check(__VA_ARGS__))  /* failures name the calling test's line */

static void check_invariants_of_scene(const scene *s, const char *path)
{
    int leaf_sizes[] = {1, 4};
    for (int k = 0; k < 2; k++) build_and_check(s, leaf_sizes[k], path);
}

static void test_bvh_build__invariants_hold_on_every_shipped_scene(void **state)
{
    PL_AT(fixture_for_each_scene(check_invariants_of_scene));  /* failures name this line */
}

static void test_bvh_build__invariants_hold_on_random_soups(void **state)
{
    int sizes[] = {1, 2, 3, 17, 100, 1000, 20000};
    int leaf_sizes[] = {1, 2, 4, 8};
    for (int i = 0; i < 7; i++) {
        scene s = {0};
        fixture_random_soup(&s, sizes[i], 1000 + i);
        for (int k = 0; k < 4; k++) {
            char what[64];
            snprintf(what, sizeof what, "soup of %d primitives (seed %d)", sizes[i], 1000 + i);
            build_and_check(&s, leaf_sizes[k], what);
        }
        scene_free(&s);
    }
}

static void test_bvh_build__identical_primitives_still_respect_the_leaf_size(void **state)
{
    /* No plane separates identical centroids: the build must still split to honour max_leaf_size. */
    scene s = {0};
    scene_add_material(&s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    triangle t = triangle_make(vec3_make(0, 0, 0), vec3_make(1, 0, 0), vec3_make(0, 1, 0), 0);
    for (int i = 0; i < 1000; i++) scene_add_triangle(&s, t);
    build_and_check(&s, 1, "1000 copies of one triangle");
    build_and_check(&s, 4, "1000 copies of one triangle");
    scene_free(&s);
}

static void test_bvh_build__empty_scene_gives_no_nodes(void **state)
{
    scene s = {0};
    build_and_check(&s, 4, "an empty scene");
}

static void test_bvh_build__rejects_a_leaf_size_below_one(void **state)
{
    scene s = {0};
    fixture_random_soup(&s, 10, 7);
    bvh b;
    pl_status st = bvh_build(&b, &s, 0);
    assert_implemented();
    bvh_free(&b);
    scene_free(&s);
    if (st != PL_ERR_INVALID) fail_msg("max_leaf_size 0: expected PL_ERR_INVALID, got %s", pl_status_name(st));
}

/* ---- the tree's quality, judged on the tree itself ----------------------------------------------- */

/* The SAH cost of tree b (the handout's model, both constants 1): the expected number of box-pair
 * and primitive tests of a random ray that meets the root, each node weighted by its area over the
 * root's. Interior nodes cost one traversal step, leaves their primitives. */
static double sah_cost(const bvh *b)
{
    if (b->num_nodes == 0) return 0.0;
    double root = aabb_surface_area(b->nodes[0].box), cost = 0.0;
    if (!(root > 0.0)) return 0.0;
    for (int i = 0; i < b->num_nodes; i++) {
        const bvh_node *n = &b->nodes[i];
        cost += aabb_surface_area(n->box) / root * (n->count > 0 ? (double)n->count : 1.0);
    }
    return cost;
}

/* How much worse than a plain median split a correct tree may be: the SAH is greedy, a build may stop
 * splitting where its own constants say a leaf is cheaper (the handout lets it choose them), and the
 * object median is a correct alternative (course/alternatives). Measured, cost over the median's on
 * the bunny, then a 20,000-primitive soup at leaf sizes 4 and 1: the solution's binned SAH 0.48,
 * 0.69, 0.74; a full-sweep SAH 0.41, 0.68, 0.72; the object median 1.00 (this very split). A tree
 * that keeps every invariant but splits in the primitives' order, not in space, costs 6.2 times the
 * median's on the bunny. */
#define SAH_WORSE_THAN_MEDIAN 1.5

static void check_sah_cost(const scene *s, int max_leaf_size, const char *what)
{
    bvh b, median;
    pl_status st = bvh_build(&b, s, max_leaf_size);
    assert_implemented();
    if (st != PL_OK) PL_FAIL("%s: bvh_build returned %s", what, pl_status_name(st));
    fixture_build_median(&median, s, max_leaf_size);
    double mine = sah_cost(&b), plain = sah_cost(&median);
    bvh_free(&b);
    bvh_free(&median);
    if (mine > SAH_WORSE_THAN_MEDIAN * plain)
        PL_FAIL("%s (max_leaf_size %d): the tree's SAH cost is %.3g, %.2g times a plain median split's %.3g; expected "
                "at most %.1f times: are the splits chosen in space, by the surface area heuristic, with the boxes "
                "of the primitives each side?", what, max_leaf_size, mine, mine / plain, plain, SAH_WORSE_THAN_MEDIAN);
}
#define check_sah_cost(...) PL_AT(check_sah_cost(__VA_ARGS__))

static void check_sah_cost_of_scene(const scene *s, const char *path)
{
    if (scene_prim_count(s) >= 64) check_sah_cost(s, 4, path);  /* a handful: any tree costs the same */
}

/* Judged on the returned tree itself (the autograder's judge reads it from the answer): a tree that
 * keeps the invariants but is split without the SAH, or not in space at all, costs every ray. */
static void test_bvh_build__sah_cost_near_a_median_splits_or_better(void **state)
{
    PL_AT(fixture_for_each_scene(check_sah_cost_of_scene));
    scene s = {0};
    fixture_random_soup(&s, 20000, 77);
    check_sah_cost(&s, 4, "a soup of 20000 primitives (seed 77)");
    check_sah_cost(&s, 1, "a soup of 20000 primitives (seed 77)");
    scene_free(&s);
}

int build_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_build__invariants_hold_on_every_shipped_scene, test_setup),
        cmocka_unit_test_setup(test_bvh_build__invariants_hold_on_random_soups, test_setup),
        cmocka_unit_test_setup(test_bvh_build__identical_primitives_still_respect_the_leaf_size, test_setup),
        cmocka_unit_test_setup(test_bvh_build__empty_scene_gives_no_nodes, test_setup),
        cmocka_unit_test_setup(test_bvh_build__rejects_a_leaf_size_below_one, test_setup),
        cmocka_unit_test_setup(test_bvh_build__sah_cost_near_a_median_splits_or_better, test_setup),
    };
    return cmocka_run_group_tests_name("part2: BVH build (task 2.2)", tests, NULL, NULL);
}
