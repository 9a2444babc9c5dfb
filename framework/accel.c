/* Ray-scene queries: part 2's BVH when implemented, the linear scan otherwise. */
#include "accel.h"
#include "todo.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Per-thread ray counter: no atomics on the hot path; the render loop collects it per worker. */
static _Thread_local uint64_t rays_traced;

uint64_t accel_take_ray_count(void)
{
    uint64_t n = rays_traced;
    rays_traced = 0;
    return n;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

pl_status accel_build(accel *out, const scene *s, bool want_bvh, int max_leaf_size, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    out->scene = s;
    if (!want_bvh || scene_prim_count(s) == 0) return PL_OK;
    double t0 = now_seconds();
    pl_status st = bvh_build(&out->bvh, s, max_leaf_size);
    out->build_seconds = now_seconds() - t0;
    if (st == PL_OK) {
        out->use_bvh = true;
        return PL_OK;
    }
    bvh_free(&out->bvh);
    if (st == PL_ERR_TODO) return PL_OK;  /* part 2 not done yet: the linear scan still renders */
    return pl_fail(diag, st, "bvh_build failed: %s", pl_status_name(st));
}

void accel_free(accel *a)
{
    if (!a) return;
    bvh_free(&a->bvh);
    a->use_bvh = false;
}

bool accel_intersect(const accel *a, ray *r, hit *h)
{
    rays_traced++;
    return a->use_bvh ? bvh_intersect(&a->bvh, a->scene, r, h) : linear_intersect(a->scene, r, h);
}

bool accel_occluded(const accel *a, const ray *r)
{
    rays_traced++;
    return a->use_bvh ? bvh_occluded(&a->bvh, a->scene, r) : linear_occluded(a->scene, r);
}

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

accel_shape accel_bvh_shape(const accel *a)
{
    accel_shape shape = {0, 0, 0};
    const bvh *b = &a->bvh;
    if (!a->use_bvh || b->num_nodes <= 0) return shape;
    /* Depth first with an explicit stack; a seen flag stops cycles and shared children. */
    struct { int node, depth; } *stack = malloc((2 * (size_t)b->num_nodes + 1) * sizeof *stack);
    unsigned char *seen = calloc((size_t)b->num_nodes, 1);
    if (!stack || !seen) {
        free(stack);
        free(seen);
        return shape;
    }
    int top = 0;
    stack[top].node = 0;
    stack[top++].depth = 0;
    while (top > 0) {
        top--;
        int id = stack[top].node, depth = stack[top].depth;
        if (seen[id]) continue;
        seen[id] = 1;
        shape.nodes++;
        if (depth > shape.depth) shape.depth = depth;
        const bvh_node *n = &b->nodes[id];
        if (n->count > 0) {
            shape.leaves++;
            continue;
        }
        for (int c = 0; c < 2; c++) {
            int child = n->first + c;
            if (child <= 0 || child >= b->num_nodes) continue;
            stack[top].node = child;
            stack[top++].depth = depth + 1;
        }
    }
    free(stack);
    free(seen);
    return shape;
}
