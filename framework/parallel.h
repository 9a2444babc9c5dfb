/* Independent pieces of work on every core, for part code that wants them: part 2's build may make
 * its subtrees side by side (handout/part2.md, "Making it fast"). Part code may not start threads
 * itself (the grader's allow-list refuses pthread_create); this is its one way to, with a bound on
 * how many and the work they count carried back to the caller. The framework's own pools (the
 * render's tiles, the output files' encoders) and the course's tools run on it too, with the thread
 * count they were asked for (parallel_for_threads).
 * Parts may not call: parallel_threads, parallel_for_threads (the grader refuses them; the functions
 * marked PL_PART_API are theirs). */
#ifndef PL_PARALLEL_H
#define PL_PARALLEL_H

#include "part_api.h"

/* Calls job(arg, i) once for every i in [0, count), on up to parallel_threads() threads (the
 * calling thread among them), in no fixed order, and returns when every call has returned. The
 * calls must not depend on each other's order or on which thread runs them; they may write only
 * what no other call reads. The work they count (node visits, primitive tests: counters.h) is
 * added to the calling thread's totals, as if it had done it (though not to a test's list of which
 * nodes one query visited). count <= 0 does nothing; when no thread can
 * be started, the calling thread makes every call itself. */
PL_PART_API void parallel_for(int count, void (*job)(void *arg, int i), void *arg);

/* How many threads parallel_for uses at most: the machine's online cores, 1 to PARALLEL_MAX_THREADS.
 * (The BVH benchmark gives Embree the same number.) */
#define PARALLEL_MAX_THREADS 16
int parallel_threads(void);

/* parallel_for on exactly `threads` threads (the calling thread among them; at least 1, at most
 * PARALLEL_MAX_THREADS_ASKED), whatever the machine has: -t N for the render, --jobs N for the
 * references. Not for part code (its threads are the framework's to bound). */
#define PARALLEL_MAX_THREADS_ASKED 1024
void parallel_for_threads(int threads, int count, void (*job)(void *arg, int i), void *arg);

#endif
