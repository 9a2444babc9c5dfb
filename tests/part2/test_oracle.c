/* Test machinery: not part of any assignment. Tasks 2.3 and 2.4: closest and any hit through the
 * BVH agree with the linear scan (framework/accel.h) on 100,000 rays per scene.
 *
 * What "agree" means. Floating point decides some hits by a hair, and a BVH's box tests and the
 * primitive test round differently, so:
 * - Ties: two primitives hit at the same t (duplicates, a ray through an edge two triangles share)
 *   may be reported either way, and neighbours compute t a few ulps apart. A different primitive
 *   passes when its t is within TIE_REL_TOL of the scan's and it really is hit there (re-tested
 *   alone: same t, normal and barycentrics).
 * - Grazes: a hit on a triangle's edge or vertex, on a degenerate triangle, or nearly tangent to a
 *   sphere exists or not by rounding (and its t may be far off when the ray is nearly parallel to
 *   the triangle). The BVH may skip it; it must then agree with the scan of the other primitives.
 * Anything else fails: a different t, a hit the scan does not see, a missed non-grazing hit. The
 * rays are fixed (seeded), so a verdict never changes between runs. */
#include "../common/test.h"
#include "fixtures.h"
#include "../common/procmesh.h"
#include "../../framework/accel.h"
#include "../../framework/rng.h"
#include "../../framework/sampler.h"
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RAYS_PER_SCENE 100000
#define ORACLE_SEED 184
#define TIE_REL_TOL 1e-5f
#define GRAZE_BARY_TOL 1e-4f   /* barycentric distance from an edge */
#define GRAZE_AREA_TOL 1e-5f   /* |e1 x e2| / longest edge^2 below this: a degenerate triangle */
#define GRAZE_COS_TOL 1e-3f    /* |cos| between ray and sphere normal below this: tangent */
#define GRAZE_MAX 8          /* grazed primitives one ray may skip */
#define ORACLE_THREADS 2     /* the linear scan is the slow half: share it between the cores */

/* ---- the rays: six kinds, interleaved ----------------------------------------------------- */

typedef struct {
    const scene *s;
    aabb bounds, wide;  /* the scene's bounds, and the same grown by half its size on every side */
    rng g;
} ray_source;

static vec3 point_in(aabb b, rng *g)
{
    return vec3_make(b.min.x + (b.max.x - b.min.x) * rng_uniform(g), b.min.y + (b.max.y - b.min.y) * rng_uniform(g),
                     b.min.z + (b.max.z - b.min.z) * rng_uniform(g));
}

/* A point on some primitive: on an edge or at a vertex of a triangle, or on a sphere. */
static vec3 point_on_edge(ray_source *src)
{
    const scene *s = src->s;
    int p = (int)(rng_u32(&src->g) % (uint32_t)scene_prim_count(s));
    if (p >= s->num_triangles) {
        const sphere *sp = &s->spheres[p - s->num_triangles];
        return vec3_add(sp->center, vec3_scale(sample_uniform_sphere(rng_uniform2(&src->g)), sp->radius));
    }
    const triangle *t = &s->triangles[p];
    vec3 v[3] = {t->p0, t->p1, t->p2};
    int e = (int)(rng_u32(&src->g) % 3);
    float u = rng_uniform(&src->g) < 0.25f ? 0.0f : rng_uniform(&src->g);  /* a quarter aim at a vertex */
    return vec3_lerp(v[e], v[(e + 1) % 3], u);
}

static ray next_ray(ray_source *src, int i)
{
    rng *g = &src->g;
    vec3 dir = sample_uniform_sphere(rng_uniform2(g));
    switch (i % 6) {
    case 0: /* anywhere around the scene, any direction */
        return ray_make(point_in(src->wide, g), dir, 0.0f, INFINITY);
    case 1: /* from inside the scene's bounds */
        return ray_make(point_in(src->bounds, g), dir, 0.0f, INFINITY);
    case 2: { /* aimed at an edge or a vertex: grazing hits, shared edges */
        vec3 o = point_in(src->wide, g);
        return ray_make(o, vec3_normalize(vec3_sub(point_on_edge(src), o)), 0.0f, INFINITY);
    }
    case 3: { /* parallel to an axis (two zero components), in the planes of a point on an edge */
        vec3 o = point_in(src->wide, g), q = point_on_edge(src);
        int axis = (int)(rng_u32(g) % 3);
        float sign = rng_uniform(g) < 0.5f ? 1.0f : -1.0f;
        vec3 d = vec3_make(axis == 0 ? sign : 0.0f, axis == 1 ? sign : 0.0f, axis == 2 ? sign : 0.0f);
        o = vec3_make(axis == 0 ? o.x : q.x, axis == 1 ? o.y : q.y, axis == 2 ? o.z : q.z);
        return ray_make(o, d, 0.0f, INFINITY);
    }
    case 4: { /* a segment between two points: unnormalised d, max_t = 1 */
        vec3 o = point_in(src->wide, g);
        return ray_make(o, vec3_sub(point_in(src->wide, g), o), 0.0f, 1.0f);
    }
    default: { /* a shadow ray: from a surface towards a point, min_t = EPS_F */
        vec3 o = point_on_edge(src), target = point_in(src->bounds, g);
        return ray_make(o, vec3_sub(target, o), EPS_F, 1.0f - EPS_F);
    }
    }
}

/* ---- the oracle, with ties and grazes ------------------------------------------------------ */

static bool same_hit(const hit *a, const hit *b)
{
    return a->t == b->t && a->prim == b->prim && a->material == b->material && a->b1 == b->b1 &&
           a->b2 == b->b2 && a->n.x == b->n.x && a->n.y == b->n.y && a->n.z == b->n.z;
}

/* The linear scan's closest hit, skipping the primitives in skip[0 .. num_skip - 1]. */
static bool linear_intersect_skipping(const scene *s, ray *r, hit *h, const int *skip, int num_skip)
{
    if (num_skip == 0) return linear_intersect(s, r, h);  /* the framework's oracle itself */
    bool found = false;
    for (int p = 0; p < scene_prim_count(s); p++) {
        bool skipped = false;
        for (int k = 0; k < num_skip; k++) skipped |= skip[k] == p;
        if (!skipped) found |= scene_prim_intersect(s, p, r, h);
    }
    return found;
}

/* Whether rounding alone may decide hit h: a hit on or next to a triangle's edges (a barycentric
 * within GRAZE_BARY_TOL of 0), any hit on a degenerate triangle (whose test divides by a rounding
 * residue), or a ray nearly tangent to a sphere. */
static bool is_graze(const scene *s, const ray *r, const hit *h)
{
    if (h->prim >= s->num_triangles) return fabsf(vec3_dot(h->n, vec3_normalize(r->d))) < GRAZE_COS_TOL;
    const triangle *t = &s->triangles[h->prim];
    vec3 e1 = vec3_sub(t->p1, t->p0), e2 = vec3_sub(t->p2, t->p0), e3 = vec3_sub(t->p2, t->p1);
    float longest2 = fmaxf(vec3_dot(e1, e1), fmaxf(vec3_dot(e2, e2), vec3_dot(e3, e3)));
    bool degenerate = vec3_length(vec3_cross(e1, e2)) <= GRAZE_AREA_TOL * longest2;
    float b0 = 1.0f - h->b1 - h->b2;
    return degenerate || fminf(b0, fminf(h->b1, h->b2)) <= GRAZE_BARY_TOL;
}

typedef struct {
    const char *why;  /* NULL when the BVH agrees */
    bool tie;         /* agreed through a tie or a graze */
    bool linear_found;
    hit linear, bvh;  /* the scan's answer and the BVH's, for the message */
} verdict;

/* Which queries a check asks, so a test can name the one task it grades. */
typedef enum { CHECK_CLOSEST = 1, CHECK_ANY = 2, CHECK_BOTH = 3 } oracle_checks;

/* bvh_intersect against the scan (v->linear), skipping grazed primitives one at a time. */
static void judge_closest(const scene *s, const bvh *b, ray r, verdict *v)
{
    ray rb = r;
    bool found_b = bvh_intersect(b, s, &rb, &v->bvh);
    if (found_b) {
        ray again = r;
        hit alone;
        if (rb.max_t != v->bvh.t) v->why = "r->max_t is not the hit's t";
        else if (!scene_prim_intersect(s, v->bvh.prim, &again, &alone) || !same_hit(&alone, &v->bvh))
            v->why = "the hit record is not what the primitive's own test gives";
    } else if (rb.max_t != r.max_t) {
        v->why = "a miss changed r->max_t";
    }

    int skip[GRAZE_MAX], num_skip = 0;
    const char *disagreement = NULL;
    bool found_l = v->linear_found;
    hit hl = v->linear;
    for (;;) {
        bool agree;
        if (found_l != found_b) agree = false;
        else if (!found_l) agree = true;
        else if (hl.prim == v->bvh.prim) agree = same_hit(&hl, &v->bvh);
        else agree = fabsf(hl.t - v->bvh.t) <= TIE_REL_TOL * fmaxf(fabsf(hl.t), 1e-3f);
        if (num_skip == 0 && !agree)
            disagreement = found_l != found_b ? (found_l ? "the BVH missed a hit the linear scan finds" : "the BVH hit something the linear scan does not")
                                              : "a different primitive at a different t";
        if (agree) {
            v->tie = num_skip > 0 || (found_l && hl.prim != v->bvh.prim);
            return;
        }
        if (!found_l || num_skip == GRAZE_MAX || !is_graze(s, &r, &hl)) {
            if (!v->why) v->why = disagreement;
            return;
        }
        skip[num_skip++] = hl.prim;
        ray rl = r;
        found_l = linear_intersect_skipping(s, &rl, &hl, skip, num_skip);
    }
}

/* bvh_occluded: the scan finds a hit exactly when it finds a closest one. The BVH may answer
 * "clear" only when every hit the scan sees is a graze. */
static void judge_any(const scene *s, const bvh *b, ray r, verdict *v)
{
    bool occ_b = bvh_occluded(b, s, &r), occ_l = v->linear_found;
    if (occ_b && !occ_l && !v->why) v->why = "bvh_occluded finds a hit, the linear scan does not";
    if (!occ_b && occ_l && !v->why) {
        int skip[GRAZE_MAX], n = 0;
        hit hk = v->linear;
        bool only_grazes = is_graze(s, &r, &hk);
        while (only_grazes && n < GRAZE_MAX - 1) {
            skip[n++] = hk.prim;
            ray rk = r;
            if (!linear_intersect_skipping(s, &rk, &hk, skip, n)) break;
            only_grazes = is_graze(s, &r, &hk);
        }
        if (!only_grazes || n == GRAZE_MAX - 1) v->why = "bvh_occluded says clear, the linear scan finds a hit";
        else v->tie = true;
    }
}

static verdict judge_ray(const scene *s, const bvh *b, ray r, oracle_checks checks)
{
    verdict v;
    memset(&v, 0, sizeof v);
    ray rl = r;
    v.linear_found = linear_intersect(s, &rl, &v.linear);  /* the oracle, for both queries */
    if (checks & CHECK_CLOSEST) judge_closest(s, b, r, &v);
    if (checks & CHECK_ANY) judge_any(s, b, r, &v);
    return v;
}

/* ---- one scene, judged on two threads ------------------------------------------------------- */

typedef struct {
    const scene *s;
    const bvh *b;
    const ray *rays;
    verdict *verdicts;
    oracle_checks checks;
    int first, step;
} oracle_job;

static void *oracle_worker(void *arg)
{
    const oracle_job *job = arg;
    for (int i = job->first; i < RAYS_PER_SCENE; i += job->step)
        job->verdicts[i] = judge_ray(job->s, job->b, job->rays[i], job->checks);
    return NULL;
}

/* Judges RAYS_PER_SCENE rays through the tree b over s, failing with the first disagreement. */
static void check_tree_against_oracle(const scene *s, const bvh *b, const char *name, oracle_checks checks)
{
    ray_source src = {s, scene_bounds(s), scene_bounds(s), rng_seeded(ORACLE_SEED, 0)};
    vec3 grow = vec3_scale(aabb_extent(src.bounds), 0.5f);
    src.wide.min = vec3_sub(src.wide.min, grow);
    src.wide.max = vec3_add(src.wide.max, grow);
    ray *rays = malloc(RAYS_PER_SCENE * sizeof *rays);
    verdict *verdicts = malloc(RAYS_PER_SCENE * sizeof *verdicts);
    if (!rays || !verdicts) fail_msg("out of memory");
    for (int i = 0; i < RAYS_PER_SCENE; i++) rays[i] = next_ray(&src, i);

    /* A stub says so on the first ray, before 100,000 linear scans. */
    judge_ray(s, b, rays[0], checks);
    if (pl_todo_count() > 0) {
        free(rays);
        free(verdicts);
        assert_implemented();
    }

    oracle_job jobs[ORACLE_THREADS];
    pthread_t threads[ORACLE_THREADS];
    for (int k = 0; k < ORACLE_THREADS; k++) {
        jobs[k] = (oracle_job){s, b, rays, verdicts, checks, k, ORACLE_THREADS};
        if (k > 0 && pthread_create(&threads[k], NULL, oracle_worker, &jobs[k]) != 0) fail_msg("pthread_create failed");
    }
    oracle_worker(&jobs[0]);
    for (int k = 1; k < ORACLE_THREADS; k++) pthread_join(threads[k], NULL);

    int wrong = 0, ties = 0, first = -1;
    for (int i = 0; i < RAYS_PER_SCENE; i++) {
        ties += verdicts[i].tie;
        if (verdicts[i].why && wrong++ == 0) first = i;
    }
    print_message("      %s: %d primitives, %d rays (seed %d), %d ties or grazes\n", name, scene_prim_count(s),
                  RAYS_PER_SCENE, ORACLE_SEED, ties);
    char msg[640] = "";
    if (wrong) {
        const ray *r = &rays[first];
        const verdict *v = &verdicts[first];
        snprintf(msg, sizeof msg,
                 "%s: %d of %d rays disagree with the linear scan; first: ray %d (o = (%.9g, %.9g, %.9g), d = (%.9g, %.9g, %.9g), "
                 "t in [%g, %g]): %s; linear: prim %d at t = %.9g; BVH: prim %d at t = %.9g",
                 name, wrong, RAYS_PER_SCENE, first, r->o.x, r->o.y, r->o.z, r->d.x, r->d.y, r->d.z, r->min_t,
                 r->max_t, v->why, v->linear.prim, v->linear.t, v->bvh.prim, v->bvh.t);
    }
    free(rays);
    free(verdicts);
    if (wrong) fail_msg("%s", msg);
}

/* Both queries through the student's own tree. */
static void check_scene_against_oracle(const scene *s, const char *name)
{
    bvh b;
    pl_status st = bvh_build(&b, s, 4);
    assert_implemented();
    if (st != PL_OK) fail_msg("%s: bvh_build returned %s", name, pl_status_name(st));
    check_tree_against_oracle(s, &b, name, CHECK_BOTH);
    bvh_free(&b);
}

/* One query through a tree the tests build (fixture_build_median), so tasks 2.3 and 2.4 are graded
 * whatever state task 2.2 is in. */
static void check_given_tree(oracle_checks checks)
{
    scene soup = {0}, mesh = {0};
    fixture_random_soup(&soup, 3000, 2002);
    scene_add_material(&mesh, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&mesh, procmesh_rows_for(5000), vec3_make(0, 0, 0), 1.0f, 0), PL_OK);
    const scene *scenes[2] = {&soup, &mesh};
    const char *names[2] = {"soup of 3000 (seed 2002), given tree", "bumpy sphere, given tree"};
    for (int i = 0; i < 2; i++) {
        bvh b;
        fixture_build_median(&b, scenes[i], 4);
        pl_diag why = pl_diag_default();
        if (bvh_validate(&b, scenes[i], 4, true, NULL, &why) != PL_OK)
            fail_msg("test machinery: the given tree is invalid: %s", why.error);
        check_tree_against_oracle(scenes[i], &b, names[i], checks);
        bvh_free(&b);
    }
    scene_free(&soup);
    scene_free(&mesh);
}

static void test_bvh_intersect__matches_linear_scan_on_a_given_tree(void **state) { check_given_tree(CHECK_CLOSEST); }
static void test_bvh_occluded__matches_linear_scan_on_a_given_tree(void **state) { check_given_tree(CHECK_ANY); }

static void check_scene_if_not_empty(const scene *s, const char *path)
{
    if (scene_prim_count(s) > 0) check_scene_against_oracle(s, path);
}

static void test_bvh_intersect__matches_linear_scan_on_shipped_scenes(void **state)
{
    fixture_for_each_scene(check_scene_if_not_empty);
}

static void test_bvh_intersect__matches_linear_scan_on_random_soups(void **state)
{
    int sizes[] = {1, 50, 3000};
    for (int i = 0; i < 3; i++) {
        scene s = {0};
        fixture_random_soup(&s, sizes[i], 2000 + i);
        char name[64];
        snprintf(name, sizeof name, "soup of %d (seed %d)", sizes[i], 2000 + i);
        check_scene_against_oracle(&s, name);
        scene_free(&s);
    }
}

static void test_bvh_intersect__matches_linear_scan_on_a_closed_mesh(void **state)
{
    /* A watertight mesh: every ray aimed at an edge hits two triangles that share it. */
    scene s = {0};
    scene_add_material(&s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    assert_int_equal(procmesh_bumpy_sphere(&s, procmesh_rows_for(5000), vec3_make(0, 0, 0), 1.0f, 0), PL_OK);
    check_scene_against_oracle(&s, "bumpy sphere");
    scene_free(&s);
}

int oracle_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_bvh_intersect__matches_linear_scan_on_a_given_tree, test_setup),
        cmocka_unit_test_setup(test_bvh_occluded__matches_linear_scan_on_a_given_tree, test_setup),
        cmocka_unit_test_setup(test_bvh_intersect__matches_linear_scan_on_random_soups, test_setup),
        cmocka_unit_test_setup(test_bvh_intersect__matches_linear_scan_on_a_closed_mesh, test_setup),
        cmocka_unit_test_setup(test_bvh_intersect__matches_linear_scan_on_shipped_scenes, test_setup),
    };
    return cmocka_run_group_tests_name("part2: closest and any hit vs the linear scan (tasks 2.3, 2.4)", tests, NULL, NULL);
}
