/* The BVH's data: the flat node array part 2 builds and the framework stores, frees, checks and
 * counts. Part 2's tasks (parts/part2_bvh/part2.h) fill and walk these structures; everything
 * here is the framework's, so a change to a part cannot change a layout the renderer, the heat
 * map and the tests read.
 *
 * Conventions (the tests rely on them):
 * - nodes[0] is the root; the two children of an interior node are stored side by side.
 * - Primitives are the scene's (scene.h: triangles, then spheres) and are tested only through
 *   scene_prim_intersect, so a hit found through the BVH is exactly the hit the linear scan finds.
 * - No tree is deeper than BVH_MAX_DEPTH, so a traversal can keep its to-do list in a fixed array.
 * - A traversal reads every node it enters through bvh_visit: that is where the framework counts
 *   node visits (counters.h) for the heat map, the sidecar and the complexity test; a traversal
 *   never reports its own.
 * Parts may not call: bvh_validate (the grader refuses them; the functions marked PL_PART_API are theirs). */
#ifndef PL_BVH_H
#define PL_BVH_H

#include "part_api.h"

#include <stdbool.h>
#include "aabb.h"
#include "scene.h"
#include "status.h"

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

/* Releases the arrays and zeroes b. NULL-safe. */
PL_PART_API void bvh_free(bvh *b);

/* ---- Counted access ------------------------------------------------------------------------ */

/* Node `index` of b, counted as one node visit on the calling thread. A traversal reads every
 * node it enters (tests the box of, or reads the children or primitives of) through bvh_visit,
 * the root included, and never reads b->nodes directly: the framework counts visits here for the
 * heat map, the sidecar and the complexity test, and a traversal has no way to report or reset
 * its own. index must be valid: bvh_validate has checked every index a traversal can reach. */
PL_PART_API const bvh_node *bvh_visit(const bvh *b, int index);

/* ---- The one validator ----------------------------------------------------------------------- */

/* The shape of a valid tree, for -v, the JSON sidecar, the benchmark and the tests. */
typedef struct {
    int nodes;   /* nodes reached from the root (all of them, in a valid tree) */
    int leaves;
    int depth;   /* longest root-to-leaf path, in edges */
} bvh_shape;

/* Checks a tree part 2 built over the primitives of s before anything walks it: the arrays and
 * counts agree with the scene, child and primitive indices are in range, no node is reached twice
 * (cycles, shared children) and none is unreachable, every primitive and prim_index slot is in
 * exactly one leaf, leaves hold 1 .. max_leaf_size primitives, every box encloses its children and
 * primitives (exactly their union when tight), depth <= BVH_MAX_DEPTH. The renderer runs it with
 * tight = false (a conservative box is correct), the part 2 tests with tight = true (task 2.2 asks
 * for tight boxes). On success fills *shape (may be NULL) and returns PL_OK; otherwise
 * PL_ERR_INVALID with the first fault in diag, e.g. "node 12: child 9000 >= num_nodes 4001";
 * PL_ERR_NOMEM without memory for the walk. */
pl_status bvh_validate(const bvh *b, const scene *s, int max_leaf_size, bool tight, bvh_shape *shape,
                       pl_diag *diag);

#endif
