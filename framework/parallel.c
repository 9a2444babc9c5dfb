/* parallel_for (parallel.h): a shared counter hands out the indices, so a thread that finishes a
 * short call takes the next one instead of waiting for a fixed share. */
#include "parallel.h"
#include "counters.h"
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct {
    void (*job)(void *arg, int i);
    void *arg;
    int count;
    atomic_int next;  /* the next index nobody has taken */
} parallel_run;

/* One helper thread's share of a run, and what it counted: counters are per thread, so the caller
 * adds each helper's to its own after the join. */
typedef struct {
    parallel_run *run;
    work_counts work;
} helper_slot;

static void run_calls(parallel_run *run)
{
    /* Each thread takes one index past the end before it stops; near INT_MAX that wraps (atomic
     * arithmetic wraps, it is not undefined), so a negative index ends the loop too. */
    for (int i = atomic_fetch_add(&run->next, 1); i >= 0 && i < run->count; i = atomic_fetch_add(&run->next, 1))
        run->job(run->arg, i);
}

static void *helper(void *p)
{
    helper_slot *slot = p;
    run_calls(slot->run);
    slot->work = counters_take();  /* a new thread counts from zero: all of it is this run's */
    return NULL;
}

int parallel_threads(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);  /* -1 when it cannot tell (a sandbox): one thread */
    return cores < 1 ? 1 : cores > PARALLEL_MAX_THREADS ? PARALLEL_MAX_THREADS : (int)cores;
}

void parallel_for(int count, void (*job)(void *arg, int i), void *arg)
{
    parallel_for_threads(parallel_threads(), count, job, arg);
}

void parallel_for_threads(int threads, int count, void (*job)(void *arg, int i), void *arg)
{
    if (count <= 0) return;
    parallel_run run = {job, arg, count, 0};
    threads = threads < 1 ? 1 : threads > PARALLEL_MAX_THREADS_ASKED ? PARALLEL_MAX_THREADS_ASKED : threads;
    int wanted = threads < count ? threads : count;
    /* The helpers' handles on the stack up to the cores' count; a -t beyond it takes them from the
     * heap, and without memory the calling thread does all the work. */
    pthread_t tid_small[PARALLEL_MAX_THREADS];
    helper_slot slot_small[PARALLEL_MAX_THREADS];
    pthread_t *tid = tid_small;
    helper_slot *slots = slot_small;
    if (wanted > PARALLEL_MAX_THREADS) {
        tid = malloc((size_t)wanted * sizeof *tid);
        slots = malloc((size_t)wanted * sizeof *slots);
        if (!tid || !slots) wanted = 1;
    }
    int started = 0;
    for (; started < wanted - 1; started++) {
        slots[started] = (helper_slot){&run, {0, 0, 0}};
        if (pthread_create(&tid[started], NULL, helper, &slots[started]) != 0) break;
    }
    run_calls(&run);  /* the calling thread works too; alone when no helper could start */
    for (int i = 0; i < started; i++) {
        pthread_join(tid[i], NULL);
        counters_add(slots[i].work);
    }
    if (tid != tid_small) free(tid);
    if (slots != slot_small) free(slots);
}
