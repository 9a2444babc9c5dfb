/* Ray-scene queries: part 2's BVH when implemented, the linear scan otherwise. */
#include "accel.h"
#include "../parts/part2_bvh/part2.h"  /* a call site of the parts (framework/README.md) */
#include "clock.h"
#include "counters.h"
#include "spawn.h"
#include "todo.h"
#include <stdlib.h>
#include <string.h>

/* Each triangle's normal and test error, once: hits then cost a blend, not a cross product, a
 * division and two square roots each (spawn.h). */
static pl_status make_frames(accel *a, const scene *s, pl_diag *diag)
{
    if (s->num_triangles == 0) return PL_OK;
    a->frames = malloc((size_t)s->num_triangles * sizeof *a->frames);
    if (!a->frames)
        return pl_fail(diag, PL_ERR_NOMEM, "out of memory for the frames of %d triangles", s->num_triangles);
    for (int i = 0; i < s->num_triangles; i++) a->frames[i] = tri_frame_make(&s->triangles[i]);
    return PL_OK;
}

/* Part 2's tree, checked, or the linear scan when part 2 is still a stub. */
static pl_status build_bvh(accel *out, const scene *s, int max_leaf_size, pl_diag *diag)
{
    double t0 = clock_seconds();
    pl_status st = bvh_build(&out->bvh, s, max_leaf_size);
    out->build_seconds = clock_seconds() - t0;
    if (st == PL_OK) {
        /* A student's tree is checked once here, so a malformed one is refused with the node at
         * fault instead of crashing somewhere inside a traversal. */
        pl_diag check = pl_diag_default();
        st = bvh_validate(&out->bvh, s, max_leaf_size, false, &out->shape, &check);
        if (st == PL_OK) {
            out->use_bvh = true;
            return PL_OK;
        }
        bvh_free(&out->bvh);
        out->shape = (bvh_shape){0, 0, 0};
        return pl_fail(diag, st, "bvh_build made a malformed tree: %s", check.error);
    }
    bvh_free(&out->bvh);
    if (st == PL_ERR_TODO) {
        /* Part 2 not done yet: the linear scan still renders, so a stubbed bvh_build is not
         * missing work for the caller (part 1's tests render before part 2 is written). */
        pl_todo_handled();
        return PL_OK;
    }
    return pl_fail(diag, st, "bvh_build failed: %s", pl_status_name(st));
}

pl_status accel_build(accel *out, const scene *s, bool want_bvh, int max_leaf_size, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    out->scene = s;
    pl_status st = make_frames(out, s, diag);
    if (st == PL_OK && want_bvh && scene_prim_count(s) > 0) st = build_bvh(out, s, max_leaf_size, diag);
    if (st != PL_OK) accel_free(out);  /* nothing half-built is left for the caller to free */
    return st;
}

void accel_free(accel *a)
{
    if (!a) return;
    free(a->frames);
    a->frames = NULL;
    bvh_free(&a->bvh);
    a->use_bvh = false;
    a->shape = (bvh_shape){0, 0, 0};
}

/* ---- the queries: every ray traced is counted here, once, whichever structure answers -------- */

bool accel_intersect_bare(const accel *a, ray *r, hit *h)
{
    counters_add_ray();
    return a->use_bvh ? bvh_intersect(&a->bvh, a->scene, r, h) : linear_intersect(a->scene, r, h);
}

bool accel_intersect(const accel *a, ray *r, hit *h)
{
    bool found = accel_intersect_bare(a, r, h);
    if (found) scene_hit_finish(a->scene, a->frames, r, h);  /* the point and its error bound, once (spawn.h) */
    return found;
}

bool accel_occluded(const accel *a, const ray *r)
{
    counters_add_ray();
    return a->use_bvh ? bvh_occluded(&a->bvh, a->scene, r) : linear_occluded(a->scene, r);
}

/* The linear scan: every primitive, in order. Slow, but obviously right: the oracle part 2's tests
 * compare the BVH with, and the renderer's fallback while part 2 is a stub. */
bool linear_intersect(const scene *s, ray *r, hit *h)
{
    bool found = false;
    int n = scene_prim_count(s);
    for (int i = 0; i < n; i++)
        found |= scene_prim_intersect(s, i, r, h);  /* each hit shrinks r->max_t */
    return found;
}

bool linear_occluded(const scene *s, const ray *r)
{
    int n = scene_prim_count(s);
    for (int i = 0; i < n; i++) {
        ray probe = *r;  /* intersect shrinks max_t; a shadow query must not change the caller's ray */
        hit h;
        if (scene_prim_intersect(s, i, &probe, &h)) return true;
    }
    return false;
}

accel_shape accel_bvh_shape(const accel *a) { return a->shape; }
