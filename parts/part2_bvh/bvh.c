/* Part 2: the bounding volume hierarchy. Tasks 2.1 - 2.4; handout/part2.md. */
#include "part2.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include "../../framework/todo.h"
#include "../../framework/parallel.h"

/* BEGIN SOLUTION */
/* ---- Slab test ------------------------------------------------------------------------------ */

/* A ray prepared for many box tests: 1/d, and which face of each slab it meets first, are worked
 * out once per ray instead of once per box. */
typedef struct {
    vec3 o;            /* origin */
    vec3 inv_d;        /* 1 / d per component: +inf or -inf where d is +0 or -0 */
    int near[3], far[3]; /* per axis, the index into an aabb's six floats (min xyz, max xyz) of the
                            plane the ray meets first and last; 1/d keeps the sign of d even for
                            d = -0, so it tells which plane comes first */
} slab_ray;

static inline slab_ray slab_ray_make(const ray *r)
{
    slab_ray s;
    s.o = r->o;
    s.inv_d = vec3_make(1.0f / r->d.x, 1.0f / r->d.y, 1.0f / r->d.z);
    for (int axis = 0; axis < 3; axis++) {
        bool backwards = vec3_get(s.inv_d, axis) < 0.0f;
        s.near[axis] = backwards ? 3 + axis : axis;
        s.far[axis] = backwards ? axis : 3 + axis;
    }
    return s;
}

/* Narrows [*t0, *t1] to the t where the ray lies between the near and far planes of one axis. */
static inline void slab_clip_axis(float near, float far, float o, float inv_d, float *t0, float *t1)
{
    float t_near = (near - o) * inv_d;
    float t_far = (far - o) * inv_d;
    /* A ray parallel to the planes gives -inf/+inf (between them: no constraint) or an empty
     * interval (outside). Starting exactly on a plane gives 0 * inf = NaN: the ray lies in the
     * face, which counts as inside, so NaN must not narrow anything. Comparisons with NaN are
     * false, which skips it. */
    if (t_near > *t0) *t0 = t_near;
    if (t_far < *t1) *t1 = t_far;
}

/* An aabb is two vec3s of three floats, read here as six floats in a row. */
_Static_assert(sizeof(aabb) == 6 * sizeof(float), "aabb must be six packed floats");

/* Intersects [*t0, *t1] with the box's three slabs; the result is empty when *t0 > *t1. */
static inline void slab_clip(const aabb *b, const slab_ray *r, float *t0, float *t1)
{
    const float *plane = (const float *)b;  /* min.x min.y min.z max.x max.y max.z: see below */
    slab_clip_axis(plane[r->near[0]], plane[r->far[0]], r->o.x, r->inv_d.x, t0, t1);
    slab_clip_axis(plane[r->near[1]], plane[r->far[1]], r->o.y, r->inv_d.y, t0, t1);
    slab_clip_axis(plane[r->near[2]], plane[r->far[2]], r->o.z, r->inv_d.z, t0, t1);
}
/* END SOLUTION */

/* === PART 2 | TASK 2.1 | aabb_intersect ============================================
 * The slab test: where does a ray enter and leave an axis-aligned box (handout/part2.md, 2.1)?
 * In:  b (may be empty: min > max), r (any direction, components may be +0 or -0).
 * Out: *t_enter, *t_exit: the part of [r->min_t, r->max_t] inside the box, on a hit.
 * Must: hits exactly when that part is non-empty; faces, edges and corners count as inside; a ray
 *       starting inside has *t_enter == r->min_t; never NaN; a ray parallel to an axis is handled.
 * Test: make test-part2
 * =================================================================================== */
bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    /* BEGIN SOLUTION */
    slab_ray sr = slab_ray_make(r);
    float t0 = r->min_t, t1 = r->max_t;
    slab_clip(b, &sr, &t0, &t1);
    *t_enter = t0;
    *t_exit = t1;
    return t0 <= t1;
    /* END SOLUTION */
    /* STUB: *t_enter = 0.0f; *t_exit = 0.0f; return PL_TODO_FALSE("2.1", "aabb_intersect"); */
}

/* BEGIN SOLUTION */
/* ---- SAH build ------------------------------------------------------------------------------ */

/* Costs in units of one primitive test. A traversal step (two box tests) costs about as much as
 * one triangle test, and so the heuristic prefers leaves of a few primitives. */
#define SAH_COST_TRAVERSE 1.0f
#define SAH_COST_INTERSECT 1.0f
/* Candidate planes per axis: 16 bins find splits nearly as good as trying every centroid. */
#define SAH_BINS 16
/* Below this depth, nodes are halved instead of split by SAH: SAH alone can peel off one
 * primitive per level on pathological input, and halving keeps every tree within BVH_MAX_DEPTH
 * (32 + 31 halvings of at most 2^31 primitives). Real scenes never get this deep. */
#define SAH_MAX_DEPTH 32
/* The top of the tree is split on one thread until it has this many subtrees (or none is worth a
 * thread); the subtrees are then built side by side (handout/part2.md, "Making it fast"). A fixed
 * count, not the number of cores, so the tree is the same on every machine. */
#define BUILD_SUBTREES 8
#define BUILD_SUBTREE_MIN 4096  /* primitives below which a subtree is not split off for a thread */

/* One primitive as the build sees it: its bounds and its scene index side by side, so each pass
 * over a node reads memory in order, and partitioning moves the records themselves. */
typedef struct { aabb box; int prim; } build_prim;

/* Centre of a primitive's bounds along one axis: what the bins sort by. */
static inline float build_centroid(const build_prim *p, int axis)
{
    return 0.5f * (vec3_get(p->box.min, axis) + vec3_get(p->box.max, axis));
}

/* A node whose box is known but whose children are still to be made: it covers
 * prims[begin .. end - 1]; cbox bounds their centroids, which the bins divide. */
typedef struct { int node, begin, end, depth; aabb box, cbox; } build_task;

/* Where a build writes nodes: a flat array, num of them used so far. */
typedef struct { bvh_node *nodes; int num; } node_array;

/* The best split found: primitives whose centroid falls in bins 0 .. bin go left. The two
 * children's boxes come out of the bins, so no extra pass over the primitives finds them. */
typedef struct { int axis, bin; float cost; aabb left, right; } sah_split;

/* Bin of a centroid coordinate c, given the centroids' lower bound lo and SAH_BINS / extent. */
static inline int sah_bin(float c, float lo, float scale)
{
    int bin = (int)((c - lo) * scale);
    return bin < SAH_BINS ? bin : SAH_BINS - 1;  /* the upper bound itself lands one past the end */
}

/* The build spends most of its time growing boxes: aabb_union is one minss / maxss per component. */
static inline void box_grow(aabb *a, const aabb *b) { *a = aabb_union(*a, *b); }
static inline void box_grow_centroid(aabb *a, const build_prim *p)
{
    vec3 c = vec3_make(build_centroid(p, 0), build_centroid(p, 1), build_centroid(p, 2));
    aabb point = {c, c};
    box_grow(a, &point);
}

/* The tight box of count primitives, and the box of their centroids. */
static void build_bounds(const build_prim *prims, int count, aabb *box, aabb *cbox)
{
    *box = aabb_empty();
    *cbox = aabb_empty();
    for (int i = 0; i < count; i++) {
        box_grow(box, &prims[i].box);
        box_grow_centroid(cbox, &prims[i]);
    }
}

/* Finds the cheapest binned SAH split of prims[0 .. count - 1] over the centroid bounds cb.
 * The cost is sum(area * count) over both sides, not yet divided by the node's area.
 * Returns false when every centroid sits in one point (no plane separates them). */
static bool sah_find_split(const build_prim *prims, int count, aabb cb, sah_split *best)
{
    /* Binning: one pass over the primitives fills the bins of all three axes. */
    float lo[3] = {cb.min.x, cb.min.y, cb.min.z}, scale[3];
    int bin_count[3][SAH_BINS] = {{0}};
    aabb bin_box[3][SAH_BINS];
    for (int axis = 0; axis < 3; axis++) {
        scale[axis] = SAH_BINS / (vec3_get(cb.max, axis) - lo[axis]);
        if (!isfinite(scale[axis])) scale[axis] = 0.0f;  /* zero (or denormal) extent: all in bin 0 */
        for (int i = 0; i < SAH_BINS; i++) bin_box[axis][i] = aabb_empty();
    }
    for (int i = 0; i < count; i++) {
        const build_prim *p = &prims[i];
        int bx = sah_bin(build_centroid(p, 0), lo[0], scale[0]), by = sah_bin(build_centroid(p, 1), lo[1], scale[1]),
            bz = sah_bin(build_centroid(p, 2), lo[2], scale[2]);
        bin_count[0][bx]++;
        bin_count[1][by]++;
        bin_count[2][bz]++;
        box_grow(&bin_box[0][bx], &p->box);
        box_grow(&bin_box[1][by], &p->box);
        box_grow(&bin_box[2][bz], &p->box);
    }

    /* Each plane's cost: its right side swept from the right, then its left side from the left. */
    best->cost = INFINITY;
    for (int axis = 0; axis < 3; axis++) {
        if (scale[axis] == 0.0f) continue;  /* nothing to separate along this axis */
        float right_cost[SAH_BINS];  /* area * count of bins i .. SAH_BINS - 1 */
        aabb right_box[SAH_BINS];    /* their union */
        aabb box = aabb_empty();
        int n = 0;
        float cost_here = INFINITY;  /* an empty side is no split */
        for (int i = SAH_BINS - 1; i > 0; i--) {
            if (bin_count[axis][i] > 0) {  /* an empty bin changes neither the box nor the cost */
                box_grow(&box, &bin_box[axis][i]);
                n += bin_count[axis][i];
                cost_here = aabb_surface_area(box) * n;
            }
            right_box[i] = box;
            right_cost[i] = cost_here;
        }
        box = aabb_empty();
        n = 0;
        for (int i = 0; i < SAH_BINS - 1; i++) {
            /* A plane after an empty bin splits like the one before it, at the same cost. */
            if (bin_count[axis][i] == 0) continue;
            box_grow(&box, &bin_box[axis][i]);
            n += bin_count[axis][i];
            float cost = aabb_surface_area(box) * n + right_cost[i + 1];
            if (cost < best->cost) *best = (sah_split){axis, i, cost, box, right_box[i + 1]};
        }
    }
    return best->cost < INFINITY;
}

/* Reorders prims so those left of the split come first; returns how many that is. Each primitive
 * is classified once, and its centroid grows the bounds of the side it goes to. */
static int sah_partition(build_prim *prims, int count, aabb cb, sah_split split, aabb *left_cbox, aabb *right_cbox)
{
    float lo = vec3_get(cb.min, split.axis);
    float scale = SAH_BINS / (vec3_get(cb.max, split.axis) - lo);
    *left_cbox = *right_cbox = aabb_empty();
    int left = 0, right = count - 1;
    while (left <= right) {
        if (sah_bin(build_centroid(&prims[left], split.axis), lo, scale) <= split.bin) {
            box_grow_centroid(left_cbox, &prims[left++]);
        } else {
            build_prim tmp = prims[left];
            prims[left] = prims[right];
            prims[right--] = tmp;
            box_grow_centroid(right_cbox, &tmp);
        }
    }
    return left;
}

/* Makes a->nodes[task.node] a leaf or splits it, appending its children's tasks to tasks. */
static void build_node(build_prim *all, int max_leaf_size, node_array *a, build_task task, build_task *tasks,
                       int *num_tasks)
{
    bvh_node *node = &a->nodes[task.node];
    build_prim *prims = all + task.begin;
    int count = task.end - task.begin;
    node->box = task.box;

    /* The children's bounds: out of the bins and the partition, or worked out after a halving. */
    int left_count;
    aabb box[2], cbox[2];
    sah_split split;
    if (task.depth >= SAH_MAX_DEPTH || !sah_find_split(prims, count, task.cbox, &split)) {
        if (count <= max_leaf_size) {
            node->first = task.begin;
            node->count = count;
            return;
        }
        left_count = count / 2;  /* any halving is a valid tree; see SAH_MAX_DEPTH */
        build_bounds(prims, left_count, &box[0], &cbox[0]);
        build_bounds(prims + left_count, count - left_count, &box[1], &cbox[1]);
    } else {
        /* Both costs multiplied by the node's area, which also copes with a zero-area node. */
        float leaf_cost = SAH_COST_INTERSECT * count * aabb_surface_area(task.box);
        float split_cost = SAH_COST_TRAVERSE * aabb_surface_area(task.box) + SAH_COST_INTERSECT * split.cost;
        if (count <= max_leaf_size && leaf_cost <= split_cost) {
            node->first = task.begin;
            node->count = count;
            return;
        }
        left_count = sah_partition(prims, count, task.cbox, split, &cbox[0], &cbox[1]);
        box[0] = split.left;
        box[1] = split.right;
    }

    /* Children side by side at the end of the array; the left one is built first. */
    node->first = a->num;
    node->count = 0;
    a->num += 2;
    int mid = task.begin + left_count;
    tasks[(*num_tasks)++] = (build_task){node->first + 1, mid, task.end, task.depth + 1, box[1], cbox[1]};
    tasks[(*num_tasks)++] = (build_task){node->first, task.begin, mid, task.depth + 1, box[0], cbox[0]};
}

/* One subtree, built depth first into its own array whose node 0 is task's node. Depth first
 * with an explicit to-do list: it never holds more than one pending sibling per level, and the
 * depth is bounded (SAH_MAX_DEPTH), so a fixed array suffices. */
typedef struct {
    build_prim *prims;
    int max_leaf_size;
    build_task task;
    node_array out;  /* out.nodes == NULL: out of memory */
} subtree_job;

static void build_subtree(subtree_job *job)
{
    int count = job->task.end - job->task.begin;
    node_array a = {malloc((2 * (size_t)count - 1) * sizeof(bvh_node)), 1};
    if (a.nodes) {
        build_task tasks[2 * BVH_MAX_DEPTH + 2];
        int num_tasks = 0;
        tasks[num_tasks] = job->task;
        tasks[num_tasks++].node = 0;
        while (num_tasks > 0) {
            build_task task = tasks[--num_tasks];
            build_node(job->prims, job->max_leaf_size, &a, task, tasks, &num_tasks);
        }
        /* Give back the nodes SAH did not need (leaves of several primitives). */
        bvh_node *fit = realloc(a.nodes, (size_t)a.num * sizeof *fit);
        if (fit) a.nodes = fit;
    }
    job->out = a;
}

/* parallel_for's job: subtree i of the list. The subtrees are independent (disjoint primitives,
 * their own arrays), so they can be built in any order, on any thread. */
static void build_subtree_job(void *jobs, int i) { build_subtree(&((subtree_job *)jobs)[i]); }

/* Copies subtree job's nodes into a: its node 0 onto the node its task named, the rest after
 * a->num. Child indices inside the subtree move by the same amount; leaves' first indices are
 * slots of the shared primitive order, and stay. */
static void stitch_subtree(node_array *a, const subtree_job *job)
{
    int shift = a->num - 1;  /* subtree node i >= 1 lands at i + shift */
    for (int i = 0; i < job->out.num; i++) {
        bvh_node node = job->out.nodes[i];
        if (node.count == 0) node.first += shift;
        a->nodes[i == 0 ? job->task.node : i + shift] = node;
    }
    a->num += job->out.num - 1;
}

/* Primitives a pending task covers. */
static inline int task_size(const build_task *t) { return t->end - t->begin; }

/* The top of the tree, on this thread: the largest pending node is split (into top; each split
 * adds two nodes) until there are BUILD_SUBTREES of them or none is worth a thread. Fills jobs with
 * the pending nodes, left to right, and returns how many. */
static int split_top(build_prim *prims, int max_leaf_size, build_task root, node_array *top, subtree_job *jobs)
{
    int num_jobs = 1;
    jobs[0].task = root;
    while (num_jobs < BUILD_SUBTREES) {
        int largest = 0;
        for (int i = 1; i < num_jobs; i++)
            if (task_size(&jobs[i].task) > task_size(&jobs[largest].task)) largest = i;
        if (task_size(&jobs[largest].task) < BUILD_SUBTREE_MIN) break;
        build_task children[2];
        int num_children = 0;
        build_node(prims, max_leaf_size, top, jobs[largest].task, children, &num_children);
        if (num_children == 0) break;  /* it became a leaf (cannot happen at this size) */
        /* The node's children take its place in the list (left, then right). */
        memmove(&jobs[largest + 2], &jobs[largest + 1], (size_t)(num_jobs - largest - 1) * sizeof *jobs);
        jobs[largest].task = children[1];
        jobs[largest + 1].task = children[0];
        num_jobs++;
    }
    for (int i = 0; i < num_jobs; i++) {
        jobs[i].prims = prims;
        jobs[i].max_leaf_size = max_leaf_size;
    }
    return num_jobs;
}

/* One node array, the top nodes and each subtree's after them, and prim_index in the records'
 * final order; frees the subtrees' arrays. PL_ERR_NOMEM (a subtree or this) leaves *out empty. */
static pl_status assemble_tree(bvh *out, const node_array *top, subtree_job *jobs, int num_jobs,
                               const build_prim *prims, int n)
{
    size_t total = (size_t)top->num;
    bool complete = true;
    for (int i = 0; i < num_jobs; i++) {
        complete = complete && jobs[i].out.nodes;
        total += (size_t)jobs[i].out.num - 1;
    }
    node_array all = {complete ? malloc(total * sizeof(bvh_node)) : NULL, top->num};
    int *prim_index = complete ? malloc((size_t)n * sizeof *prim_index) : NULL;
    if (all.nodes && prim_index) {
        memcpy(all.nodes, top->nodes, (size_t)top->num * sizeof *all.nodes);
        for (int i = 0; i < num_jobs; i++) stitch_subtree(&all, &jobs[i]);
        for (int i = 0; i < n; i++) prim_index[i] = prims[i].prim;
        *out = (bvh){all.nodes, all.num, prim_index, n};
    } else {
        free(all.nodes);
        free(prim_index);
    }
    for (int i = 0; i < num_jobs; i++) free(jobs[i].out.nodes);
    return out->nodes ? PL_OK : PL_ERR_NOMEM;
}
/* END SOLUTION */

/* === PART 2 | TASK 2.2 | bvh_build =================================================
 * Build a BVH over every primitive with the surface area heuristic (handout/part2.md, 2.2).
 * In:  s (read-only; primitives 0 .. scene_prim_count(s) - 1), max_leaf_size >= 1.
 * Out: *out: nodes (root at 0, children side by side), prim_index, num_nodes, num_prims.
 * Must: every primitive in exactly one leaf; leaves hold 1 .. max_leaf_size primitives; each
 *       box is the union of its primitives' bounds (tight); depth <= BVH_MAX_DEPTH; one flat node
 *       array (no allocation per node); PL_ERR_INVALID for max_leaf_size < 1; an empty scene gives
 *       num_nodes == 0.
 * Test: make test-part2
 * =================================================================================== */
pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    /* BEGIN SOLUTION */
    *out = (bvh){0};
    if (max_leaf_size < 1) return PL_ERR_INVALID;
    int n = scene_prim_count(s);
    if (n == 0) return PL_OK;

    build_prim *prims = malloc((size_t)n * sizeof *prims);
    if (!prims) return PL_ERR_NOMEM;
    for (int i = 0; i < n; i++) {
        prims[i] = (build_prim){scene_prim_bounds(s, i), i};
        /* No bin can hold an infinite or NaN coordinate (the loaders reject them anyway). */
        if (!vec3_is_finite(prims[i].box.min) || !vec3_is_finite(prims[i].box.max)) {
            free(prims);
            return PL_ERR_INVALID;
        }
    }

    /* The top on this thread, the subtrees side by side, then one tree. */
    bvh_node top_nodes[2 * BUILD_SUBTREES];
    node_array top = {top_nodes, 1};
    subtree_job jobs[BUILD_SUBTREES + 1];
    build_task root = {.node = 0, .begin = 0, .end = n, .depth = 0};
    build_bounds(prims, n, &root.box, &root.cbox);
    int num_jobs = split_top(prims, max_leaf_size, root, &top, jobs);
    parallel_for(num_jobs, build_subtree_job, jobs);
    pl_status st = assemble_tree(out, &top, jobs, num_jobs, prims, n);
    free(prims);
    return st;
    /* END SOLUTION */
    /* STUB: *out = (bvh){0}; return PL_TODO("2.2", "bvh_build"); */
}

/* BEGIN SOLUTION */
/* ---- Traversal ------------------------------------------------------------------------------ */

/* slab_clip rounds three times per plane, so for a box the ray only grazes it may put the exit a
 * few ulps before the entry although the primitive test, computed differently, hits there.
 * Widening the exit by 2 gamma(3) (Ize 2013, "Robust BVH Ray Traversal") keeps such boxes. */
#define SLAB_EXIT_SLACK (4.0f * FLT_EPSILON)

/* True when the ray may hit something inside node's box before max_t; *t_enter is where it enters. */
static inline bool node_hit(const bvh_node *node, const slab_ray *r, float min_t, float max_t, float *t_enter)
{
    float t0 = min_t, t1 = max_t;
    slab_clip(&node->box, r, &t0, &t1);
    *t_enter = t0;
    return t0 <= t1 * (1.0f + SLAB_EXIT_SLACK);  /* t1 >= 0 whenever t0 <= t1 can hold */
}

/* Closest hit (stop_at_first = false) or any hit (true): tasks 2.3 and 2.4 share this traversal. */
static bool bvh_traverse(const bvh *b, const scene *s, ray *r, hit *h, bool stop_at_first)
{
    if (b->num_nodes == 0) return false;
    slab_ray sr = slab_ray_make(r);

    /* Nodes still to visit, with the t where the ray enters each. Nearest first pushes at most one
     * pending sibling per level, so depth + 1 entries suffice. */
    struct { const bvh_node *node; float t_enter; } todo[BVH_MAX_DEPTH + 1];
    int num_todo = 0;
    float t_root;
    const bvh_node *root = bvh_visit(b, 0);
    if (node_hit(root, &sr, r->min_t, r->max_t, &t_root)) {
        todo[0].node = root;
        todo[0].t_enter = t_root;
        num_todo = 1;
    }

    bool found = false;
    while (num_todo > 0 && !(found && stop_at_first)) {
        num_todo--;
        /* Early exit: a hit found since this node was pushed may now lie before its box. */
        if (todo[num_todo].t_enter > r->max_t) continue;
        /* Its box was tested, and its visit counted, when it was pushed. */
        const bvh_node *node = todo[num_todo].node;

        if (node->count > 0) {
            for (int i = 0; i < node->count && !(found && stop_at_first); i++)
                found |= scene_prim_intersect(s, b->prim_index[node->first + i], r, h);  /* shrinks max_t */
            continue;
        }

        /* Visit the nearer child first: its hits shrink max_t, which may rule out the other. */
        const bvh_node *near = bvh_visit(b, node->first), *far = bvh_visit(b, node->first + 1);
        float t_near, t_far;
        bool hit_near = node_hit(near, &sr, r->min_t, r->max_t, &t_near);
        bool hit_far = node_hit(far, &sr, r->min_t, r->max_t, &t_far);
        if (hit_near && hit_far && t_far < t_near) {
            const bvh_node *swap_node = near; near = far; far = swap_node;
            float swap_t = t_near; t_near = t_far; t_far = swap_t;
            bool swap_hit = hit_near; hit_near = hit_far; hit_far = swap_hit;
        }
        if (hit_far) {
            todo[num_todo].node = far;
            todo[num_todo++].t_enter = t_far;
        }
        if (hit_near) {
            todo[num_todo].node = near;
            todo[num_todo++].t_enter = t_near;
        }
    }
    return found;
}
/* END SOLUTION */

/* === PART 2 | TASK 2.3 | bvh_intersect =============================================
 * Closest hit through the BVH (handout/part2.md, 2.3).
 * In:  b (built by bvh_build over s), s, r.   Out: *h, r->max_t (only on a hit).
 * Must: the same hit as linear_intersect (same t and primitive; either one on an exact tie);
 *       visit the nearer child first and skip boxes entered beyond r->max_t; call bvh_visit for
 *       every node you enter (the root and each child whose box you test; never b->nodes[i]) and
 *       scene_prim_intersect for every primitive you test (never triangle_intersect): the
 *       framework counts both, and the tests check each ray's counts against its hit.
 * Test: make test-part2
 * =================================================================================== */
bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h)
{
    /* BEGIN SOLUTION */
    return bvh_traverse(b, s, r, h, false);
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("2.3", "bvh_intersect"); */
}

/* === PART 2 | TASK 2.4 | bvh_occluded ==============================================
 * Any hit through the BVH, for shadow rays (handout/part2.md, 2.4).
 * In:  b (built by bvh_build over s), s, r (read-only).   Out: true when anything is hit.
 * Must: the same answer as linear_occluded; return at the first hit found; leave *r unchanged;
 *       bvh_visit for every node you enter, scene_prim_intersect for every primitive you test.
 * Test: make test-part2
 * =================================================================================== */
bool bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    /* BEGIN SOLUTION */
    ray probe = *r;  /* primitive tests shrink max_t; the caller's ray must not change */
    hit scratch;
    return bvh_traverse(b, s, &probe, &scratch, true);
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("2.4", "bvh_occluded"); */
}
