/* Part 2: a bounding volume hierarchy with the surface area heuristic.
 * Handout: handout/part2.md. Test: make test-part2. */
#ifndef PL_PART2_H
#define PL_PART2_H

#include <stdbool.h>
#include "../../framework/scene.h"
#include "../../framework/aabb.h"
#include "../../framework/ray.h"
#include "../../framework/status.h"

/* One node of the flat node array. Interior nodes have count == 0 and two children stored next
 * to each other at nodes[first] and nodes[first + 1]; leaves have count > 0 and hold primitives
 * prim_index[first .. first + count - 1]. nodes[0] is the root. */
typedef struct {
    aabb box;   /* bounds of everything below this node */
    int first;  /* interior: index of the left child; leaf: first slot in prim_index */
    int count;  /* primitives in a leaf; 0 for an interior node */
} bvh_node;

typedef struct {
    bvh_node *nodes; int num_nodes;    /* owned */
    int *prim_index; int num_prims;    /* owned: scene primitive indices, grouped by leaf */
} bvh;

/* TASK 2.1: slab test. */
bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit);
/* TASK 2.2: SAH build. */
pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size);
/* TASK 2.3: closest hit. */
bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h);
/* TASK 2.4: any hit. */
bool bvh_occluded(const bvh *b, const scene *s, const ray *r);

/* Framework: releases the arrays and zeroes b. NULL-safe. */
void bvh_free(bvh *b);

#endif
