/* Adversary (issue 46): a file whose name holds HTML with an event attribute. Before, the refusal
 * quoted any printable name, and results.json (Markdown a course platform renders) carried the markup.
 * A refused name is described now, never quoted.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: characters other than a-z, 0-9 and
 * absent: onerror
 * absent: <img
 */
#include "part5.h"
#include <math.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
/* === FILE parts/part5_adaptive/<img src=x onerror=alert(1)>.c === */
int pl_named(void);
