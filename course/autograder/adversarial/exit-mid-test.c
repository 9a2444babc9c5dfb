/* Adversary: correct answers, but calls _exit(0) on its third call, mid-suite and mid-render: a
 * suite that stops early fails whatever it printed, and a render that wrote no image scores zero
 * (and _exit is not on the allow-list).
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
    static int calls;
    if (++calls == 3) _exit(0);
    if (n < 2) return false;
    double mean = s1 / n;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
