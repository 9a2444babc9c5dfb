/* The BVH's storage, counters and validator: owned by the framework, so the tree can be freed,
 * counted and checked whatever state part 2 is in. */
#include "bvh.h"
#include "check.h"
#include "counters.h"
#include <stdlib.h>
#include <string.h>

/* ---- Storage and counted access ---------------------------------------------------------------- */

/* The framework frees what part 2 allocated (bvh_build fills nodes and prim_index with malloc), so a
 * tree is released the same way whatever state the part is in. */
void bvh_free(bvh *b)
{
    if (!b) return;
    free(b->nodes);
    free(b->prim_index);
    memset(b, 0, sizeof *b);
}

PL_HOT const bvh_node *bvh_visit(const bvh *b, int index)
{
    PL_CHECK(index >= 0 && index < b->num_nodes);  /* a traversal's bug, caught before the read */
    counters_add_visit(index);
    return &b->nodes[index];
}

/* ---- Validation ------------------------------------------------------------------------------ */

/* Exact equality, for the tight check: a tight box is the union of the same floats, so no epsilon. */
static bool aabb_equal(aabb a, aabb b)
{
    return a.min.x == b.min.x && a.min.y == b.min.y && a.min.z == b.min.z && a.max.x == b.max.x &&
           a.max.y == b.max.y && a.max.z == b.max.z;
}

/* The scratch a walk needs: what has been seen, and the nodes still to visit. */
typedef struct {
    int *prim_seen, *slot_seen;
    char *node_seen;
    struct { int node, depth; } *stack;
} walk_scratch;

static void scratch_free(walk_scratch *w)
{
    free(w->prim_seen);
    free(w->slot_seen);
    free(w->node_seen);
    free(w->stack);
}

/* One leaf's checks: its slots and primitives are in range and seen once. Out: *box, the union of
 * its primitives' bounds, for the caller's box check. */
static pl_status check_leaf(const bvh *b, const scene *s, int id, int max_leaf_size, walk_scratch *w, aabb *box,
                            pl_diag *diag)
{
    const bvh_node *node = &b->nodes[id];
    int n = b->num_prims;
    if (max_leaf_size > 0 && node->count > max_leaf_size)
        return pl_fail(diag, PL_ERR_INVALID, "node %d: leaf holds %d primitives, max_leaf_size is %d", id, node->count,
                       max_leaf_size);
    if (node->first < 0 || node->first > n - node->count)
        return pl_fail(diag, PL_ERR_INVALID, "node %d: leaf covers slots %d .. %d, prim_index has %d", id, node->first,
                       node->first + node->count - 1, n);
    /* Every slot and every primitive may be claimed once: a second claim names the node at fault. */
    *box = aabb_empty();
    for (int i = node->first; i < node->first + node->count; i++) {
        int p = b->prim_index[i];
        if (w->slot_seen[i]++) return pl_fail(diag, PL_ERR_INVALID, "node %d: prim_index slot %d belongs to two leaves", id, i);
        if (p < 0 || p >= n)
            return pl_fail(diag, PL_ERR_INVALID, "node %d: prim_index[%d] = %d is not a primitive (0 .. %d)", id, i, p, n - 1);
        if (w->prim_seen[p]++) return pl_fail(diag, PL_ERR_INVALID, "node %d: primitive %d is in two leaves", id, p);
        *box = aabb_union(*box, scene_prim_bounds(s, p));
    }
    return PL_OK;
}

/* Walks the tree depth first from the root with an explicit stack; each node is checked when it
 * is popped, and pushed only after its parent has checked the child index. */
static pl_status walk(const bvh *b, const scene *s, int max_leaf_size, bool tight, walk_scratch *w, bvh_shape *shape,
                      pl_diag *diag)
{
    int top = 0;
    w->stack[top].node = 0;
    w->stack[top++].depth = 0;
    while (top > 0) {
        top--;
        int id = w->stack[top].node, depth = w->stack[top].depth;
        const bvh_node *node = &b->nodes[id];
        /* A second arrival at a node means a cycle or a shared child: refused before it is walked. */
        if (w->node_seen[id]++) return pl_fail(diag, PL_ERR_INVALID, "node %d: reached twice from the root (a cycle or a shared child)", id);
        if (depth > BVH_MAX_DEPTH)
            return pl_fail(diag, PL_ERR_INVALID, "node %d: depth %d exceeds BVH_MAX_DEPTH (%d)", id, depth, BVH_MAX_DEPTH);
        shape->nodes++;
        if (depth > shape->depth) shape->depth = depth;
        if (node->count < 0) return pl_fail(diag, PL_ERR_INVALID, "node %d: count %d < 0", id, node->count);
        /* A leaf: its primitives, then its box against their bounds. */
        if (node->count > 0) {
            shape->leaves++;
            aabb box = aabb_empty();
            pl_status st = check_leaf(b, s, id, max_leaf_size, w, &box, diag);
            if (st != PL_OK) return st;
            if (tight ? !aabb_equal(box, node->box) : !aabb_contains(node->box, box))
                return pl_fail(diag, PL_ERR_INVALID, "node %d: leaf box is not %s its primitives' bounds", id,
                               tight ? "exactly the union of (tight)" : "enclosing");
            continue;
        }
        /* Interior: both children must exist, come after the root, and sit inside this box. */
        if (node->first < 1 || node->first >= b->num_nodes - 1)
            return pl_fail(diag, PL_ERR_INVALID, "node %d: child %d %s num_nodes %d", id,
                           node->first < 1 ? node->first : node->first + 1, node->first < 1 ? "< 1," : ">=", b->num_nodes);
        const bvh_node *l = &b->nodes[node->first], *r = &b->nodes[node->first + 1];
        if (!aabb_contains(node->box, l->box) || !aabb_contains(node->box, r->box))
            return pl_fail(diag, PL_ERR_INVALID, "node %d: a child box (node %d or %d) pokes out of it", id, node->first,
                           node->first + 1);
        if (tight && !aabb_equal(aabb_union(l->box, r->box), node->box))
            return pl_fail(diag, PL_ERR_INVALID, "node %d: box is larger than the union of its children's (not tight)", id);
        for (int c = 0; c < 2; c++) {
            w->stack[top].node = node->first + c;
            w->stack[top++].depth = depth + 1;
        }
    }
    /* After the walk: nothing left out, neither a primitive nor a node. */
    for (int p = 0; p < b->num_prims; p++)
        if (!w->prim_seen[p]) return pl_fail(diag, PL_ERR_INVALID, "primitive %d is in no leaf", p);
    for (int i = 0; i < b->num_nodes; i++)
        if (!w->node_seen[i]) return pl_fail(diag, PL_ERR_INVALID, "node %d: not reachable from the root (num_nodes too large?)", i);
    return PL_OK;
}

/* The sizes first (cheap, and they bound every index the walk reads), then the walk itself. */
pl_status bvh_validate(const bvh *b, const scene *s, int max_leaf_size, bool tight, bvh_shape *shape, pl_diag *diag)
{
    bvh_shape ignored;
    if (!shape) shape = &ignored;
    *shape = (bvh_shape){0, 0, 0};
    int n = scene_prim_count(s);
    if (b->num_prims != n)
        return pl_fail(diag, PL_ERR_INVALID, "num_prims is %d, the scene has %d primitives", b->num_prims, n);
    if (n == 0) {
        if (b->num_nodes != 0)
            return pl_fail(diag, PL_ERR_INVALID, "an empty scene must give num_nodes == 0, got %d", b->num_nodes);
        return PL_OK;
    }
    if (b->num_nodes < 1 || b->num_nodes > 2 * n - 1 || !b->nodes || !b->prim_index)
        return pl_fail(diag, PL_ERR_INVALID, "num_nodes is %d: expected 1 .. 2n - 1 = %d, with both arrays allocated",
                       b->num_nodes, 2 * n - 1);

    /* Each node pops at most once (a second arrival is refused), so 2 pushes per node suffice. */
    walk_scratch w = {calloc((size_t)n, sizeof(int)), calloc((size_t)n, sizeof(int)), calloc((size_t)b->num_nodes, 1),
                      malloc((2 * (size_t)b->num_nodes + 1) * sizeof *w.stack)};
    pl_status st = w.prim_seen && w.slot_seen && w.node_seen && w.stack
                       ? walk(b, s, max_leaf_size, tight, &w, shape, diag)
                       : pl_fail(diag, PL_ERR_NOMEM, "out of memory checking a BVH of %d nodes", b->num_nodes);
    scratch_free(&w);
    return st;
}
