/* Part 2: a bounding volume hierarchy built with the surface area heuristic.
 * Handout: handout/part2.md. Test: make test-part2.
 *
 * Conventions (the tests rely on them):
 * - A ray "hits" a box when some t in [r->min_t, r->max_t] puts o + t d inside the closed box
 *   (faces, edges and corners count as inside).
 * - The BVH is one flat array of nodes; nodes[0] is the root and the two children of an interior
 *   node are stored side by side. Primitives are the scene's (scene.h: triangles, then spheres) and
 *   are tested only through scene_prim_intersect, so a hit found through the BVH is exactly the hit
 *   the linear scan (framework/accel.h) finds.
 * - No tree is deeper than BVH_MAX_DEPTH, so a traversal can keep its to-do list in a fixed array. */
#ifndef PL_PART2_H
#define PL_PART2_H

#include <stdbool.h>
#include "../../framework/scene.h"
#include "../../framework/aabb.h"
#include "../../framework/ray.h"
#include "../../framework/status.h"

/* Longest root-to-leaf path, in edges (the root alone has depth 0). */
#define BVH_MAX_DEPTH 64

/* One node of the flat node array. Interior nodes have count == 0 and two children stored next
 * to each other at nodes[first] and nodes[first + 1]; leaves have count > 0 and hold primitives
 * prim_index[first .. first + count - 1]. nodes[0] is the root. */
typedef struct {
    aabb box;   /* tight bounds of everything below this node: the union of its primitives' bounds */
    int first;  /* interior: index of the left child; leaf: first slot in prim_index */
    int count;  /* primitives in a leaf (1 .. max_leaf_size); 0 for an interior node */
} bvh_node;

typedef struct {
    bvh_node *nodes; int num_nodes;    /* owned; num_nodes == 0 for a scene without primitives */
    int *prim_index; int num_prims;    /* owned: scene primitive indices, grouped by leaf */
} bvh;

/* TASK 2.1: slab test. True when the ray hits box *b within [r->min_t, r->max_t]; then
 * [*t_enter, *t_exit] is the part of [r->min_t, r->max_t] the ray spends inside the box (so a ray
 * starting inside has *t_enter == r->min_t). Direction components may be +0 or -0: no NaN, no
 * division trap, and a ray lying in a face's plane still hits. On a miss the outputs are unspecified. */
bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit);

/* TASK 2.2: SAH build over every primitive of s. max_leaf_size >= 1 (else PL_ERR_INVALID).
 * Out: *out (overwritten; release it with bvh_free). PL_ERR_NOMEM leaves *out empty. */
pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size);

/* TASK 2.3: closest hit, as linear_intersect would find it: shrinks r->max_t and fills *h on a hit;
 * changes nothing on a miss. */
bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h);

/* TASK 2.4: any hit in [r->min_t, r->max_t] (shadow rays), as linear_occluded would answer. */
bool bvh_occluded(const bvh *b, const scene *s, const ray *r);

/* Framework: releases the arrays and zeroes b. NULL-safe. */
void bvh_free(bvh *b);

/* Framework (framework/heatmap.c): adds `nodes` to the calling thread's count of BVH nodes visited,
 * i.e. of node boxes tested against a ray. bvh_intersect and bvh_occluded call it once per query;
 * the heat map (--heatmap) and the complexity test read the count (bvh_take_visits, heatmap.h). */
void bvh_count_visits(int nodes);

#endif
