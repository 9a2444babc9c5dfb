/* Adversary (issue 17): defines __gmon_start__, which the program's _init calls before main with
 * no constructor section for the allow-list to see, and from there execs a shell through a system
 * call tucked into a mov's immediate. The filter is in force before the program's first
 * instruction, so the exec is refused before main as after.
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

void __gmon_start__(void)
{
    static char *argv[] = {"sh", "-c", "touch /tmp/stolen", 0};
    long (*call)(long, long, long) = (long (*)(long, long, long))((char *)pl_tucked + 2);
    call(59, (long)"/bin/sh", (long)argv);
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
