/* Adversary: correct answers, plus a constructor (code that runs before main, before any check:
 * here it prints fake passing lines). Constructors are refused by the allow-list: zero, even though
 * the function itself is right.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include <math.h>
#include <stdio.h>

__attribute__((constructor)) static void before_main(void)
{
    printf("[  PASSED  ] 9 test(s).\n");
}

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
