/* Stub bookkeeping: which student tasks ran as stubs. Mutable state by necessity (a stub can only
 * report by side effect); every access is atomic or under the mutex, since renders are threaded. */
#include "todo.h"
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

#define MAX_REPORTED 64

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static const char *reported[MAX_REPORTED];  /* function names already printed (string literals) */
static int num_reported;
static char last[160];
static atomic_int calls;
static atomic_bool quiet;

/* Counts every call (the tests ask "did a stub run?") but prints once per function, so a render
 * that calls a stub a million times says so in one line. */
void pl_todo_report(const char *task, const char *function)
{
    atomic_fetch_add(&calls, 1);
    pthread_mutex_lock(&lock);
    /* "3.4" -> "Part 3, task 3.4: direct_hemisphere()" */
    snprintf(last, sizeof last, "Part %.*s, task %s: %s()", (int)strcspn(task, "."), task, task, function);
    bool seen = false;
    for (int i = 0; i < num_reported; i++)
        if (strcmp(reported[i], function) == 0) seen = true;
    if (!seen && num_reported < MAX_REPORTED) reported[num_reported++] = function;
    if (!seen && !atomic_load(&quiet)) fprintf(stderr, "%s is not implemented yet\n", last);
    pthread_mutex_unlock(&lock);
}

int pl_todo_count(void) { return atomic_load(&calls); }

void pl_todo_reset(void)
{
    pthread_mutex_lock(&lock);
    atomic_store(&calls, 0);
    last[0] = '\0';
    pthread_mutex_unlock(&lock);
}

/* The caller coped with the stub (the linear scan stands in for an unwritten BVH): one call fewer
 * counts as missing work. */
void pl_todo_handled(void)
{
    pthread_mutex_lock(&lock);
    if (atomic_load(&calls) > 0) atomic_fetch_sub(&calls, 1);
    last[0] = '\0';
    pthread_mutex_unlock(&lock);
}

const char *pl_todo_last(void) { return last[0] ? last : NULL; }

void pl_todo_set_quiet(bool q) { atomic_store(&quiet, q); }
