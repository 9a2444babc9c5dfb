/* Part 5: adaptive sampling. Handout: handout/part5.md. */
#include "part5.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 5 | TASK 5.1 | adaptive_converged =========================================
 * Whether a pixel may stop sampling (handout/part5.md): CS184's 95% confidence test on the mean
 * luminance of its samples.
 * In:  n >= 1 samples; s1 = sum of their luminances, s2 = sum of their squares; tol = T.
 * Out: true when I = 1.96 sqrt(var / n) <= tol * mean, with mean = s1 / n and
 *      var = (s2 - s1^2 / n) / (n - 1); false when n < 2 (no variance estimate yet).
 * Must: use the standard error of the mean (var / n), not the spread of one sample (var);
 *       rounding can make s2 - s1^2 / n slightly negative: treat that as 0.
 * Test: make test-part5
 * =================================================================================== */
bool adaptive_converged(int n, double s1, double s2, float tol)
{
    /* BEGIN SOLUTION */
    if (n < 2) return false;
    double mean = s1 / n;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    double half_width = 1.96 * sqrt(var / n);
    return half_width <= tol * mean;
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("5.1", "adaptive_converged"); */
}
