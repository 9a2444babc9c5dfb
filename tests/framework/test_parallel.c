/* Test machinery: not part of any assignment. parallel_for (framework/parallel.c): every call made
 * once, the work counted on helper threads carried back to the caller. */
#include "../common/test.h"
#include <stdatomic.h>
#include <stdbool.h>
#include <time.h>
#include "../../framework/counters.h"
#include "../../framework/parallel.h"

#define CALLS 1000

typedef struct {
    atomic_int made[CALLS];  /* how often each index was called */
    atomic_int threads;      /* how many threads have made a call */
} call_log;

static _Thread_local bool joined;  /* this thread has made a call */

/* Each call records its index and counts two node visits and one primitive test, as a traversal
 * run inside a job would. On a machine of several cores, a thread's first call waits (5 s at
 * most) for a second thread to make one, so that work really is counted on a helper thread and
 * must be carried back: otherwise the calling thread could take every index before a helper starts. */
static void log_call(void *arg, int i)
{
    call_log *log = arg;
    if (!joined) {
        joined = true;
        atomic_fetch_add(&log->threads, 1);
        for (int wait = 0; parallel_threads() > 1 && atomic_load(&log->threads) < 2 && wait < 5000; wait++)
            nanosleep(&(struct timespec){0, 1000 * 1000}, NULL);
    }
    atomic_fetch_add(&log->made[i], 1);
    counters_add_visit(i);
    counters_add_visit(i);
    counters_add_prim(i);
}

static void test_parallel_for__calls_every_index_once_and_counts_the_work_for_the_caller(void **state)
{
    (void)state;
    static call_log log;  /* zeroed: static storage */
    (void)counters_take();
    parallel_for(CALLS, log_call, &log);
    for (int i = 0; i < CALLS; i++)
        if (atomic_load(&log.made[i]) != 1) fail_msg("index %d was called %d times, not once", i, atomic_load(&log.made[i]));
    work_counts w = counters_take();
    assert_int_equal(2 * CALLS, (int)w.node_visits);  /* whichever threads ran them */
    assert_int_equal(CALLS, (int)w.prim_tests);
    assert_true(parallel_threads() >= 1 && parallel_threads() <= PARALLEL_MAX_THREADS);
}

static void never_called(void *arg, int i)
{
    (void)arg;
    fail_msg("called with index %d for a count of zero or less", i);
}

static void test_parallel_for__no_call_for_a_count_of_zero_or_less(void **state)
{
    (void)state;
    parallel_for(0, never_called, NULL);
    parallel_for(-5, never_called, NULL);
}

int parallel_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parallel_for__calls_every_index_once_and_counts_the_work_for_the_caller),
        cmocka_unit_test(test_parallel_for__no_call_for_a_count_of_zero_or_less),
    };
    return cmocka_run_group_tests_name("parallel", tests, NULL, NULL);
}
