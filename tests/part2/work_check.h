/* Test machinery: not part of any assignment.
 * Checks that the framework's work counts (framework/counters.h) agree with what every correct
 * traversal must do, whatever its order (nearest-first, plain depth-first, any-hit):
 * - a query that reports a hit tested that primitive through scene_prim_intersect (closest hit:
 *   the primitive it reports; any hit: some primitive it tested really hits the ray);
 * - it entered every node on the path from the root to the leaf holding that primitive, each
 *   through bvh_visit, so at least depth + 1 node visits were counted;
 * - nobody reset the counts during the query.
 * A traversal that reads nodes or tests triangles behind the framework's back fails one of these.
 * Nothing is claimed about misses, or about how much work a hit took beyond its own path. */
#ifndef PL_PART2_WORK_CHECK_H
#define PL_PART2_WORK_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include "../../framework/bvh.h"
#include "../../framework/counters.h"
#include "../../framework/scene.h"

typedef struct {
    const bvh *b;            /* not owned; valid (bvh_validate) */
    const scene *s;          /* not owned */
    int *parent;             /* per node: its parent, -1 for the root */
    int *depth;              /* per node: edges from the root */
    int *leaf_of_prim;       /* per primitive: the leaf holding it */
    char *mark;              /* per node: scratch for membership tests, all zero between calls */
    counters_trace trace;    /* what the last query touched (arrays owned) */
    work_counts counted;     /* what the framework counted for it */
} work_check;

/* Maps the tree (b must be valid) and allocates the trace. Fails the current test without memory. */
void work_check_init(work_check *c, const bvh *b, const scene *s);
void work_check_free(work_check *c);  /* NULL-safe */

/* Around one query on the calling thread: begin drops earlier counts and starts tracing; end stops. */
void work_check_begin(work_check *c);
void work_check_end(work_check *c);

/* After a closest-hit query (task 2.3) that reported hit *h for ray number ray_index: true when the
 * counts are consistent with it; otherwise false with the reason in why, e.g. "ray 17 hit prim 42
 * in leaf 311 at depth 12 but only 1 node visit was counted: call bvh_visit for every node you
 * enter (task 2.3)". */
bool work_check_closest(work_check *c, int ray_index, const hit *h, char *why, size_t why_len);

/* After an any-hit query (task 2.4) that answered "occluded" for ray r: the same claims for some
 * primitive it tested that hits r. May test primitives itself (after work_check_end). */
bool work_check_any(work_check *c, int ray_index, const ray *r, char *why, size_t why_len);

#endif
