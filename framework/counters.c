/* The work counters (counters.h): per-thread, so the hot path pays one thread-local add and one
 * well-predicted branch (is a test tracing?) per count, and no atomics. */
#include "counters.h"
#include "check.h"
#include <stddef.h>

static _Thread_local work_counts counts;
static _Thread_local counters_trace *trace;  /* NULL unless a test is tracing this thread */

/* Read and reset in one step, on the thread that did the work (the render loop's workers hand
 * theirs to the loop; a test takes its own). */
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

PL_HOT void counters_add_ray(void) { counts.rays++; }

/* A traced count also records which node or primitive: appended while the test's list has room,
 * else the trace says it overflowed (the test then knows its record is incomplete). */
static void trace_append(counters_trace *t, int *list, int *num, int cap, int value)
{
    if (*num < cap) list[(*num)++] = value;
    else t->overflow = true;
}

PL_HOT void counters_add_visit(int node)
{
    counts.node_visits++;
    counters_trace *t = trace;
    if (t) trace_append(t, t->nodes, &t->num_nodes, t->cap_nodes, node);
}

PL_HOT void counters_add_prim(int prim)
{
    counts.prim_tests++;
    counters_trace *t = trace;
    if (t) trace_append(t, t->prims, &t->num_prims, t->cap_prims, prim);
}

void counters_trace_begin(counters_trace *t)
{
    t->num_nodes = t->num_prims = 0;
    t->overflow = false;
    trace = t;
}

void counters_trace_end(void) { trace = NULL; }

counters_trace *counters_trace_current(void) { return trace; }
