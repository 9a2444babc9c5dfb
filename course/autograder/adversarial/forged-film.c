/* Adversary (invented against the film stream): the render's film comes back on descriptor 3. The
 * code writes a film of its own there first (the right header and size, every pixel the reference's
 * likely mean: a flat grey with made-up sums) and exits before the framework sends the real one.
 * The grader reads whatever arrives, so it must refuse this one by its shape (sample counts that
 * are not the case's, sums no samples can have) or its image: no points.
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

static long raw(long nr, long a, long b, long c)
{
    long (*call)(long, long, long, long, long, long) =
        (long (*)(long, long, long, long, long, long))((char *)pl_tucked6 + 2);
    return call(a, b, c, 0, 0, nr);
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int sent;
    if (!sent++) {
        static unsigned char film[8 + 8 + 32 + 136 * 64 + 8] = {'P', 'L', 'F', 'I', 'L', 'M', '1', '\n', 8, 0, 0, 0, 8, 0, 0, 0};
        for (int i = 0; i < 64; i++) film[48 + 136 * i + 128] = 64;  /* n = 64 samples, sums all zero */
        raw(1, 3, (long)film, sizeof film);  /* write to the film's descriptor */
        raw(231, 0, 0, 0);                   /* exit_group(0): the framework never sends its film */
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
