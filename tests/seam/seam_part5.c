/* Grader machinery: not part of any assignment. Part 5's function across the split (seam.h; see
 * seam_part1.c for the pattern). */
#include "seam.h"
#include "../../parts/part5_adaptive/part5.h"

static uint64_t converged_inputs(int n, double s1, double s2, float tol)
{
    double d[] = {s1, s2};
    return SEAM_HASH(SEAM_HASH(seam_hash_int(SEAM_HASH_START, n), d), tol);
}

#ifdef PL_SEAM_SUBJECT
bool __real_adaptive_converged(int n, double s1, double s2, float tol);
bool __wrap_adaptive_converged(int n, double s1, double s2, float tol);

bool __wrap_adaptive_converged(int n, double s1, double s2, float tol)
{
    seam_call call;
    uint64_t in = converged_inputs(n, s1, s2, tol);
    if (!seam_begin(&call)) return __real_adaptive_converged(n, s1, s2, tol);
    unsigned char out = __real_adaptive_converged(n, s1, s2, tol);
    seam_end(&call, SEAM_ADAPTIVE_CONVERGED, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}
#endif

#ifdef PL_SEAM_JUDGE
bool adaptive_converged(int n, double s1, double s2, float tol)
{
    unsigned char out;
    seam_replay_fixed(SEAM_ADAPTIVE_CONVERGED, converged_inputs(n, s1, s2, tol), NULL, &out, sizeof out);
    return out != 0;
}
#endif
