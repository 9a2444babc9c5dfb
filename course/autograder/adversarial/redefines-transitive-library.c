/* Adversary (issue 17): correct answers, and definitions of names that libraries the program loads
 * only indirectly already define: liblzma's lzma_code (libxml2 reaches liblzma when it opens a
 * scene file, to read compressed ones) and libgcc_s's _Unwind_Backtrace. The executable's definitions would
 * take their place, so part code would run inside the scene loader, where the allow-list never
 * looked. The allow-list reads the names of every library loaded, transitively, and refuses the
 * part: zero, though its answers are right (with the definitions removed it gets full marks).
 * (_Unwind_Backtrace is also a name reserved to the implementation, refused as such: issue 46.)
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: defines 'lzma_code', which a library of the program already defines
 */
#include "part5.h"
#include <math.h>

/* The 95% interval's half-width against the tolerance, both sides squared (no square root). */
bool adaptive_converged(int n, double s1, double s2, float tol)
{
    if (n < 2) return false;
    double mean = s1 / n, bound = tol * mean;
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));
    return bound >= 0.0 && 3.8416 * var / n <= bound * bound;
}

int lzma_code(void *stream, int action);
int lzma_code(void *stream, int action)
{
    (void)stream, (void)action;
    return 11;  /* LZMA_PROG_ERROR: libxml2 then reads the file as it is */
}

void _Unwind_Backtrace(void);
void _Unwind_Backtrace(void) {}
