/* Adversary (issue 46): a part 2 with a valid tree that its traversal never uses. bvh_build halves
 * the index range (a tree bvh_validate accepts), bvh_intersect and bvh_occluded test every
 * primitive in turn. Its images are right; before, it reported (forged) node-visit counts of its own
 * and took both image cases, the hidden one included. Now the grader measures the render's CPU time
 * itself (the kernel's count) against the course's own part on the same case: a linear scan is tens
 * of times slower, and loses both cases whatever it says about its work. Its tree, split in index
 * order, also fails task 2.2's SAH cost check, which the judge makes on the returned tree itself.
 * part: 2
 * base: stub
 * replaces: parts/part2_bvh/bvh.c
 * expect: unit=lost images=0
 * present: the tree does not save work
 */
#include "part2.h"
#include <stdlib.h>

bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    float t0 = r->min_t, t1 = r->max_t;
    const float o[3] = {r->o.x, r->o.y, r->o.z}, d[3] = {r->d.x, r->d.y, r->d.z};
    const float lo[3] = {b->min.x, b->min.y, b->min.z}, hi[3] = {b->max.x, b->max.y, b->max.z};
    for (int a = 0; a < 3; a++) {
        float inv = 1.0f / d[a], near = (lo[a] - o[a]) * inv, far = (hi[a] - o[a]) * inv;
        if (near > far) { float t = near; near = far; far = t; }
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
        if (!(t0 <= t1)) return false;
    }
    *t_enter = t0, *t_exit = t1;
    return true;
}

/* Node `self` over prim_index[first .. first + count): halves of the index range, down to leaves of
 * at most max_leaf_size, children side by side: a valid, useless tree. */
static void halves(bvh *out, const scene *s, int self, int first, int count, int max_leaf_size, int *next)
{
    aabb box = aabb_empty();
    for (int i = first; i < first + count; i++) box = aabb_union(box, scene_prim_bounds(s, out->prim_index[i]));
    out->nodes[self].box = box;
    if (count <= max_leaf_size) {
        out->nodes[self].first = first, out->nodes[self].count = count;
        return;
    }
    int left = *next;
    *next += 2;
    out->nodes[self].first = left, out->nodes[self].count = 0;
    halves(out, s, left, first, count / 2, max_leaf_size, next);
    halves(out, s, left + 1, first + count / 2, count - count / 2, max_leaf_size, next);
}

pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    int n = scene_prim_count(s);
    *out = (bvh){0};
    if (max_leaf_size < 1) return PL_ERR_INVALID;
    if (n == 0) return PL_OK;
    out->nodes = calloc((size_t)(2 * n), sizeof *out->nodes);
    out->prim_index = malloc((size_t)n * sizeof *out->prim_index);
    if (!out->nodes || !out->prim_index) return PL_ERR_NOMEM;
    for (int i = 0; i < n; i++) out->prim_index[i] = i;
    out->num_prims = n;
    int next = 1;
    halves(out, s, 0, 0, n, max_leaf_size, &next);
    out->num_nodes = next;
    return PL_OK;
}

bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h)
{
    bool any = false;
    for (int i = 0; i < b->num_prims; i++) any = scene_prim_intersect(s, b->prim_index[i], r, h) || any;
    return any;
}

bool bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    ray copy = *r;
    hit h;
    for (int i = 0; i < b->num_prims; i++)
        if (scene_prim_intersect(s, b->prim_index[i], &copy, &h)) return true;
    return false;
}
