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
typedef struct { scene s; bvh b; work_check check; bool built, checked; } sized_tree;
static sized_tree trees[3];
static const long TREE_SIZES[3] = {10000, 1000000, 10000};
enum { SMALL = 0, LARGE = 1, GIVEN = 2 };

static sized_tree *tree_of(int which)
{
    sized_tree *t = &trees[which];
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
        if (st != PL_OK) fail_msg("bvh_build returned %s", pl_status_name(st));
    }
    pl_diag why = pl_diag_default();
    if (bvh_validate(&t->b, &t->s, 4, false, NULL, &why) != PL_OK) fail_msg("bvh_build made a malformed tree: %s", why.error);
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

int complexity_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_intersect__work_grows_like_log_n, test_setup),
        cmocka_unit_test_setup(test_bvh_occluded__counts_its_work_through_the_framework, test_setup),
    };
    return cmocka_run_group_tests_name("part2: work grows like log N", tests, NULL, free_trees);
}
