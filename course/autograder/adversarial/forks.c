/* Adversary: correct answers, and forks on every call (a fork bomb): fork is not on the
 * allow-list, and the process limit of the sandbox's user stops it where it runs.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include <math.h>
#include <unistd.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (fork() == 0)
        for (;;) fork();
    if (n < 2) return false;
    double mean = s1 / n;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
