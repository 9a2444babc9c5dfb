/* The work counters (counters.h): per-thread, so the hot path pays one thread-local add and one
 * well-predicted branch (is a test tracing?) per count, and no atomics. */
#include "counters.h"
#include <stddef.h>

static _Thread_local work_counts counts;
static _Thread_local counters_trace *trace;  /* NULL unless a test is tracing this thread */

work_counts counters_take(void)
{
    work_counts c = counts;
    counts = (work_counts){0, 0, 0};
    return c;
}

work_counts counters_peek(void) { return counts; }

void counters_add(work_counts w)
{
    counts.rays += w.rays;
    counts.node_visits += w.node_visits;
    counts.prim_tests += w.prim_tests;
}

void counters_add_ray(void) { counts.rays++; }

void counters_add_visit(int node)
{
    counts.node_visits++;
    counters_trace *t = trace;
    if (t) {
        if (t->num_nodes < t->cap_nodes) t->nodes[t->num_nodes++] = node;
        else t->overflow = true;
    }
}

void counters_add_prim(int prim)
{
    counts.prim_tests++;
    counters_trace *t = trace;
    if (t) {
        if (t->num_prims < t->cap_prims) t->prims[t->num_prims++] = prim;
        else t->overflow = true;
    }
}

void counters_trace_begin(counters_trace *t)
{
    t->num_nodes = t->num_prims = 0;
    t->overflow = false;
    trace = t;
}

void counters_trace_end(void) { trace = NULL; }

counters_trace *counters_trace_current(void) { return trace; }
