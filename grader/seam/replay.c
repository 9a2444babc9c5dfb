/* Grader machinery: not part of any assignment. The judge's half of the split suites (seam.h): part
 * N's functions answer from the subject's records ($PL_SEAM_FD, else stdin). Nothing read is trusted:
 * every length is bounded before it is used, and anything wrong fails the running test. */
#include "seam.h"
#include "../../tests/common/test.h"
#include "../../framework/todo.h"
#include <errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_TODO_REPLAYED 64  /* tests ask whether a stub ran, not how often */

static int in_fd;
static pthread_t test_thread;       /* main's: the thread cmocka runs the tests on */
static bool broken;                 /* the stream failed once: every later call fails too */
static unsigned char *payload;      /* the last record's outputs (one test calls from one thread) */
static _Thread_local int bound_nodes, bound_prims;  /* seam_trace_bounds, for the next replay */

void seam_trace_bounds(int nodes, int prims)
{
    bound_nodes = nodes;
    bound_prims = prims;
}
static size_t payload_room;

__attribute__((constructor)) static void open_pipe(void)
{
    const char *fd = getenv("PL_SEAM_FD");
    in_fd = fd && *fd ? atoi(fd) : 0;
    test_thread = pthread_self();
}

_Noreturn void seam_fail(seam_fn fn, const char *format, ...)
{
    char text[512];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    broken = true;
    if (pthread_equal(pthread_self(), test_thread)) check_fail_msg(__FILE__, __LINE__, "%s() under test: %s", seam_fn_name(fn), text);
    /* A render's worker cannot end the test through cmocka's longjmp: end the judge instead. */
    fprintf(stderr, "seam: %s() under test: %s\n", seam_fn_name(fn), text);
    fflush(NULL);
    _exit(3);
}

/* Reads exactly size bytes through a buffer (a record is a few small reads, a trace many); false at
 * the end of the stream (the subject crashed, exited or stopped). */
static unsigned char in_buffer[64 * 1024];
static size_t in_start, in_end;

static bool read_all(void *data, size_t size)
{
    unsigned char *p = data;
    while (size > 0) {
        if (in_start == in_end) {
            ssize_t n = read(in_fd, in_buffer, sizeof in_buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            in_start = 0;
            in_end = (size_t)n;
        }
        size_t k = in_end - in_start < size ? in_end - in_start : size;
        memcpy(p, in_buffer + in_start, k);
        in_start += k;
        p += k;
        size -= k;
    }
    return true;
}

static void read_or_fail(seam_fn fn, void *data, size_t size)
{
    if (!read_all(data, size))
        seam_fail(fn, "its record stops short: the code under test crashed or stopped while answering");
}

/* The trace entries the call added, into the test's own trace (at most its capacity). */
static void replay_trace(seam_fn fn, const seam_header *h)
{
    counters_trace *t = counters_trace_current();
    if (!t && (h->trace_nodes || h->trace_prims)) seam_fail(fn, "it sent a trace the test was not recording");
    if (h->trace_nodes > SEAM_MAX_TRACE || h->trace_prims > SEAM_MAX_TRACE) seam_fail(fn, "it sent an oversized trace");
    for (uint32_t i = 0; i < h->trace_nodes + h->trace_prims; i++) {
        int entry;
        read_or_fail(fn, &entry, sizeof entry);
        bool node = i < h->trace_nodes;
        int *list = node ? t->nodes : t->prims, *num = node ? &t->num_nodes : &t->num_prims;
        int cap = node ? t->cap_nodes : t->cap_prims, bound = node ? bound_nodes : bound_prims;
        if (entry < 0 || entry >= bound)
            seam_fail(fn, "it reports a visit to a %s that is not one of the %d of this call", node ? "node" : "primitive",
                      bound);  /* never the entry: a number the code under test chose */
        if (*num < cap) list[(*num)++] = entry;
        else t->overflow = true;
    }
    if (t && h->trace_overflow) t->overflow = true;
}

static void replay_todo(const seam_header *h, seam_fn fn)
{
    int named = h->todo_fn >= 0 && h->todo_fn < SEAM_NUM_FUNCTIONS ? h->todo_fn : (int)fn;
    for (uint32_t i = 0; i < h->todo_calls && i < MAX_TODO_REPLAYED; i++)
        pl_todo_report(seam_fn_task(named), seam_fn_name(named));
}

const void *seam_replay(seam_fn fn, uint64_t inputs, rng *g, size_t max, size_t *size)
{
    if (broken) seam_fail(fn, "an earlier call's record was wrong");
    seam_header h;
    if (!read_all(&h, sizeof h))
        seam_fail(fn, "no answer: the code under test crashed, exited or stopped in this call or before it");
    if (h.magic != SEAM_MAGIC) seam_fail(fn, "the answer is not a record (something else was written to the pipe)");
    if (h.fn != (uint32_t)fn)
        seam_fail(fn, "the answer is for %s(): the code under test did not make the test's calls", seam_fn_name((int)h.fn));
    if (h.inputs != inputs) seam_fail(fn, "the answer is for a call with other arguments than the test's");
    /* Sized before anything is allocated: a record claiming more than this call can answer (up to
     * SEAM_MAX_PAYLOAD) would make the judge grow to what the subject names. The message is the
     * judge's own: it never repeats the claimed size, a number the code under test chose. */
    if (h.payload > max || h.payload > SEAM_MAX_PAYLOAD)
        seam_fail(fn, "its outputs are longer than this call can return");
    replay_trace(fn, &h);
    seam_trace_bounds(0, 0);
    if (h.payload > payload_room) {
        free(payload);
        payload_room = h.payload;
        payload = malloc(payload_room);
        if (!payload) {
            payload_room = 0;
            seam_fail(fn, "the judge has no memory for the outputs of this call");
        }
    }
    read_or_fail(fn, payload, h.payload);
    counters_add(h.work);
    replay_todo(&h, fn);
    if (g) *g = h.after;
    *size = h.payload;
    return payload;
}

void seam_replay_fixed(seam_fn fn, uint64_t inputs, rng *g, void *out, size_t size)
{
    size_t got;
    const void *p = seam_replay(fn, inputs, g, size, &got);
    if (got != size) seam_fail(fn, "its outputs are shorter than this call returns (%zu bytes)", size);
    memcpy(out, p, size);
}

bool seam_replay_hit(seam_fn fn, uint64_t inputs, ray *r, hit *h)
{
    seam_hit_out out;
    seam_replay_fixed(fn, inputs, NULL, &out, sizeof out);
    if (r) *r = out.r;
    if (h) *h = out.h;
    return out.found != 0;
}

rgb seam_replay_sample(seam_fn fn, uint64_t inputs, vec3 *wi, float *pdf)
{
    seam_sample_out out;
    seam_replay_fixed(fn, inputs, NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    if (pdf) *pdf = out.pdf;
    return out.f;
}
