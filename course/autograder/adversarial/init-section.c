/* Adversary (issue 46): code in the .init section, which the C runtime runs before main (no
 * constructor attribute, no .init_array: the old deny-list of five section names did not see it).
 * Sections are allowed by kind now: .init is refused by name.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: has a .init section
 */
#include "part5.h"
#include <math.h>
#include <stdio.h>

__attribute__((section(".init"), used)) static void before_main(void) { puts("[  PASSED  ] 9 test(s)."); }

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
