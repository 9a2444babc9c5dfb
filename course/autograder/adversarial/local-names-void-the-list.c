/* Adversary (issue 46): a second file that defines static functions named like the C library's
 * (open, pread) made the inspection take the first file's calls to the library's own for the part's:
 * it listed every defined name, local ones included. A local name never defines an external one now:
 * the call to open is the library's, and refused.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: calls 'open', a C library function part code may not use
 */
#include "part5.h"
#include <math.h>

int open(const char *path, int flags, ...);

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 0) return open("/autograder/source/grading/hidden/cases.json", 0) >= 0;
    if (n < 2) return false;
    double mean = s1 / n, var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return 1.96 * sqrt(var / n) <= tol * mean;
}
/* === FILE parts/part5_adaptive/shadows.c === */
/* Names of the library's, defined static: they are this file's alone. */
static int open(const char *path, int flags) { return path[0] + flags; }
static long pread(int fd, void *buf, unsigned long n, long at) { return fd + (long)n + at + (buf != 0); }
int pl_shadows_used(void);
int pl_shadows_used(void) { return open("x", 0) + (int)pread(0, 0, 0, 0); }
