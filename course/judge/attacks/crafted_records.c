/* Attack (course/judge/split_check.sh): part 5's task is the stub, and each call first writes
 * records of its own making to the record pipe, each wrong in one way the judge must survive: an
 * output of 1 GiB + 1, a trace of 2^31 entries, four billion stub reports naming no function, the
 * answer to another function, a short record; then the process exits. Expected: every test fails with the judge's
 * message, and the judge neither crashes nor allocates what the record claims.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: passes=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include "../../grader/seam/seam.h"
#include <stdlib.h>
#include <unistd.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    /* One flaw a test (each test is a process of its own): picked by a hash of the test's name,
     * which spreads part 5's nine tests over all five. */
    const char *test = getenv("PL_TEST_FILTER");
    uint32_t pick = 0;
    for (const char *c = test ? test : ""; *c; c++) pick = pick * 2 + (unsigned char)*c;
    seam_header h = {SEAM_MAGIC, SEAM_adaptive_converged, 0, {0, 0, 0}, 0, -1, {0, 0}, 0, 0, 0, 1};
    double d[] = {s1, s2};
    h.inputs = SEAM_HASH(SEAM_HASH(seam_hash_int(SEAM_HASH_START, n), d), tol);  /* the judge's own hash */
    switch (pick % 5) {
    case 0: h.payload = SEAM_MAX_PAYLOAD + 1; break;
    case 1: h.trace_nodes = 1u << 31; break;
    case 2: h.todo_calls = 0xffffffffu; h.todo_fn = 1 << 30; break;
    case 3: h.fn = SEAM_bvh_build; break;
    default: h.payload = 1 << 20; break;  /* promised, never sent */
    }
    struct { seam_header h; unsigned char answer; } r = {h, 1};  /* "converged", the one byte promised */
    (void)!write(3, &r, sizeof r);
    _exit(0);
}
