/* Adversary (invented against the trees): leaves files where a later part, or a later grading,
 * could read them (/tmp, /dev/shm, /var/tmp, its own tree and the sandbox folder above it), and a
 * process that calls setsid to outlive its render. The render's filter refuses creating files, fork
 * and setsid; the tree is removed when the part is graded. test.sh checks none of the files exist.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * absent-files: /tmp/pathlab-persist /dev/shm/pathlab-persist /var/tmp/pathlab-persist
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
    /* In a render only (its film descriptor, 3, is open): the unit-test suite still writes cmocka's XML
     * files until the judge and subject split lands, so its filter lets it create files. */
    if (!tried++ && raw(72, 3, 1 /* fcntl(3, F_GETFD) */) >= 0) {
        static const char *const paths[] = {"/tmp/pathlab-persist", "/dev/shm/pathlab-persist",
                                            "/var/tmp/pathlab-persist", "pathlab-persist", "../pathlab-persist"};
        for (unsigned i = 0; i < sizeof paths / sizeof paths[0]; i++)
            raw(2, (long)paths[i], 0101 /* O_WRONLY | O_CREAT */);  /* open; mode in rdx is 0 */
        if (raw(57, 0, 0) == 0) {  /* fork, setsid, and live on */
            raw(112, 0, 0);
            for (;;) raw(34, 0, 0);  /* pause */
        }
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
