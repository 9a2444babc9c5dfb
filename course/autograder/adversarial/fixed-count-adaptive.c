/* Adversary (issue 46): a part 5 that stops every pixel at one fixed number of samples, chosen so
 * that the mean samples per pixel is within 5% of the course's, with no confidence test at all.
 * Before, only that mean was compared (and it is printed to every student), so it took the adaptive
 * image case. Now the sample-rate map is compared with the course's, block by block: a fixed count
 * follows none of the course's variation and loses the case.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=lost images=0
 * present: does each pixel stop by its own confidence interval
 */
#include "part5.h"

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    (void)s1, (void)s2, (void)tol;
    return n >= 416;
}
