/* Test machinery: not part of any assignment. The point of a BVH: the work a ray costs grows like
 * log N with the number of triangles N, not like N. Counted, never timed, and counted by the
 * framework: node visits where bvh_visit hands a node out, primitive tests in
 * scene_prim_intersect (framework/counters.h). A traversal has no declared way to read, report or
 * reset a count, and every ray's counts are checked against what any correct traversal must do
 * (work_check.h), so reading nodes or testing triangles behind the framework's back fails. */
#include "../common/test.h"
#include "../../framework/procmesh.h"
#include "fixtures.h"
#include "work_check.h"
#include "../../parts/part1_raygen/part1.h"
#include "../../parts/part2_bvh/part2.h"
#include "../../framework/accel.h"
#include "../../framework/counters.h"
#include "../../framework/rng.h"
#include "../../framework/sampler.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COMPLEXITY_RAYS 2000
/* Enough rays to see a linear scan's primitive tests; few, since each costs 10^6 of them. */
#define FAKE_RAYS 20
#define COMPLEXITY_SEED 42
/* From 10^4 to 10^6 triangles, log2 N grows by 1.5x; N^(1/2) would grow 10x and N 100x. A good
 * tree stays near 1.5x; 3x leaves room for a simpler but sound one and still rejects sqrt(N). */
#define MAX_GROWTH 3.0

/* A closest-hit query: part 2's bvh_intersect, or a stand-in the tests below use. */
typedef bool (*closest_fn)(const bvh *b, const scene *s, ray *r, hit *h);
/* An any-hit query: part 2's bvh_occluded, or a stand-in. */
typedef bool (*any_fn)(const bvh *b, const scene *s, const ray *r);

/* Work per ray, as the framework counted it. */
typedef struct { double visits, prim_tests; int rays; } work;


/* The two bumpy spheres (about 10^4 and 10^6 triangles) with their trees from bvh_build, and the
 * small one with a tree the tests build (fixture_build_median) for the machinery tests, built on
 * first use and shared by the tests of this group (the large build is most of the group's time). */
typedef struct {
    scene s;
    bvh b;
    work_check check;
    bool built, checked;
    char broken[PL_DIAG_MSG_MAX + 128];  /* why its tree cannot be used: every test sharing it fails so */
} sized_tree;
static sized_tree trees[3];
static const long TREE_SIZES[3] = {10000, 1000000, 10000};
enum { SMALL = 0, LARGE = 1, GIVEN = 2 };

static sized_tree *tree_of(int which)
{
    sized_tree *t = &trees[which];
    if (t->broken[0]) fail_msg("%s", t->broken);  /* a later test on the same tree: the same reason */
    if (t->built) return t;
    t->s = (scene){0};
    scene_add_material(&t->s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&t->s, procmesh_rows_for(TREE_SIZES[which]), vec3_make(0, 0, 0), 1.0f, 0),
                     PL_OK);
    t->built = true;  /* whatever happens next: the group teardown frees it */
    if (which == GIVEN) {
        fixture_build_median(&t->b, &t->s, 4);
    } else {
        pl_status st = bvh_build(&t->b, &t->s, 4);
        assert_implemented();
        if (st != PL_OK) snprintf(t->broken, sizeof t->broken, "bvh_build returned %s", pl_status_name(st));
    }
    pl_diag why = pl_diag_default();
    if (!t->broken[0] && bvh_validate(&t->b, &t->s, 4, false, NULL, &why) != PL_OK)
        snprintf(t->broken, sizeof t->broken, "bvh_build made a malformed tree (task 2.2; these tests need a valid one): %s",
                 why.error);
    if (t->broken[0]) fail_msg("%s", t->broken);
    work_check_init(&t->check, &t->b, &t->s);
    t->checked = true;
    return t;
}

static void print_work(int which, work w)
{
    print_message("      %d triangles: %.1f nodes visited, %.1f primitives tested per ray (%d rays, seed %d)\n",
                  trees[which].s.num_triangles, w.visits, w.prim_tests, w.rays, COMPLEXITY_SEED);
}

static int free_trees(void **state)
{
    (void)state;
    for (int i = 0; i < 3; i++) {
        if (trees[i].checked) work_check_free(&trees[i].check);
        if (!trees[i].built) continue;
        bvh_free(&trees[i].b);
        scene_free(&trees[i].s);
        trees[i].built = trees[i].checked = false;
    }
    return 0;
}

/* Ray i of the fixed set: from a sphere of radius 3 towards points near the centre, so every ray
 * hits, as camera rays on a close-up would. The same rays for every tree. */
static ray test_ray(rng *g)
{
    vec3 o = vec3_scale(sample_uniform_sphere(rng_uniform2(g)), 3.0f);
    vec3 target = vec3_scale(sample_uniform_sphere(rng_uniform2(g)), 0.5f);
    return ray_make(o, vec3_normalize(vec3_sub(target, o)), 0.0f, INFINITY);
}

/* Mean work per ray of query for `rays` rays at tree `which`. Every ray's counts are checked
 * (work_check.h); the first inconsistency goes to why and makes *consistent false. */
static work mean_work(int which, closest_fn query, int rays, bool *consistent, char *why, size_t why_len)
{
    sized_tree *t = tree_of(which);
    rng g = rng_seeded(COMPLEXITY_SEED, 0);
    double visits = 0, tests = 0;
    int done = 0;
    *consistent = true;
    for (int i = 0; i < rays; i++, done++) {
        ray r = test_ray(&g);
        hit h;
        work_check_begin(&t->check);
        bool found = query(&t->b, &t->s, &r, &h);
        work_check_end(&t->check);
        visits += (double)t->check.counted.node_visits;
        tests += (double)t->check.counted.prim_tests;
        if (found && !work_check_closest(&t->check, i, &h, why, why_len)) {
            *consistent = false;
            done++;
            break;
        }
    }
    work w = {visits / done, tests / done, done};
    assert_implemented();
    return w;
}

/* True when every ray's counts are consistent and both counts stay within MAX_GROWTH from 10^4 to
 * 10^6 triangles; otherwise false with the reason in why (the caller fails at its own line). */
static bool grows_like_log_n(closest_fn query, int rays, char *why, size_t why_len)
{
    bool consistent;
    work small = mean_work(SMALL, query, rays, &consistent, why, why_len);
    print_work(SMALL, small);
    if (!consistent) return false;
    work large = mean_work(LARGE, query, rays, &consistent, why, why_len);
    print_work(LARGE, large);
    if (!consistent) return false;
    if (small.visits == 0.0 || large.visits == 0.0)
        snprintf(why, why_len, "bvh_intersect visited no nodes: call bvh_visit for every node you enter (task 2.3)");
    else if (large.visits > MAX_GROWTH * small.visits)
        snprintf(why, why_len, "from 10^4 to 10^6 triangles the nodes visited per ray grew %.1fx (%.1f -> %.1f); log N "
                 "grows 1.5x, more than %.0fx means the tree or its traversal does not prune",
                 large.visits / small.visits, small.visits, large.visits, MAX_GROWTH);
    else if (large.prim_tests > MAX_GROWTH * small.prim_tests)
        snprintf(why, why_len, "from 10^4 to 10^6 triangles the primitives tested per ray grew %.1fx (%.1f -> %.1f); a "
                 "pruning traversal tests about the same few per ray, more than %.0fx means it does not prune",
                 large.prim_tests / small.prim_tests, small.prim_tests, large.prim_tests, MAX_GROWTH);
    else
        return true;
    return false;
}

/* True when query's counts are consistent on `rays` rays at tree `which`; else the reason in why. */
static bool closest_consistent(int which, closest_fn query, int rays, char *why, size_t why_len)
{
    bool consistent;
    (void)mean_work(which, query, rays, &consistent, why, why_len);
    return consistent;
}

/* The same for an any-hit query. */
static bool any_consistent(int which, any_fn query, int rays, char *why, size_t why_len)
{
    sized_tree *t = tree_of(which);
    rng g = rng_seeded(COMPLEXITY_SEED, 1);
    for (int i = 0; i < rays; i++) {
        ray r = test_ray(&g);
        work_check_begin(&t->check);
        bool occluded = query(&t->b, &t->s, &r);
        work_check_end(&t->check);
        if (occluded && !work_check_any(&t->check, i, &r, why, why_len)) return false;
    }
    assert_implemented();
    return true;
}

/* ---- The machinery: forgers are caught, correct traversals of any order are not ---------------- */

/* A conservative slab test of the test's own (a box that is too generous is still correct). */
static bool box_overlaps(const bvh_node *n, const ray *r)
{
    float t0 = r->min_t, t1 = r->max_t;
    float o[3] = {r->o.x, r->o.y, r->o.z}, d[3] = {r->d.x, r->d.y, r->d.z};
    float lo[3] = {n->box.min.x, n->box.min.y, n->box.min.z}, hi[3] = {n->box.max.x, n->box.max.y, n->box.max.z};
    for (int a = 0; a < 3; a++) {
        float inv = 1.0f / d[a], ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
        t0 = fmaxf(t0, fminf(ta, tb));  /* fminf/fmaxf drop a NaN: the test stays conservative */
        t1 = fminf(t1, fmaxf(ta, tb));
    }
    return t0 <= t1 * 1.0001f;
}

/* A plain depth-first traversal: left child before right, whatever is nearer, no early exit; each
 * node counted when it is entered (popped), not when its box is tested from the parent. */
static bool dfs_traverse(const bvh *b, const scene *s, ray *r, hit *h, bool any)
{
    if (b->num_nodes == 0) return false;
    int stack[2 * BVH_MAX_DEPTH + 2], top = 0;
    stack[top++] = 0;
    bool found = false;
    while (top > 0 && !(any && found)) {
        const bvh_node *n = bvh_visit(b, stack[--top]);
        if (!box_overlaps(n, r)) continue;
        if (n->count > 0) {
            for (int i = 0; i < n->count && !(any && found); i++)
                found |= scene_prim_intersect(s, b->prim_index[n->first + i], r, h);
            continue;
        }
        stack[top++] = n->first + 1;
        stack[top++] = n->first;
    }
    return found;
}

static bool dfs_closest(const bvh *b, const scene *s, ray *r, hit *h) { return dfs_traverse(b, s, r, h, false); }

static bool dfs_any(const bvh *b, const scene *s, const ray *r)
{
    ray probe = *r;
    hit scratch;
    return dfs_traverse(b, s, &probe, &scratch, true);
}

/* Forger A: one visit, a linear scan, then the counts wiped (through the framework-internal
 * counters_take, which part code has no declaration of and the grader refuses). */
static bool forger_wipes_counts(const bvh *b, const scene *s, ray *r, hit *h)
{
    if (b->num_nodes > 0) (void)bvh_visit(b, 0);
    bool found = linear_intersect(s, r, h);
    (void)counters_take();
    return found;
}

/* Forger B: one visit, then triangle_intersect straight on the scene's triangles. */
static bool forger_tests_behind_the_back(const bvh *b, const scene *s, ray *r, hit *h)
{
    if (b->num_nodes > 0) (void)bvh_visit(b, 0);
    bool found = false;
    for (int i = 0; i < s->num_triangles; i++)
        if (triangle_intersect(&s->triangles[i], r, h)) {
            h->prim = i;
            h->material = s->triangles[i].material;
            found = true;
        }
    return found;
}

/* Forger C: pads the visits with the root, finds the hit behind the framework's back, then tests
 * only that primitive through scene_prim_intersect. */
static bool forger_pads_visits(const bvh *b, const scene *s, ray *r, hit *h)
{
    for (int i = 0; b->num_nodes > 0 && i < BVH_MAX_DEPTH; i++) (void)bvh_visit(b, 0);
    int best = -1;
    ray scan = *r;
    hit scratch;
    for (int i = 0; i < s->num_triangles; i++)
        if (triangle_intersect(&s->triangles[i], &scan, &scratch)) best = i;
    return best >= 0 && scene_prim_intersect(s, best, r, h);
}

/* The linear scan behind one root visit, as a traversal reporting "one visit per ray" did. */
static bool forger_one_visit(const bvh *b, const scene *s, ray *r, hit *h)
{
    if (b->num_nodes > 0) (void)bvh_visit(b, 0);
    return linear_intersect(s, r, h);
}

/* Forger D, any hit: one visit, then the scan. */
static bool forger_any_one_visit(const bvh *b, const scene *s, const ray *r)
{
    if (b->num_nodes > 0) (void)bvh_visit(b, 0);
    return linear_occluded(s, r);
}

/* Fails the test unless the forger is caught with a message containing `expect`. */
static void expect_caught(bool passed, const char *forger, const char *why, const char *expect)
{
    if (passed) fail_msg("test machinery: %s passed the work check", forger);
    if (!strstr(why, expect)) fail_msg("test machinery: %s was caught, but not by '%s': %s", forger, expect, why);
}

/* The work check itself: forgers are caught, a correct depth-first traversal passes. Run inside
 * the tests of tasks 2.3 and 2.4 rather than as tests of their own, which would pass with part 2
 * not written. */
static void the_work_check_catches_forged_closest_hits(void)
{
    char why[512];
    expect_caught(closest_consistent(GIVEN, forger_wipes_counts, FAKE_RAYS, why, sizeof why),
                  "forger A (wipes the counts)", why, "reset");
    expect_caught(closest_consistent(GIVEN, forger_tests_behind_the_back, FAKE_RAYS, why, sizeof why),
                  "forger B (calls triangle_intersect)", why, "scene_prim_intersect");
    expect_caught(closest_consistent(GIVEN, forger_pads_visits, FAKE_RAYS, why, sizeof why),
                  "forger C (pads visits with the root)", why, "was never read through bvh_visit");
    expect_caught(closest_consistent(GIVEN, forger_one_visit, FAKE_RAYS, why, sizeof why),
                  "one visit + linear scan", why, "call bvh_visit for every node you enter");
    if (!closest_consistent(GIVEN, dfs_closest, COMPLEXITY_RAYS, why, sizeof why))
        fail_msg("test machinery: a correct depth-first closest-hit traversal failed: %s", why);
}

static void the_work_check_catches_forged_any_hits(void)
{
    char why[512];
    expect_caught(any_consistent(GIVEN, forger_any_one_visit, FAKE_RAYS, why, sizeof why),
                  "any hit: one visit + linear scan", why, "call bvh_visit for every node you enter");
    if (!any_consistent(GIVEN, dfs_any, COMPLEXITY_RAYS, why, sizeof why))
        fail_msg("test machinery: a correct depth-first any-hit traversal failed: %s", why);
}


/* The test machinery checks itself first, inside the graded tests: as tests of their own these
 * self-checks would pass with part 2 stubbed and give a stub points. */
static void test_bvh_intersect__work_grows_like_log_n(void **state)
{
    the_work_check_catches_forged_closest_hits();
    char why[512];
    if (grows_like_log_n(forger_one_visit, FAKE_RAYS, why, sizeof why))
        fail_msg("test machinery: a linear scan that visits one node per ray passed the log N test");
    if (!grows_like_log_n(bvh_intersect, COMPLEXITY_RAYS, why, sizeof why)) fail_msg("%s", why);
}

static void test_bvh_occluded__counts_its_work_through_the_framework(void **state)
{
    the_work_check_catches_forged_any_hits();
    char why[512];
    if (!any_consistent(SMALL, bvh_occluded, COMPLEXITY_RAYS, why, sizeof why)) fail_msg("%s", why);
}

/* ---- Order: the nearer child first, nothing behind the nearest hit, nothing after an any hit ---- */

/* Trees the tests build by hand, so that the student's bvh_build plays no part: what is judged is
 * the traversal alone, on a tree whose shape makes order matter. The scenes are built so that no
 * two boxes are entered at the same t, and every count below is exact for a correct traversal. */
typedef struct { scene s; bvh b; work_check check; } order_tree;

static void order_tree_free(order_tree *t)
{
    work_check_free(&t->check);
    bvh_free(&t->b);
    scene_free(&t->s);
}

static void add_big_triangle(scene *s, float z)
{
    /* Covers (x, y) in [-1.5, 1.5]^2 and more, in the plane z. */
    scene_add_triangle(s, triangle_make(vec3_make(-4, -4, z), vec3_make(4, -4, z), vec3_make(0, 4, z), 0));
}

/* The hand-built tree must be one the tests of task 2.2 would accept, tight boxes and all. */
static void order_tree_check(order_tree *t)
{
    pl_diag why = pl_diag_default();
    if (bvh_validate(&t->b, &t->s, 64, true, NULL, &why) != PL_OK) PL_FAIL("test machinery: a bad tree: %s", why.error);
    work_check_init(&t->check, &t->b, &t->s);
}

/* The node array's children of the root, nodes[1] and nodes[2], hold a and b's trees; a is a leaf
 * of a_count primitives starting at prim slot 0; b is the tree `sub` (of the primitives after a's),
 * whose nodes follow. wall_second puts a at nodes[2]. */
static void order_tree_finish(order_tree *t, int a_count, const bvh *sub, bool a_second)
{
    int n = 3 + (sub->num_nodes - 1), prims = a_count + sub->num_prims;
    t->b.nodes = malloc((size_t)n * sizeof *t->b.nodes);
    t->b.prim_index = malloc((size_t)prims * sizeof *t->b.prim_index);
    if (!t->b.nodes || !t->b.prim_index) PL_FAIL("test machinery: out of memory");
    t->b.num_nodes = n;
    t->b.num_prims = prims;
    aabb a_box = aabb_empty();
    for (int i = 0; i < a_count; i++) {
        t->b.prim_index[i] = i;
        a_box = aabb_union(a_box, scene_prim_bounds(&t->s, i));
    }
    for (int i = 0; i < sub->num_prims; i++) t->b.prim_index[a_count + i] = sub->prim_index[i] + a_count;
    int a_at = a_second ? 2 : 1, sub_at = a_second ? 1 : 2;
    t->b.nodes[a_at] = (bvh_node){a_box, 0, a_count};
    /* sub's node i > 0 moves to i + 2; its interior nodes' children and its leaves' slots move too. */
    for (int i = 0; i < sub->num_nodes; i++) {
        bvh_node node = sub->nodes[i];
        node.first += node.count > 0 ? a_count : 2;
        t->b.nodes[i == 0 ? sub_at : i + 2] = node;
    }
    t->b.nodes[0] = (bvh_node){aabb_union(a_box, sub->nodes[0].box), 1, 0};
    order_tree_check(t);
}

/* A wall (2 triangles at z = 0) in front of a mesh (8 layers of 32 small triangles, z = -1 to
 * -2.75), the wall one child of the root and the mesh's own median tree the other. */
static void wall_tree(order_tree *t, bool wall_second)
{
    memset(t, 0, sizeof *t);
    scene mesh = {0};
    for (scene *s = &t->s; s; s = s == &t->s ? &mesh : NULL) scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(0)));
    scene_add_triangle(&t->s, triangle_make(vec3_make(-1, -1, 0), vec3_make(1, -1, 0), vec3_make(1, 1, 0), 0));
    scene_add_triangle(&t->s, triangle_make(vec3_make(-1, -1, 0), vec3_make(1, 1, 0), vec3_make(-1, 1, 0), 0));
    for (int layer = 0; layer < 8; layer++)
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                float z = -1.0f - 0.25f * (float)layer, x = -1.0f + 0.5f * (float)i, y = -1.0f + 0.5f * (float)j;
                triangle q[2] = {triangle_make(vec3_make(x, y, z), vec3_make(x + 0.5f, y, z), vec3_make(x + 0.5f, y + 0.5f, z), 0),
                                 triangle_make(vec3_make(x, y, z), vec3_make(x + 0.5f, y + 0.5f, z), vec3_make(x, y + 0.5f, z), 0)};
                for (int k = 0; k < 2; k++) scene_add_triangle(&t->s, q[k]), scene_add_triangle(&mesh, q[k]);
            }
    bvh sub;
    fixture_build_median(&sub, &mesh, 4);
    order_tree_finish(t, 2, &sub, wall_second);
    bvh_free(&sub);
    scene_free(&mesh);
}

/* Ray k of 49, straight down -z from z = 5 through the wall, at points off the wall's edges. */
static ray wall_ray(int k) { return ray_make(vec3_make(-0.87f + 0.29f * (float)(k % 7), -0.87f + 0.29f * (float)(k / 7), 5), vec3_make(0, 0, -1), 0.0f, INFINITY); }

/* A query of either kind, for the order checks below (each reads the one it judges). */
typedef struct { closest_fn closest; any_fn any; } query_fn;

/* The closest hit on the wall tree, both ways round: true when every ray hit the wall testing no
 * primitive of the mesh behind it; otherwise false with what the query did in why. */
static bool nothing_behind_the_wall(query_fn q, char *why, size_t why_len)
{
    closest_fn query = q.closest;
    int most = 0, mesh = 0;
    for (int order = 0; order < 2; order++) {
        order_tree t;
        wall_tree(&t, order == 1);
        mesh = t.s.num_triangles - 2;
        for (int k = 0; k < 49; k++) {
            ray r = wall_ray(k);
            hit h;
            work_check_begin(&t.check);
            bool found = query(&t.b, &t.s, &r, &h);
            work_check_end(&t.check);
            int behind = 0;
            for (int i = 0; i < t.check.trace.num_prims; i++) behind += t.check.trace.prims[i] >= 2;
            most = t.check.trace.num_prims > most ? t.check.trace.num_prims : most;
            if (!found || h.prim > 1)
                snprintf(why, why_len, "ray %d from (%.2f, %.2f, 5) straight at a wall: %s", k, (double)r.o.x,
                         (double)r.o.y, found ? "it reported a hit behind the wall" : "it reported no hit");
            else if (behind > 0)
                snprintf(why, why_len, "ray %d hit a wall at t = %.3g, then tested %d triangles of the mesh behind it "
                         "(the wall was child %d of the root): visit the nearer child first, and skip a popped node "
                         "whose t_enter > r->max_t (task 2.3)", k, (double)h.t, behind, order + 1);
            if (!found || h.prim > 1 || behind > 0) {
                order_tree_free(&t);
                return false;
            }
        }
        order_tree_free(&t);
    }
    snprintf(why, why_len, "2 x 49 rays at a wall in front of a %d-triangle mesh, the wall either child of the root: at most "
             "%d primitive tests on one ray, none of the mesh", mesh, most);
    return true;
}

/* A row of ROW_BOXES boxes along x, each a leaf of 4 triangles: two squares of side 1 facing along
 * x, at c - 0.25 and c + 0.25 for box c = 0, 1, 2, ... Half a unit of empty space lies between
 * neighbours, so no two nodes are entered at the same t. Over them a balanced tree whose children
 * are stored in the row's order at even depths and reversed at odd ones: an order that ignores the
 * ray goes wrong at some level, from one end of the row or the other. */
#define ROW_BOXES 16
#define ROW_RAYS 18

static void add_square_facing_x(scene *s, float x)
{
    scene_add_triangle(s, triangle_make(vec3_make(x, -0.5f, -0.5f), vec3_make(x, 0.5f, -0.5f), vec3_make(x, 0.5f, 0.5f), 0));
    scene_add_triangle(s, triangle_make(vec3_make(x, -0.5f, -0.5f), vec3_make(x, 0.5f, 0.5f), vec3_make(x, -0.5f, 0.5f), 0));
}

/* Writes the subtree over boxes [lo, hi) at node `at`, its children from node *next on; returns its box. */
static aabb row_subtree(order_tree *t, int at, int lo, int hi, int depth, int *next)
{
    if (hi - lo == 1) {
        aabb box = aabb_empty();
        for (int i = 0; i < 4; i++) box = aabb_union(box, scene_prim_bounds(&t->s, 4 * lo + i));
        t->b.nodes[at] = (bvh_node){box, 4 * lo, 4};
        return box;
    }
    int first = *next, mid = (lo + hi) / 2, reversed = depth % 2;
    *next += 2;
    aabb box = aabb_union(row_subtree(t, first + reversed, lo, mid, depth + 1, next),
                          row_subtree(t, first + 1 - reversed, mid, hi, depth + 1, next));
    t->b.nodes[at] = (bvh_node){box, first, 0};
    return box;
}

static void row_tree(order_tree *t)
{
    memset(t, 0, sizeof *t);
    scene_add_material(&t->s, material_make(rgb_gray(0.5f), rgb_gray(0)));
    for (int c = 0; c < ROW_BOXES; c++) add_square_facing_x(&t->s, (float)c - 0.25f), add_square_facing_x(&t->s, (float)c + 0.25f);
    t->b.num_nodes = 2 * ROW_BOXES - 1;
    t->b.num_prims = 4 * ROW_BOXES;
    t->b.nodes = malloc((size_t)t->b.num_nodes * sizeof *t->b.nodes);
    t->b.prim_index = malloc((size_t)t->b.num_prims * sizeof *t->b.prim_index);
    if (!t->b.nodes || !t->b.prim_index) PL_FAIL("test machinery: out of memory");
    for (int i = 0; i < t->b.num_prims; i++) t->b.prim_index[i] = i;  /* box c's leaf holds 4c .. 4c + 3 */
    int next = 1;
    (void)row_subtree(t, 0, 0, ROW_BOXES, 0, &next);
    order_tree_check(t);
}

/* Ray k of ROW_RAYS: the first half from x = -5 along +x, the rest from the other end along -x,
 * through the squares away from their edges, tilted a little so that no slab sees a zero
 * direction component (the order is judged here, not the slab test's infinities). */
static ray row_ray(int k)
{
    int i = k % (ROW_RAYS / 2);
    bool from_left = k < ROW_RAYS / 2;
    vec3 o = vec3_make(from_left ? -5.0f : (float)ROW_BOXES + 4.0f, -0.3f + 0.27f * (float)(i % 3), -0.25f + 0.26f * (float)(i / 3));
    return ray_make(o, vec3_normalize(vec3_make(from_left ? 1.0f : -1.0f, 0.01f, -0.007f)), 0.0f, INFINITY);
}

/* The closest hit along the row, from both ends: true when every ray hit the first box on its way
 * testing no primitive of another box; otherwise false with what the query did in why. */
static bool nothing_behind_the_first_box(query_fn q, char *why, size_t why_len)
{
    order_tree t;
    row_tree(&t);
    bool ok = true;
    int most = 0;
    for (int k = 0; k < ROW_RAYS && ok; k++) {
        ray r = row_ray(k);
        int first_box = k < ROW_RAYS / 2 ? 0 : ROW_BOXES - 1;
        hit h;
        work_check_begin(&t.check);
        bool found = q.closest(&t.b, &t.s, &r, &h);
        work_check_end(&t.check);
        int behind = 0, first_leaf = t.check.leaf_of_prim[4 * first_box];
        for (int i = 0; i < t.check.trace.num_prims; i++) behind += t.check.leaf_of_prim[t.check.trace.prims[i]] != first_leaf;
        most = t.check.trace.num_prims > most ? t.check.trace.num_prims : most;
        const char *end = k < ROW_RAYS / 2 ? "left" : "right";
        if (!found || h.prim / 4 != first_box)
            snprintf(why, why_len, "ray %d from the %s end of a row of %d boxes: %s", k, end, ROW_BOXES,
                     found ? "it reported a hit behind the first box" : "it reported no hit");
        else if (behind > 0)
            snprintf(why, why_len, "ray %d from the %s end of a row of %d boxes hit the first box at t = %.3g, then "
                     "tested %d triangles of the boxes behind it: visit the nearer child first at every level, and "
                     "skip a popped node whose t_enter > r->max_t (task 2.3)", k, end, ROW_BOXES, (double)h.t, behind);
        ok = found && h.prim / 4 == first_box && behind == 0;
    }
    order_tree_free(&t);
    if (ok)
        snprintf(why, why_len, "%d rays along a row of %d boxes of 4 triangles, from both ends: at most %d primitive "
                 "tests on one ray, none of another box", ROW_RAYS, ROW_BOXES, most);
    return ok;
}

/* The test's own nearest-first traversal with the early exit, as the handout describes it. */
static bool nearest_first(const bvh *b, const scene *s, ray *r, hit *h)
{
    int stack[2 * BVH_MAX_DEPTH + 2], top = 0;
    stack[top++] = 0;
    bool found = false;
    while (top > 0) {
        const bvh_node *n = bvh_visit(b, stack[--top]);
        if (!box_overlaps(n, r)) continue;  /* with the current max_t: what lies behind a hit is skipped */
        if (n->count > 0) {
            for (int i = 0; i < n->count; i++) found |= scene_prim_intersect(s, b->prim_index[n->first + i], r, h);
            continue;
        }
        /* The child whose box centre is nearer along the ray goes on top (read directly: the test's
         * own traversal, whose visit counts nobody judges). */
        const bvh_node *c0 = &b->nodes[n->first], *c1 = &b->nodes[n->first + 1];
        vec3 m0 = vec3_scale(vec3_add(c0->box.min, c0->box.max), 0.5f), m1 = vec3_scale(vec3_add(c1->box.min, c1->box.max), 0.5f);
        bool first_nearer = vec3_dot(vec3_sub(m0, r->o), r->d) <= vec3_dot(vec3_sub(m1, r->o), r->d);
        stack[top++] = first_nearer ? n->first + 1 : n->first;
        stack[top++] = first_nearer ? n->first : n->first + 1;
    }
    return found;
}

/* An order check run on the part's query, after the check itself: a correct query passes and a
 * buggy one is caught with a message holding `expect` (else the check is the test's fault). */
static void judge_order(bool (*check)(query_fn, char *, size_t), query_fn correct, query_fn bug, const char *bug_name,
                        const char *expect, query_fn part)
{
    char why[512];
    /* Each verdict waits for assert_implemented: with part 1 or part 2 a stub, the test says which
     * task is missing, not that a traversal found nothing. */
    bool correct_passed = check(correct, why, sizeof why);
    assert_implemented();
    if (!correct_passed) fail_msg("test machinery: a correct traversal failed: %s", why);
    expect_caught(check(bug, why, sizeof why), bug_name, why, expect);
    bool part_passed = check(part, why, sizeof why);
    assert_implemented();
    if (!part_passed) fail_msg("%s", why);
    print_message("      %s\n", why);  /* what the part did, as the log test prints its work */
}

static void test_bvh_intersect__nearer_child_first_nothing_behind_the_nearest_hit(void **state)
{
    (void)state;
    judge_order(nothing_behind_the_wall, (query_fn){.closest = nearest_first}, (query_fn){.closest = dfs_closest},
                "a left-first traversal", "child 2 of the root", (query_fn){.closest = bvh_intersect});
    judge_order(nothing_behind_the_first_box, (query_fn){.closest = nearest_first}, (query_fn){.closest = dfs_closest},
                "a left-first traversal", "boxes behind it", (query_fn){.closest = bvh_intersect});
}

/* Two leaves under the root: A holds a small triangle off to the side (it stretches A's box
 * forward, so the ray enters A first, at t = 6) and two big ones at z = -7 and -8; B holds big
 * ones at z = -2 and -3 (entered at t = 7). A closest-hit search tests B after A's hit at t = 12;
 * an any-hit query has its answer at its first hit. */
static void stack_tree(order_tree *t)
{
    memset(t, 0, sizeof *t);
    scene_add_material(&t->s, material_make(rgb_gray(0.5f), rgb_gray(0)));
    scene_add_triangle(&t->s, triangle_make(vec3_make(3, 0, -1), vec3_make(3.5f, 0, -1), vec3_make(3, 0.5f, -1), 0));
    add_big_triangle(&t->s, -7);
    add_big_triangle(&t->s, -8);
    add_big_triangle(&t->s, -2);
    add_big_triangle(&t->s, -3);
    bvh leaf_b = {.nodes = malloc(sizeof(bvh_node)), .num_nodes = 1, .prim_index = malloc(2 * sizeof(int)), .num_prims = 2};
    if (!leaf_b.nodes || !leaf_b.prim_index) PL_FAIL("test machinery: out of memory");
    leaf_b.prim_index[0] = 0, leaf_b.prim_index[1] = 1;  /* prims 3 and 4, numbered after A's */
    leaf_b.nodes[0] = (bvh_node){aabb_union(scene_prim_bounds(&t->s, 3), scene_prim_bounds(&t->s, 4)), 0, 2};
    order_tree_finish(t, 3, &leaf_b, false);
    bvh_free(&leaf_b);
}

/* Any hit on the stack tree: true when no ray tested a primitive of another leaf after the first
 * primitive it tested that hits (the rest of that leaf may still be tested); else false, why. */
static bool stops_at_the_first_hit(query_fn q, char *why, size_t why_len)
{
    any_fn query = q.any;
    order_tree t;
    stack_tree(&t);
    bool ok = true;
    int most = 0;
    for (int k = 0; k < 9 && ok; k++) {
        ray r = ray_make(vec3_make(-0.3f + 0.3f * (float)(k % 3), -0.3f + 0.3f * (float)(k / 3), 5), vec3_make(0, 0, -1), 0.0f, 20.0f);
        work_check_begin(&t.check);
        bool occluded = query(&t.b, &t.s, &r);
        work_check_end(&t.check);
        const counters_trace *tr = &t.check.trace;
        int first = -1, after = 0;
        most = tr->num_prims > most ? tr->num_prims : most;
        for (int i = 0; i < tr->num_prims; i++) {
            ray probe = r;
            hit scratch;
            if (first < 0 && scene_prim_intersect(&t.s, tr->prims[i], &probe, &scratch)) first = i;
            else if (first >= 0) after += t.check.leaf_of_prim[tr->prims[i]] != t.check.leaf_of_prim[tr->prims[first]];
        }
        if (!occluded) snprintf(why, why_len, "ray %d passes through four triangles and bvh_occluded says nothing is hit", k);
        else if (after > 0)
            snprintf(why, why_len, "ray %d: bvh_occluded tested primitive %d, which hits, then %d primitives of another leaf: "
                     "an any-hit query returns at the first hit it finds, it does not look for the nearest (task 2.4)",
                     k, tr->prims[first], after);
        ok = occluded && after == 0;
    }
    order_tree_free(&t);
    if (ok)
        snprintf(why, why_len, "9 shadow rays through 4 triangles in two leaves: at most %d primitive tests on one ray, "
                 "none of another leaf after the first hit", most);
    return ok;
}

/* The search for the closest hit, answering as an any-hit query: the bug the test is for. */
static bool any_by_closest(const bvh *b, const scene *s, const ray *r)
{
    ray probe = *r;
    hit scratch;
    return nearest_first(b, s, &probe, &scratch);
}

static void test_bvh_occluded__stops_at_the_first_hit(void **state)
{
    (void)state;
    judge_order(stops_at_the_first_hit, (query_fn){.any = dfs_any}, (query_fn){.any = any_by_closest},
                "a closest-hit search", "first hit", (query_fn){.any = bvh_occluded});
}

int complexity_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_intersect__work_grows_like_log_n, test_setup),
        cmocka_unit_test_setup(test_bvh_occluded__counts_its_work_through_the_framework, test_setup),
        cmocka_unit_test_setup(test_bvh_intersect__nearer_child_first_nothing_behind_the_nearest_hit, test_setup),
        cmocka_unit_test_setup(test_bvh_occluded__stops_at_the_first_hit, test_setup),
    };
    return cmocka_run_group_tests_name("part2: work grows like log N", tests, NULL, free_trees);
}
