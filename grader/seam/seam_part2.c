/* Grader machinery: not part of any assignment. Part 2's functions across the split (seam.h; see
 * seam_part1.c for the pattern). bvh_build's record carries the whole tree it built, which the judge
 * allocates as bvh_build would, so bvh_free and bvh_validate work on it unchanged. */
#include "seam.h"
#include "../../parts/part2_bvh/part2.h"
#include <stdlib.h>
#include <string.h>

typedef struct { unsigned char found; float t_enter, t_exit; } slab_out;
typedef struct { int32_t status, num_nodes, num_prims; } build_out;  /* then nodes, then prim_index */

static uint64_t slab_inputs(const aabb *b, const ray *r, const float *t_enter, const float *t_exit)
{
    uint64_t h = b ? SEAM_HASH(SEAM_HASH_START, *b) : seam_hash_int(SEAM_HASH_START, -1);
    return seam_hash_int(seam_hash_ray(h, r), (t_enter != NULL) * 2 + (t_exit != NULL));
}

/* The whole scene: a build reads every primitive, and is called a few times per test. */
static uint64_t build_inputs(const bvh *out, const scene *s, int max_leaf_size)
{
    uint64_t h = seam_hash_int(seam_hash_scene(SEAM_HASH_START, s), max_leaf_size);
    if (s && s->triangles) h = seam_hash(h, s->triangles, (size_t)s->num_triangles * sizeof *s->triangles);
    if (s && s->spheres) h = seam_hash(h, s->spheres, (size_t)s->num_spheres * sizeof *s->spheres);
    return seam_hash_int(h, out != NULL);
}

static uint64_t traverse_inputs(const bvh *b, const scene *s, const ray *r, const hit *h)
{
    return seam_hash_int(seam_hash_ray(seam_hash_scene(seam_hash_bvh(SEAM_HASH_START, b), s), r), h != NULL);
}

_Static_assert(sizeof(aabb) == 6 * 4 && sizeof(bvh_node) == 8 * 4, "padding in aabb or bvh_node");

#ifdef PL_SEAM_SUBJECT
bool __real_aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit);
pl_status __real_bvh_build(bvh *out, const scene *s, int max_leaf_size);
bool __real_bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h);
bool __real_bvh_occluded(const bvh *b, const scene *s, const ray *r);
bool __wrap_aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit);
pl_status __wrap_bvh_build(bvh *out, const scene *s, int max_leaf_size);
bool __wrap_bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h);
bool __wrap_bvh_occluded(const bvh *b, const scene *s, const ray *r);

bool __wrap_aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    seam_call call;
    uint64_t in = slab_inputs(b, r, t_enter, t_exit);
    if (!seam_begin(&call)) return __real_aabb_intersect(b, r, t_enter, t_exit);
    slab_out out;
    memset(&out, 0, sizeof out);
    out.found = __real_aabb_intersect(b, r, t_enter, t_exit);
    if (t_enter) out.t_enter = *t_enter;
    if (t_exit) out.t_exit = *t_exit;
    seam_end(&call, SEAM_aabb_intersect, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out.found;
}

pl_status __wrap_bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    seam_call call;
    uint64_t in = build_inputs(out, s, max_leaf_size);
    if (!seam_begin(&call)) return __real_bvh_build(out, s, max_leaf_size);
    pl_status st = __real_bvh_build(out, s, max_leaf_size);
    /* Only a built tree is sent: after a failure *out may be anything. */
    bool built = st == PL_OK && out;
    build_out head = {st, built ? out->num_nodes : 0, built ? out->num_prims : 0};
    const void *arrays[] = {built ? out->nodes : NULL, built ? out->prim_index : NULL};
    size_t sizes[] = {(size_t)head.num_nodes * sizeof(bvh_node), (size_t)head.num_prims * sizeof(int)};
    seam_end(&call, SEAM_bvh_build, in, NULL, &head, sizeof head, arrays, sizes, 2);
    return st;
}

bool __wrap_bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h)
{
    seam_call call;
    uint64_t in = traverse_inputs(b, s, r, h);
    if (!seam_begin(&call)) return __real_bvh_intersect(b, s, r, h);
    bool found = __real_bvh_intersect(b, s, r, h);
    seam_end_hit(&call, SEAM_bvh_intersect, in, found, r, h);
    return found;
}

bool __wrap_bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    seam_call call;
    uint64_t in = traverse_inputs(b, s, r, NULL);
    if (!seam_begin(&call)) return __real_bvh_occluded(b, s, r);
    bool found = __real_bvh_occluded(b, s, r);
    seam_end_hit(&call, SEAM_bvh_occluded, in, found, NULL, NULL);
    return found;
}
#endif

#ifdef PL_SEAM_JUDGE
bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    slab_out out;
    seam_replay_fixed(SEAM_aabb_intersect, slab_inputs(b, r, t_enter, t_exit), NULL, &out, sizeof out);
    if (t_enter) *t_enter = out.t_enter;
    if (t_exit) *t_exit = out.t_exit;
    return out.found != 0;
}

/* The tree, checked for size only: its shape is for the tests to judge (bvh_validate). A tree has
 * at most 2n - 1 nodes; the bound leaves room for a wasteful one the validator will name. The same
 * bound sizes the record before the judge allocates it (seam_replay's max). */
pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    int64_t bound = 4 * (int64_t)(s ? scene_prim_count(s) : 0) + 16;
    build_out head;
    size_t size, max = sizeof head + (size_t)bound * (sizeof(bvh_node) + sizeof(int));
    const unsigned char *p = seam_replay(SEAM_bvh_build, build_inputs(out, s, max_leaf_size), NULL, max, &size);
    if (size < sizeof head) seam_fail(SEAM_bvh_build, "its answer is shorter than a tree's header");
    memcpy(&head, p, sizeof head);
    if (head.num_nodes < 0 || head.num_prims < 0 || head.num_nodes > bound || head.num_prims > bound ||
        size != sizeof head + (size_t)head.num_nodes * sizeof(bvh_node) + (size_t)head.num_prims * sizeof(int))
        seam_fail(SEAM_bvh_build, "it sent a tree whose counts are negative, beyond %lld for this scene, or not "
                  "those of its length", (long long)bound);
    pl_status st = head.status >= PL_OK && head.status <= PL_ERR_NOMEM ? (pl_status)head.status : PL_ERR_INVALID;
    if (!out) return st;
    *out = (bvh){0};
    if (st != PL_OK) return st;
    out->nodes = malloc((size_t)head.num_nodes * sizeof(bvh_node) + 1);
    out->prim_index = malloc((size_t)head.num_prims * sizeof(int) + 1);
    if (!out->nodes || !out->prim_index) {
        bvh_free(out);
        return PL_ERR_NOMEM;
    }
    memcpy(out->nodes, p + sizeof head, (size_t)head.num_nodes * sizeof(bvh_node));
    memcpy(out->prim_index, p + sizeof head + (size_t)head.num_nodes * sizeof(bvh_node), (size_t)head.num_prims * sizeof(int));
    out->num_nodes = head.num_nodes;
    out->num_prims = head.num_prims;
    return PL_OK;
}

/* The tree and scene bound the trace; a hit names a primitive and material that the judge's own
 * code (the renderer, the tests' messages) indexes its arrays with: a real hit came from
 * scene_prim_intersect, which sets both from the scene. */
static bool replay_traversal(seam_fn fn, const bvh *b, const scene *s, const ray *r, ray *r_out, hit *h)
{
    int prims = s ? scene_prim_count(s) : 0;
    seam_trace_bounds(b ? b->num_nodes : 0, prims);
    bool found = seam_replay_hit(fn, traverse_inputs(b, s, r, h), r_out, h);
    if (!found || !h) return found;
    bool real = h->prim >= 0 && h->prim < prims &&
                h->material == (h->prim < s->num_triangles ? s->triangles[h->prim].material
                                                           : s->spheres[h->prim - s->num_triangles].material);
    if (!real)  /* named without its numbers: they are the code under test's choice */
        seam_fail(fn, "it found a hit on no primitive of the scene's %d, or with a material not that primitive's", prims);
    return found;
}

bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h)
{
    return replay_traversal(SEAM_bvh_intersect, b, s, r, r, h);
}

bool bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    return replay_traversal(SEAM_bvh_occluded, b, s, r, NULL, NULL);
}
#endif
