/* Adversary (issue 46): an indirect function, whose resolver the dynamic loader runs while the program
 * loads, before main and before any check of the test. The inspection refuses every IFUNC symbol.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: defines an indirect function
 */
#include "part5.h"
#include <math.h>
#include <stdio.h>

static bool real(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}

static bool (*resolve(void))(int, double, double, float)
{
    puts("[  PASSED  ] 9 test(s).");
    return real;
}

bool adaptive_converged(int n, double s1, double s2, float tol) __attribute__((ifunc("resolve")));
