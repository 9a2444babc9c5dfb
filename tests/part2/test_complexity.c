/* Test machinery: not part of any assignment. The point of a BVH: the work a ray costs grows like
 * log N with the number of triangles N, not like N. Counted, never timed, and counted by the
 * framework: node visits where bvh_visit hands a node out, primitive tests in
 * scene_prim_intersect. A traversal has no way to report its own counts. */
#include "../common/test.h"
#include "../common/procmesh.h"
#include "../../parts/part2_bvh/part2.h"
#include "../../framework/accel.h"
#include "../../framework/rng.h"
#include "../../framework/sampler.h"
#include <stdio.h>

#define COMPLEXITY_RAYS 2000
/* Enough rays to see a linear scan's primitive tests; few, since each costs 10^6 of them. */
#define FAKE_RAYS 20
#define COMPLEXITY_SEED 42
/* From 10^4 to 10^6 triangles, log2 N grows by 1.5x; N^(1/2) would grow 10x and N 100x. A good
 * tree stays near 1.5x; 3x leaves room for a simpler but sound one and still rejects sqrt(N). */
#define MAX_GROWTH 3.0

/* A closest-hit query: part 2's bvh_intersect, or a stand-in the tests below use. */
typedef bool (*closest_fn)(const bvh *b, const scene *s, ray *r, hit *h);

/* Work per ray, as the framework counted it. */
typedef struct { double visits, prim_tests; } work;

/* The two bumpy spheres (about 10^4 and 10^6 triangles) and their trees from bvh_build, built on
 * first use and shared by the tests of this group (the large build is most of the group's time). */
typedef struct { scene s; bvh b; bool built; } sized_tree;
static sized_tree trees[2];
static const long TREE_SIZES[2] = {10000, 1000000};

static const sized_tree *tree_of(int which)
{
    sized_tree *t = &trees[which];
    if (t->built) return t;
    t->s = (scene){0};
    scene_add_material(&t->s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&t->s, procmesh_rows_for(TREE_SIZES[which]), vec3_make(0, 0, 0), 1.0f, 0),
                     PL_OK);
    pl_status st = bvh_build(&t->b, &t->s, 4);
    t->built = true;  /* whatever happened: the group teardown frees it */
    assert_implemented();
    if (st != PL_OK) fail_msg("bvh_build returned %s", pl_status_name(st));
    return t;
}

static int free_trees(void **state)
{
    (void)state;
    for (int i = 0; i < 2; i++) {
        if (!trees[i].built) continue;
        bvh_free(&trees[i].b);
        scene_free(&trees[i].s);
        trees[i].built = false;
    }
    return 0;
}

/* Mean work per ray of query for `rays` camera-like rays at tree `which`. */
static work mean_work(int which, closest_fn query, int rays)
{
    const sized_tree *t = tree_of(which);
    /* From a sphere of radius 3 towards points near the centre: every ray hits, as camera rays
     * on a close-up would. The same rays for every tree. */
    rng g = rng_seeded(COMPLEXITY_SEED, 0);
    bvh_take_visits();
    scene_take_prim_tests();
    for (int i = 0; i < rays; i++) {
        vec3 o = vec3_scale(sample_uniform_sphere(rng_uniform2(&g)), 3.0f);
        vec3 target = vec3_scale(sample_uniform_sphere(rng_uniform2(&g)), 0.5f);
        ray r = ray_make(o, vec3_normalize(vec3_sub(target, o)), 0.0f, INFINITY);
        hit h;
        query(&t->b, &t->s, &r, &h);
    }
    work w = {(double)bvh_take_visits() / rays, (double)scene_take_prim_tests() / rays};
    assert_implemented();
    print_message("      %d triangles: %.1f nodes visited, %.1f primitives tested per ray (%d rays, seed %d)\n",
                  t->s.num_triangles, w.visits, w.prim_tests, rays, COMPLEXITY_SEED);
    return w;
}

/* True when both counts stay within MAX_GROWTH from 10^4 to 10^6 triangles; otherwise false with
 * the reason in why (the caller fails at its own line). */
static bool grows_like_log_n(closest_fn query, int rays, char *why, size_t why_len)
{
    work small = mean_work(0, query, rays), large = mean_work(1, query, rays);
    if (small.visits == 0.0 || large.visits == 0.0)
        snprintf(why, why_len, "bvh_intersect visited no nodes: read each node whose box you test through bvh_visit (bvh.h)");
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

static void test_bvh_intersect__work_grows_like_log_n(void **state)
{
    char why[320];
    if (!grows_like_log_n(bvh_intersect, COMPLEXITY_RAYS, why, sizeof why)) fail_msg("%s", why);
}

/* A submission that fakes its work: it visits the root through bvh_visit, as a traversal
 * reporting "one visit per ray" did, then tests every primitive. The counts are the framework's,
 * so the primitive tests give it away. */
static bool faking_traversal(const bvh *b, const scene *s, ray *r, hit *h)
{
    if (b->num_nodes > 0) (void)bvh_visit(b, 0);
    return linear_intersect(s, r, h);
}

static void test_complexity__a_traversal_cannot_fake_its_counts(void **state)
{
    char why[320];
    if (grows_like_log_n(faking_traversal, FAKE_RAYS, why, sizeof why))
        fail_msg("test machinery: a linear scan that visits one node per ray passed the log N test");
}

int complexity_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_intersect__work_grows_like_log_n, test_setup),
        cmocka_unit_test_setup(test_complexity__a_traversal_cannot_fake_its_counts, test_setup),
    };
    return cmocka_run_group_tests_name("part2: work grows like log N", tests, NULL, free_trees);
}
