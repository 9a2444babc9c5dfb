/* Adversary: correct answers, and runs a shell command with system() (copying the references
 * and writing a results file). system is refused by the allow-list: zero for the part.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include <math.h>
#include <stdlib.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static int done;
    if (!done++)
        if (system("cp -r /autograder/source/reference_images /tmp/stolen 2>/dev/null; "
                   "echo '{\"score\": 100}' > /autograder/results/results.json 2>/dev/null") != 0) done = 1;
    if (n < 2) return false;
    double mean = s1 / n;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
