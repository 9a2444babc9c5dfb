/* Ray-scene queries for the renderer: part 2's BVH when it is implemented, otherwise a linear scan
 * over every primitive. The linear scan is also the oracle the BVH tests compare against.
 * Parts may not call: accel_build, accel_free, accel_intersect_bare, accel_bvh_shape (the grader refuses
 * them; the functions marked PL_PART_API are theirs). */
#ifndef PL_ACCEL_H
#define PL_ACCEL_H

#include "part_api.h"

#include <stdbool.h>
#include "scene.h"
#include "status.h"
#include "bvh.h"

typedef struct {
    const scene *scene;   /* not owned */
    bvh bvh;              /* valid when use_bvh */
    bool use_bvh;         /* false: linear scan (part 2 not implemented, or --no-bvh) */
    bvh_shape shape;      /* from bvh_validate; zeros for the linear scan */
    double build_seconds; /* time bvh_build took */
    struct tri_frame *frames; /* one per triangle, owned: what each hit's refinement needs (spawn.h) */
} accel;

/* Computes every triangle's tri_frame (spawn.h; PL_ERR_NOMEM without memory), then builds the BVH
 * with part 2's bvh_build and checks it with bvh_validate before anything walks it;
 * a stub (PL_ERR_TODO) or want_bvh = false falls back to the linear scan and still returns PL_OK.
 * Other failures, and a malformed tree (PL_ERR_INVALID, "bvh_build made a malformed tree: node 12:
 * child 9000 >= num_nodes 4001"), are returned. */
pl_status accel_build(accel *out, const scene *s, bool want_bvh, int max_leaf_size, pl_diag *diag);
void accel_free(accel *a);  /* NULL-safe */

/* Closest hit in [r->min_t, r->max_t]; shrinks r->max_t and fills *h on a hit, the framework's
 * point and error bound included (scene_hit_finish). */
PL_PART_API bool accel_intersect(const accel *a, ray *r, hit *h);
/* accel_intersect without scene_hit_finish: h->p, h->p_err and h->ng are left as part 1 left them.
 * For a render that never leaves the surface it hits (--normals shades by h->n alone), where the
 * refinement would cost about 5% of the render for nothing. Parts never call it. */
bool accel_intersect_bare(const accel *a, ray *r, hit *h);
/* Any hit in [r->min_t, r->max_t] (shadow rays). */
PL_PART_API bool accel_occluded(const accel *a, const ray *r);

/* The oracle: every primitive, in order. */
PL_PART_API bool linear_intersect(const scene *s, ray *r, hit *h);
PL_PART_API bool linear_occluded(const scene *s, const ray *r);

/* The shape of the BVH in use, for -v, the JSON sidecar and the benchmark (bvh_validate measured
 * it); zeros for the linear scan. */
typedef bvh_shape accel_shape;
accel_shape accel_bvh_shape(const accel *a);

/* accel_intersect and accel_occluded each count one ray (counters.h, framework-internal). */

#endif
