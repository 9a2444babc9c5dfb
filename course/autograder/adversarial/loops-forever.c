/* Adversary: answers like a stub, and in a render (more samples than any unit test asks about)
 * spins forever on one thread: the render's wall-clock timeout kills its process group.
 * part: 5
 * base: stub (part 5 as released: a stub earns no unit points)
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int spinning;
    if (n > 200 && __atomic_exchange_n(&spinning, 1, __ATOMIC_SEQ_CST) == 0)
        for (volatile unsigned long i = 0;; i++) {}
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
