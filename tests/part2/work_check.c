/* Test machinery: not part of any assignment. See work_check.h. */
#include "../common/test.h"
#include "work_check.h"
#include <stdio.h>
#include <stdlib.h>

void work_check_init(work_check *c, const bvh *b, const scene *s)
{
    *c = (work_check){0};
    c->b = b;
    c->s = s;
    int n = b->num_nodes, p = scene_prim_count(s);
    c->parent = malloc(((size_t)n + 1) * sizeof *c->parent);
    c->depth = malloc(((size_t)n + 1) * sizeof *c->depth);
    c->leaf_of_prim = malloc(((size_t)p + 1) * sizeof *c->leaf_of_prim);
    c->mark = calloc((size_t)n + 1, 1);
    /* Room for every node and primitive twice: more for one ray is no traversal worth tracing. */
    c->trace.cap_nodes = 2 * n + 64;
    c->trace.cap_prims = 2 * p + 64;
    c->trace.nodes = malloc((size_t)c->trace.cap_nodes * sizeof *c->trace.nodes);
    c->trace.prims = malloc((size_t)c->trace.cap_prims * sizeof *c->trace.prims);
    if (!c->parent || !c->depth || !c->leaf_of_prim || !c->mark || !c->trace.nodes || !c->trace.prims) {
        work_check_free(c);
        fail_msg("test machinery: out of memory for the work check of %d nodes", n);
    }
    for (int i = 0; i < p; i++) c->leaf_of_prim[i] = -1;
    /* Children come after their parent in no guaranteed order: walk from the root. */
    if (n > 0) {
        int *stack = c->trace.nodes, top = 0;  /* the trace's array is free until the first query */
        c->parent[0] = -1;
        c->depth[0] = 0;
        stack[top++] = 0;
        while (top > 0) {
            int i = stack[--top];
            const bvh_node *node = &b->nodes[i];
            if (node->count > 0) {
                for (int k = 0; k < node->count; k++) c->leaf_of_prim[b->prim_index[node->first + k]] = i;
                continue;
            }
            for (int k = 0; k < 2; k++) {
                int child = node->first + k;
                c->parent[child] = i;
                c->depth[child] = c->depth[i] + 1;
                stack[top++] = child;
            }
        }
    }
}

void work_check_free(work_check *c)
{
    if (!c) return;
    free(c->parent);
    free(c->depth);
    free(c->leaf_of_prim);
    free(c->mark);
    free(c->trace.nodes);
    free(c->trace.prims);
    *c = (work_check){0};
}

void work_check_begin(work_check *c)
{
    (void)counters_take();
    counters_trace_begin(&c->trace);
}

void work_check_end(work_check *c)
{
    counters_trace_end();
    c->counted = counters_take();
}

static const char *plural(unsigned long long n, const char *one, const char *many) { return n == 1 ? one : many; }

/* Faults every query is judged on first: the trace overflowed, or the counts were reset. */
static bool counts_intact(const work_check *c, int ray_index, const char *task, char *why, size_t len)
{
    const counters_trace *t = &c->trace;
    if (t->overflow) {
        snprintf(why, len, "ray %d: more than %d node visits or %d primitive tests for one ray: a traversal enters each "
                 "node at most once per ray (task %s)", ray_index, t->cap_nodes, t->cap_prims, task);
        return false;
    }
    if (c->counted.node_visits < (uint64_t)t->num_nodes || c->counted.prim_tests < (uint64_t)t->num_prims) {
        snprintf(why, len, "ray %d: the framework's counts were reset during the query (%d node visits and %d primitive "
                 "tests made, %llu and %llu left counted): part code must never read or reset the counters (task %s)",
                 ray_index, t->num_nodes, t->num_prims, (unsigned long long)c->counted.node_visits,
                 (unsigned long long)c->counted.prim_tests, task);
        return false;
    }
    return true;
}

static bool prim_was_tested(const work_check *c, int prim)
{
    for (int i = 0; i < c->trace.num_prims; i++)
        if (c->trace.prims[i] == prim) return true;
    return false;
}

/* The first node on the path from the root to `leaf` that the query never read through bvh_visit,
 * or -1 when it read them all. */
static int first_unvisited_ancestor(work_check *c, int leaf)
{
    const counters_trace *t = &c->trace;
    for (int i = 0; i < t->num_nodes; i++) c->mark[t->nodes[i]] = 1;
    int missing = -1;
    for (int n = leaf; n >= 0; n = c->parent[n])
        if (!c->mark[n]) missing = n;  /* keep going: the one nearest the root is the clearest */
    for (int i = 0; i < t->num_nodes; i++) c->mark[t->nodes[i]] = 0;
    return missing;
}

/* The path claims for primitive prim, which the query says it hit; "what" opens the message. */
static bool path_visited(work_check *c, const char *what, int prim, const char *task, char *why, size_t len)
{
    int leaf = c->leaf_of_prim[prim];
    if (leaf < 0) {
        snprintf(why, len, "%s, which no leaf of the tree holds (task %s)", what, task);
        return false;
    }
    int depth = c->depth[leaf];
    unsigned long long visits = c->counted.node_visits;
    if (visits < (unsigned long long)depth + 1) {
        snprintf(why, len, "%s in leaf %d at depth %d but only %llu node %s counted: call bvh_visit for every node you "
                 "enter (task %s)", what, leaf, depth, visits, plural(visits, "visit was", "visits were"), task);
        return false;
    }
    int missing = first_unvisited_ancestor(c, leaf);
    if (missing >= 0) {
        snprintf(why, len, "%s in leaf %d at depth %d, but node %d on the path from the root to that leaf was never read "
                 "through bvh_visit (%llu node visits counted): call bvh_visit for every node you enter (task %s)",
                 what, leaf, depth, missing, visits, task);
        return false;
    }
    return true;
}

bool work_check_closest(work_check *c, int ray_index, const hit *h, char *why, size_t why_len)
{
    if (!counts_intact(c, ray_index, "2.3", why, why_len)) return false;
    int prim = h->prim;
    if (prim < 0 || prim >= scene_prim_count(c->s) || c->b->num_nodes == 0) {
        snprintf(why, why_len, "ray %d: bvh_intersect reported prim %d, which the tree does not hold", ray_index, prim);
        return false;
    }
    char what[96];
    snprintf(what, sizeof what, "ray %d hit prim %d", ray_index, prim);
    unsigned long long tests = c->counted.prim_tests;
    if (!prim_was_tested(c, prim)) {
        snprintf(why, why_len, "%s but never tested it through scene_prim_intersect (%llu primitive %s counted): test "
                 "primitives only through scene_prim_intersect (task 2.3)", what, tests, plural(tests, "test was", "tests were"));
        return false;
    }
    return path_visited(c, what, prim, "2.3", why, why_len);
}

bool work_check_any(work_check *c, int ray_index, const ray *r, char *why, size_t why_len)
{
    if (!counts_intact(c, ray_index, "2.4", why, why_len)) return false;
    if (c->trace.num_prims == 0 || c->b->num_nodes == 0) {
        snprintf(why, why_len, "ray %d is occluded but no primitive test was counted: test primitives only through "
                 "scene_prim_intersect (task 2.4)", ray_index);
        return false;
    }
    /* Some primitive it tested must hit r; the claims hold for one of them (it may have found a hit
     * and tested more in the same leaf). Judge the first that hits when none satisfies them. */
    int first_hit = -1;
    char first_why[512] = "";
    for (int i = 0; i < c->trace.num_prims; i++) {
        int prim = c->trace.prims[i];
        ray probe = *r;
        hit scratch;
        if (!scene_prim_intersect(c->s, prim, &probe, &scratch)) continue;
        char what[96];
        snprintf(what, sizeof what, "ray %d is occluded by prim %d", ray_index, prim);
        char reason[512];
        if (path_visited(c, what, prim, "2.4", reason, sizeof reason)) return true;
        if (first_hit < 0) {
            first_hit = prim;
            snprintf(first_why, sizeof first_why, "%s", reason);
        }
    }
    if (first_hit < 0)
        snprintf(why, why_len, "ray %d is occluded but none of the %d primitives tested through scene_prim_intersect "
                 "hits it: test primitives only through scene_prim_intersect (task 2.4)", ray_index, c->trace.num_prims);
    else
        snprintf(why, why_len, "%s", first_why);
    return false;
}
