/* Framework-internal: the work counters. Part code never includes this header: only the framework,
 * the tests, the benchmark and the grader do, and the grader refuses a submission that names any
 * symbol declared here.
 *
 * Work is counted where the framework does it for the parts, never where a part reports it:
 *   rays            accel_intersect, accel_occluded (accel.c)
 *   node visits     bvh_visit (bvh.c): a traversal reads every node it enters through it
 *   primitive tests scene_prim_intersect (scene.c): the only counted way to test a primitive
 * Each thread counts its own work (no atomics on the hot path); a reader takes and resets the
 * calling thread's counts. The heat map, the JSON sidecar, the complexity test and the benchmark
 * read them here.
 *
 * Symbols part code must never reference (the grader's allow-list refuses them):
 *   counters_take, counters_add_ray, counters_add_visit, counters_add_prim,
 *   counters_trace_begin, counters_trace_end, counters_peek, counters_add, counters_trace_current
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_COUNTERS_H
#define PL_COUNTERS_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    uint64_t rays;         /* accel_intersect + accel_occluded calls */
    uint64_t node_visits;  /* bvh_visit calls */
    uint64_t prim_tests;   /* scene_prim_intersect calls */
} work_counts;

/* The calling thread's counts since its last call; resets them to zero. */
work_counts counters_take(void);

/* The calling thread's counts, left as they are; and counts added in one go. The grader's split
 * suites (grader/seam/) carry the work a part's call did from the process that ran it to the judge. */
work_counts counters_peek(void);
void counters_add(work_counts w);

/* The counting points, called by accel.c, bvh.c and scene.c only. */
void counters_add_ray(void);
void counters_add_visit(int node);
void counters_add_prim(int prim);

/* For the tests' consistency checks: which nodes and primitives one query touched, in order. The
 * caller owns the arrays; entries past a capacity are dropped and set `overflow`. */
typedef struct {
    int *nodes; int num_nodes, cap_nodes;  /* bvh_visit indices */
    int *prims; int num_prims, cap_prims;  /* scene_prim_intersect primitives */
    bool overflow;                         /* some entry did not fit */
} counters_trace;

/* Records into t (emptied first) on the calling thread until counters_trace_end. */
void counters_trace_begin(counters_trace *t);
void counters_trace_end(void);
/* The calling thread's trace being recorded, or NULL (for the split suites, like counters_peek). */
counters_trace *counters_trace_current(void);

#endif
