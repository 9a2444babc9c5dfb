/* Test machinery: not part of any assignment. The framework's BVH validator (framework/bvh.h):
 * a malformed tree is refused with the node at fault, never walked into a crash. */
#include "../common/test.h"
#include "../../framework/bvh.h"
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

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

/* ---- PL_CHECK (framework/check.h), attacked through bvh_visit --------------------------------- */

/* A handler that records the failed check and jumps back to the test, so the read it guards never
 * happens. */
static jmp_buf check_return;
static char check_text[256];
static void record_check(const char *what, const char *file, int line)
{
    snprintf(check_text, sizeof check_text, "%s:%d: %s", file, line, what);
    longjmp(check_return, 1);
}

/* A traversal that asks for node -1 or one past the end is stopped at bvh_visit, naming the check. */
static void test_bvh_visit__a_bad_index_fails_its_check(void **state)
{
    two_leaf_tree t;
    two_leaf_tree_make(&t);
    const int bad[] = {-1, 3, 1 << 30};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        check_text[0] = '\0';
        pl_check_set_handler(record_check);
        if (setjmp(check_return) == 0) {
            (void)bvh_visit(&t.b, bad[i]);
            pl_check_set_handler(check_failed_invariant);
            scene_free(&t.s);
            fail_msg("bvh_visit(%d) of a 3-node tree passed its check", bad[i]);
        }
        pl_check_set_handler(check_failed_invariant);
        if (!strstr(check_text, "framework/bvh.c") || !strstr(check_text, "num_nodes")) {
            scene_free(&t.s);
            fail_msg("bvh_visit(%d): the failed check says \"%s\", expected framework/bvh.c and the condition",
                     bad[i], check_text);
        }
    }
    PL_CHECK(bvh_visit(&t.b, 2) == &t.nodes[2]);  /* a good index passes, and is the node */
    scene_free(&t.s);
}

/* Outside the tests a failed check prints where and what, and aborts: a render stops at the bug. */
static void test_pl_check__default_handler_prints_and_aborts(void **state)
{
    int out[2];
    assert_int_equal(pipe(out), 0);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        dup2(out[1], 2);
        pl_check_set_handler(NULL);
        PL_CHECK(1 + 1 == 3);
        _exit(0);  /* not reached when the check works */
    }
    close(out[1]);
    char text[256] = {0};
    ssize_t n = read(out[0], text, sizeof text - 1);
    close(out[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFSIGNALED(status) || WTERMSIG(status) != SIGABRT)
        fail_msg("a failed check did not abort (status %d)", status);
    if (n <= 0 || !strstr(text, "check failed: 1 + 1 == 3") || !strstr(text, "test_bvh.c:"))
        fail_msg("a failed check printed \"%s\", expected file:line: check failed: 1 + 1 == 3", text);
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
        cmocka_unit_test(test_bvh_visit__a_bad_index_fails_its_check),
        cmocka_unit_test(test_pl_check__default_handler_prints_and_aborts),
    };
    return cmocka_run_group_tests_name("framework: BVH validator", tests, NULL, NULL);
}
