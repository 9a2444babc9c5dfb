/* parallel_for (parallel.h): a shared counter hands out the indices, so a thread that finishes a
 * short call takes the next one instead of waiting for a fixed share. */
#include "parallel.h"
#include "counters.h"
#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

typedef struct {
    void (*job)(void *arg, int i);
    void *arg;
    int count;
    atomic_int next;       /* the next index nobody has taken */
    pthread_mutex_t lock;  /* guards work */
    work_counts work;      /* what the helper threads counted, for the caller */
} parallel_run;

static void run_calls(parallel_run *run)
{
    for (int i = atomic_fetch_add(&run->next, 1); i < run->count; i = atomic_fetch_add(&run->next, 1))
        run->job(run->arg, i);
}

/* A helper thread: its calls, then its counts handed over (counters are per thread). */
static void *helper(void *p)
{
    parallel_run *run = p;
    (void)counters_take();  /* a new thread counts from zero; this only makes it plain */
    run_calls(run);
    work_counts w = counters_take();
    pthread_mutex_lock(&run->lock);
    run->work.rays += w.rays;
    run->work.node_visits += w.node_visits;
    run->work.prim_tests += w.prim_tests;
    pthread_mutex_unlock(&run->lock);
    return NULL;
}

int parallel_threads(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN);  /* -1 when it cannot tell (a sandbox): one thread */
    return cores < 1 ? 1 : cores > PARALLEL_MAX_THREADS ? PARALLEL_MAX_THREADS : (int)cores;
}

void parallel_for(int count, void (*job)(void *arg, int i), void *arg)
{
    if (count <= 0) return;
    parallel_run run = {job, arg, count, 0, PTHREAD_MUTEX_INITIALIZER, {0, 0, 0}};
    int wanted = parallel_threads() < count ? parallel_threads() : count;
    pthread_t helpers[PARALLEL_MAX_THREADS];
    int started = 0;
    while (started < wanted - 1 && pthread_create(&helpers[started], NULL, helper, &run) == 0) started++;
    run_calls(&run);  /* the calling thread works too */
    for (int i = 0; i < started; i++) pthread_join(helpers[i], NULL);
    counters_add(run.work);
    pthread_mutex_destroy(&run.lock);
}
