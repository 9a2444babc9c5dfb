/* Adversary (issue 46): an entry of the transactional-memory clone table, which the C runtime's start
 * files register before main. The section is refused by name.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: has a .tm_clone_table section
 */
#include "part5.h"
#include <math.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}

__attribute__((section(".tm_clone_table"), used)) static void *clones[2] = {(void *)adaptive_converged, 0};
