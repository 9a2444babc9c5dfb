/* Test machinery: not part of any assignment. The framework's BVH validator (framework/bvh.h):
 * a malformed tree is refused with the node at fault, never walked into a crash. */
#include "../common/test.h"
#include "../../framework/bvh.h"
#include <string.h>

/* Two triangles side by side and a valid tree over them: a root and two leaves. */
typedef struct {
    scene s;
    bvh_node nodes[3];
    int prim_index[2];
    bvh b;
} two_leaf_tree;

static void two_leaf_tree_make(two_leaf_tree *t)
{
    memset(t, 0, sizeof *t);
    scene_add_material(&t->s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    scene_add_triangle(&t->s, triangle_make(vec3_make(0, 0, 0), vec3_make(1, 0, 0), vec3_make(0, 1, 0), 0));
    scene_add_triangle(&t->s, triangle_make(vec3_make(2, 0, 0), vec3_make(3, 0, 0), vec3_make(2, 1, 0), 0));
    t->nodes[1] = (bvh_node){scene_prim_bounds(&t->s, 0), 0, 1};
    t->nodes[2] = (bvh_node){scene_prim_bounds(&t->s, 1), 1, 1};
    t->nodes[0] = (bvh_node){aabb_union(t->nodes[1].box, t->nodes[2].box), 1, 0};
    t->prim_index[0] = 0;
    t->prim_index[1] = 1;
    t->b = (bvh){t->nodes, 3, t->prim_index, 2};
}

/* Validates t's tree, expecting it refused with a message containing `expected`. */
static void expect_refused(two_leaf_tree *t, const char *expected, const char *file, int line)
{
    pl_diag diag = pl_diag_default();
    pl_status st = bvh_validate(&t->b, &t->s, 4, false, NULL, &diag);
    scene_free(&t->s);
    if (st != PL_ERR_INVALID) {
        print_error("expected PL_ERR_INVALID (\"%s\"), got %s\n", expected, pl_status_name(st));
        _fail(file, line);
    }
    if (!strstr(diag.error, expected)) {
        print_error("the message \"%s\" does not say \"%s\"\n", diag.error, expected);
        _fail(file, line);
    }
}
#define assert_refused(t, expected) expect_refused((t), (expected), __FILE__, __LINE__)

static void test_bvh_validate__accepts_a_valid_tree_and_measures_it(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    bvh_shape shape;
    pl_diag diag = pl_diag_default();
    pl_status st = bvh_validate(&t.b, &t.s, 1, true, &shape, &diag);
    scene_free(&t.s);
    if (st != PL_OK) fail_msg("a valid tree was refused: %s", diag.error);
    assert_int_equal(shape.nodes, 3);
    assert_int_equal(shape.leaves, 2);
    assert_int_equal(shape.depth, 1);
}

static void test_bvh_validate__refuses_a_child_out_of_range(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    t.nodes[0].first = 9000;
    assert_refused(&t, "node 0: child 9001 >= num_nodes 3");
}

static void test_bvh_validate__refuses_a_cycle(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    t.nodes[1] = (bvh_node){t.nodes[0].box, 1, 0};  /* node 1's children are nodes 1 and 2 */
    assert_refused(&t, "reached twice from the root");
}

static void test_bvh_validate__refuses_a_primitive_in_two_leaves(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    t.prim_index[1] = 0;
    t.nodes[2].box = t.nodes[1].box;  /* enclosing its (now duplicated) primitive */
    assert_refused(&t, "primitive 0 is in two leaves");
}

static void test_bvh_validate__refuses_a_box_that_does_not_enclose_its_primitives(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    t.nodes[2].box = t.nodes[1].box;
    t.nodes[0].box = t.nodes[1].box;
    assert_refused(&t, "node 2: leaf box is not enclosing");
}

static void test_bvh_validate__refuses_a_leaf_slot_out_of_range(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    t.nodes[2].first = 7;
    assert_refused(&t, "node 2: leaf covers slots 7 .. 7, prim_index has 2");
}

int bvh_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_validate__accepts_a_valid_tree_and_measures_it, test_setup),
        cmocka_unit_test_setup(test_bvh_validate__refuses_a_child_out_of_range, test_setup),
        cmocka_unit_test_setup(test_bvh_validate__refuses_a_cycle, test_setup),
        cmocka_unit_test_setup(test_bvh_validate__refuses_a_primitive_in_two_leaves, test_setup),
        cmocka_unit_test_setup(test_bvh_validate__refuses_a_box_that_does_not_enclose_its_primitives, test_setup),
        cmocka_unit_test_setup(test_bvh_validate__refuses_a_leaf_slot_out_of_range, test_setup),
    };
    return cmocka_run_group_tests_name("framework: BVH validator", tests, NULL, NULL);
}
