/* Adversary: allocates without bound (64 MiB at a time, touching each block, never freeing) and
 * uses the memory; when malloc finally fails at the sandbox's address-space limit it writes through
 * the null pointer. Answers like a stub. Malloc is allowed: the limit and the crash must score zero.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdlib.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    for (;;) {
        volatile char *p = malloc((size_t)64 << 20);
        p[0] = 1;                     /* a null p: SIGSEGV */
        p[((size_t)64 << 20) - 1] = 1;
        if (n < 0) break;             /* never: keeps the compiler from proving the loop endless */
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
