/* Grader machinery: not part of any assignment. The subject's half of the split suites (seam.h): each
 * outermost call of a wrapped part function becomes one record on the pipe ($PL_SEAM_FD, else fd 3).
 * Records are buffered and written whole, at least every FLUSH_SECONDS so the judge works while the
 * subject does; a subject that dies loses what it had not written, which the judge sees as the end
 * of the stream: the test fails, as it should. */
#include "../../framework/clock.h"
#include "seam.h"
#include "../../framework/todo.h"
#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define BUFFER_SIZE (64 * 1024)
#define FLUSH_SECONDS 0.002

static _Thread_local int depth;  /* part calls under way on this thread */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static unsigned char buffer[BUFFER_SIZE];
static size_t buffered;
static int out_fd = -1;
static double last_flush;

/* Everything or nothing: a write error (the judge has gone) ends the subject quietly. */
static void write_all(const void *data, size_t size)
{
    const unsigned char *p = data;
    while (size > 0) {
        ssize_t n = write(out_fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) _exit(4);
        p += n;
        size -= (size_t)n;
    }
}

static void flush_locked(void)
{
    if (buffered > 0) write_all(buffer, buffered);
    buffered = 0;
    last_flush = clock_seconds();
}

static void put_locked(const void *data, size_t size)
{
    if (buffered + size > BUFFER_SIZE) flush_locked();
    if (size >= BUFFER_SIZE) write_all(data, size);
    else {
        memcpy(buffer + buffered, data, size);
        buffered += size;
    }
}

static void flush_at_exit(void)
{
    pthread_mutex_lock(&lock);
    flush_locked();
    pthread_mutex_unlock(&lock);
}

__attribute__((constructor)) static void open_pipe(void)
{
    const char *fd = getenv("PL_SEAM_FD");
    out_fd = fd && *fd ? atoi(fd) : 3;
    atexit(flush_at_exit);
}

bool seam_begin(seam_call *c)
{
    /* A nested call leaves the depth alone: the wrapper calls the real function and returns. */
    c->outermost = depth == 0;
    if (!c->outermost) return false;
    depth = 1;
    c->work = counters_peek();
    c->todo = pl_todo_count();
    counters_trace *t = counters_trace_current();
    c->nodes = t ? (uint32_t)t->num_nodes : 0;
    c->prims = t ? (uint32_t)t->num_prims : 0;
    c->overflow = t && t->overflow;
    return true;
}

void seam_end(seam_call *c, seam_fn fn, uint64_t inputs, const rng *g, const void *out, size_t size,
              const void *const *extra, const size_t *extra_sizes, int num_extra)
{
    depth = 0;
    work_counts now = counters_peek();
    counters_trace *t = counters_trace_current();
    int todo = pl_todo_count() - c->todo;
    seam_header h = {SEAM_MAGIC, fn, inputs,
                     {now.rays - c->work.rays, now.node_visits - c->work.node_visits, now.prim_tests - c->work.prim_tests},
                     todo > 0 ? (uint32_t)todo : 0, todo > 0 ? seam_fn_from_todo(pl_todo_last()) : -1,
                     g ? *g : (rng){0, 0},
                     t ? (uint32_t)t->num_nodes - c->nodes : 0, t ? (uint32_t)t->num_prims - c->prims : 0,
                     t && t->overflow && !c->overflow, (uint32_t)size};
    for (int i = 0; i < num_extra; i++) h.payload += (uint32_t)extra_sizes[i];
    pthread_mutex_lock(&lock);
    put_locked(&h, sizeof h);
    if (h.trace_nodes) put_locked(t->nodes + c->nodes, h.trace_nodes * sizeof(int));
    if (h.trace_prims) put_locked(t->prims + c->prims, h.trace_prims * sizeof(int));
    put_locked(out, size);
    for (int i = 0; i < num_extra; i++) put_locked(extra[i], extra_sizes[i]);
    if (clock_seconds() - last_flush > FLUSH_SECONDS) flush_locked();
    pthread_mutex_unlock(&lock);
}

void seam_end_hit(seam_call *c, seam_fn fn, uint64_t inputs, bool found, const ray *r, const hit *h)
{
    seam_hit_out out;
    memset(&out, 0, sizeof out);
    out.found = found;
    if (r) out.r = *r;
    if (h) out.h = *h;
    seam_end(c, fn, inputs, NULL, &out, sizeof out, NULL, NULL, 0);
}

_Static_assert(sizeof(seam_sample_out) == 7 * 4, "padding in seam_sample_out");

rgb seam_end_sample(seam_call *c, seam_fn fn, uint64_t inputs, rgb f, const vec3 *wi, const float *pdf)
{
    seam_sample_out out;
    memset(&out, 0, sizeof out);
    out.f = f;
    if (wi) out.wi = *wi;
    if (pdf) out.pdf = *pdf;
    seam_end(c, fn, inputs, NULL, &out, sizeof out, NULL, NULL, 0);
    return f;
}
