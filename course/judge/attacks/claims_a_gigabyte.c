/* Attack (course/judge/split_check.sh): part 5's task is the stub, and each call first writes a
 * record of its own making to the record pipe: the right function and inputs, but outputs of
 * exactly SEAM_MAX_PAYLOAD (1 GiB) where the function returns one byte, and then only that byte
 * before the process exits. Within the old ceiling, so only the call's own bound refuses it: a judge
 * that allocated what the record claims before reading it grew to 1 GiB per test (and under a
 * memory limit failed saying it had no memory). Expected: every test fails with the judge's message
 * that the outputs are longer than the call can return, before any allocation, and the judge
 * neither crashes nor repeats the claimed size.
 * The judge runs under an address space of 200 MiB here, so one that allocates what the record
 * claims says it has no memory, and split_check.sh counts that as a problem.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * judge memory: 200 MiB
 * expect: passes=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include "../../grader/seam/seam.h"
#include <unistd.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    seam_header h = {SEAM_MAGIC, SEAM_adaptive_converged, 0, {0, 0, 0}, 0, -1, {0, 0}, 0, 0, 0, 1};
    double d[] = {s1, s2};
    h.inputs = SEAM_HASH(SEAM_HASH(seam_hash_int(SEAM_HASH_START, n), d), tol);  /* the judge's own hash */
    h.payload = SEAM_MAX_PAYLOAD;
    struct { seam_header h; unsigned char answer; } r = {h, 1};  /* "converged", the one byte sent */
    (void)!write(3, &r, sizeof r);
    _exit(0);
}
