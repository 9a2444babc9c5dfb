/* Adversary: writes through a null pointer on its first call (unit tests and renders crash).
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include <stddef.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    volatile int *p = NULL;
    *p = n;
    return false;
}
