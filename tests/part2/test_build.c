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

int build_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_build__invariants_hold_on_every_shipped_scene, test_setup),
        cmocka_unit_test_setup(test_bvh_build__invariants_hold_on_random_soups, test_setup),
        cmocka_unit_test_setup(test_bvh_build__identical_primitives_still_respect_the_leaf_size, test_setup),
        cmocka_unit_test_setup(test_bvh_build__empty_scene_gives_no_nodes, test_setup),
        cmocka_unit_test_setup(test_bvh_build__rejects_a_leaf_size_below_one, test_setup),
    };
    return cmocka_run_group_tests_name("part2: BVH build (task 2.2)", tests, NULL, NULL);
}
