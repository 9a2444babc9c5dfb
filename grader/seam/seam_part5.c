/* Grader machinery: not part of any assignment. Part 5's function across the split (seam.h; see
 * seam_part1.c for the pattern). */
#include "seam.h"
#include "../../parts/part5_adaptive/part5.h"

static uint64_t converged_inputs(int n, double s1, double s2, float tol)
{
    double d[] = {s1, s2};
    return SEAM_HASH(SEAM_HASH(seam_hash_int(SEAM_HASH_START, n), d), tol);
}

/* The verdict, sent as a byte (SEAM_FIXED in seam.h). */
SEAM_FIXED(bool, unsigned char, adaptive_converged, (int n, double s1, double s2, float tol), (n, s1, s2, tol),
           converged_inputs(n, s1, s2, tol), NULL)
