/* Adversary (invented against the film stream's messages): the render's film comes back on
 * descriptor 3, and a refused film's reason reaches the student in results.json. The code writes a
 * film header of its own there, its width and height 1074580685 and 1085276160 (the bits of the
 * floats 2.2 and 5.5: any 8 bytes the render read, a hidden scene's or its own memory's), and exits
 * before the framework sends the real film. The refusal once echoed both ("the film is
 * 1074580685x1085276160, the case renders ..."); it now says what the case expects in the grader's
 * words, and neither number may appear anywhere in results.json. No points.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * absent: 1074580685
 * absent: 1085276160
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
        /* "PLFILM1\n", width 0x400ccccd, height 0x40b00000 (little-endian), four counts of zero. */
        static const unsigned char header[48] = {'P', 'L', 'F', 'I', 'L', 'M', '1', '\n', 0xcd, 0xcc, 0x0c, 0x40,
                                                 0x00, 0x00, 0xb0, 0x40};
        raw(1, 3, (long)header, sizeof header);  /* write to the film's descriptor */
        raw(231, 0, 0, 0);                       /* exit_group(0): the framework never sends its film */
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
