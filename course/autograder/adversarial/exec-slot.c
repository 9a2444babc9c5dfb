/* Adversary (invented against the filter's one exec): the filter lets through only an execveat
 * from descriptor 255. The code opens /bin/sh, raises its descriptor limit, moves the descriptor
 * to 255 and execveats it; then an in-memory file (memfd_create) exec'd the same way. The slot
 * can never be filled again (RLIMIT_NOFILE is 255 and cannot be raised), and memfd_create is not
 * allowed: every exec fails.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 */
#include "part5.h"
#include "../../framework/todo.h"

/* A six-argument system call tucked into two movabs immediates (see hidden-syscall-exec.c): entered
 * 2 bytes in, mov %rcx, %r10; mov %r9, %rax; a jump over the second opcode; syscall; ret. */
__asm__(".text\n.globl pl_tucked6\n.type pl_tucked6, @function\npl_tucked6:\n"
        "  .byte 0x48, 0xb8, 0x49, 0x89, 0xca, 0x4c, 0x89, 0xc8, 0xeb, 0x02\n"
        "  .byte 0x48, 0xb8, 0x0f, 0x05, 0xc3, 0x90, 0x90, 0x90, 0x90, 0x90\n");
long pl_tucked6(long a, long b, long c, long d, long e, long nr);

static long raw(long nr, long a, long b, long c, long d, long e)
{
    long (*call)(long, long, long, long, long, long) =
        (long (*)(long, long, long, long, long, long))((char *)pl_tucked6 + 2);
    return call(a, b, c, d, e, nr);
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int tried;
    if (!tried++) {
        static char *argv[] = {"sh", "-c", "touch /tmp/stolen", 0};
        long limit[2] = {4096, 4096};
        raw(302, 0, 7 /* RLIMIT_NOFILE */, (long)limit, 0, 0);          /* prlimit64: raise */
        long fd = raw(257, -100, (long)"/bin/sh", 0, 0, 0);              /* openat, read-only */
        raw(33, fd, 255, 0, 0, 0);                                       /* dup2 into the slot */
        raw(322, 255, (long)"", (long)argv, 0, 0x1000);                  /* execveat(255, "", AT_EMPTY_PATH) */
        long mem = raw(319, (long)"x", 0, 0, 0, 0);                      /* memfd_create */
        raw(322, mem, (long)"", (long)argv, 0, 0x1000);
        raw(59, (long)"/bin/sh", (long)argv, 0, 0, 0);                   /* execve */
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
