/* Adversary (invented against the judge, issue 29's fourth class): in a split suite the subject's
 * records reach the judge, the course's process that holds the verdicts and runs as root. Each call
 * here first writes a record of its own making to the record pipe (descriptor 3): the right
 * function and the judge's own hash of the call's inputs, but 1 GiB of outputs claimed where the
 * function returns one byte; then it exits. A judge that allocated what a record claims before
 * checking it grew to 1 GiB a test, and said so in the test's message, the claimed number
 * included. The judge now sizes the payload from what the call can return before anything is
 * allocated: every test fails in the judge's own words. No points.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: its outputs are longer than this call can return
 * absent: 1073741824
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdint.h>

/* A three-argument system call tucked into two movabs immediates (see forged-film.c). */
__asm__(".text\n.globl pl_tucked6j\n.type pl_tucked6j, @function\npl_tucked6j:\n"
        "  .byte 0x48, 0xb8, 0x49, 0x89, 0xca, 0x4c, 0x89, 0xc8, 0xeb, 0x02\n"
        "  .byte 0x48, 0xb8, 0x0f, 0x05, 0xc3, 0x90, 0x90, 0x90, 0x90, 0x90\n");
long pl_tucked6j(long a, long b, long c, long d, long e, long nr);

static long raw(long nr, long a, long b, long c)
{
    long (*call)(long, long, long, long, long, long) =
        (long (*)(long, long, long, long, long, long))((char *)pl_tucked6j + 2);
    return call(a, b, c, 0, 0, nr);
}

/* The record's header as the seam lays it out (80 bytes), read from the shipped grader's sources. */
typedef struct {
    uint32_t magic, fn;
    uint64_t inputs, rays, node_visits, prim_tests;
    uint32_t todo_calls;
    int32_t todo_fn;
    uint64_t rng_state, rng_inc;
    uint32_t trace_nodes, trace_prims, trace_overflow, payload;
} forged_header;

/* The seam's FNV-1a hash of the call's inputs. */
static uint64_t hash(uint64_t h, const void *data, unsigned long size)
{
    const unsigned char *p = data;
    for (unsigned long i = 0; i < size; i++) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    int64_t wide = n;
    double d[] = {s1, s2};
    uint64_t h = hash(hash(hash(0xcbf29ce484222325ull, &wide, sizeof wide), d, sizeof d), &tol, sizeof tol);
    struct { forged_header h; unsigned char answer; } r = {{0x6d616573u, 17, h, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0,
                                                             1u << 30}, 1};
    raw(1, 3, (long)&r, sizeof r);  /* write to the record pipe */
    raw(231, 0, 0, 0);              /* exit_group(0) */
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
