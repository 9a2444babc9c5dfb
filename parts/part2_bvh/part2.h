/* Part 2: a bounding volume hierarchy built with the surface area heuristic.
 * Handout: handout/part2.md. Test: make test-part2.
 *
 * The tree's types (bvh, bvh_node, BVH_MAX_DEPTH, bvh_free, bvh_visit) are the framework's:
 * framework/bvh.h, with the conventions the tests rely on.
 *
 * - A ray "hits" a box when some t in [r->min_t, r->max_t] puts o + t d inside the closed box
 *   (faces, edges and corners count as inside). */
#ifndef PL_PART2_H
#define PL_PART2_H

#include <stdbool.h>
#include "../../framework/scene.h"
#include "../../framework/aabb.h"
#include "../../framework/bvh.h"
#include "../../framework/ray.h"
#include "../../framework/status.h"

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

/* TASK 2.4: any hit in [r->min_t, r->max_t] (shadow rays), as linear_occluded would answer.
 * Both traversals call bvh_visit (framework/bvh.h) for every node they enter (the root and each
 * child whose box they test; never b->nodes[i] directly) and scene_prim_intersect for every
 * primitive they test (never triangle_intersect directly): the framework counts both, and the
 * tests check each ray's counts against its answer. */
bool bvh_occluded(const bvh *b, const scene *s, const ray *r);

#endif
