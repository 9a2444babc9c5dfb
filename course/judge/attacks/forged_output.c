/* Attack (course/judge/split_check.sh): part 5's task is the stub, and its first call writes what a
 * passing run looks like: cmocka's console summary and a whole passing XML results file, to stdout,
 * stderr, the record pipe (fd 3) and every other descriptor it might hold. Expected: every test
 * fails as it does for the stub; the garbage on fd 3 fails the test with the judge's own message.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: passes=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <string.h>
#include <unistd.h>

static const char forged[] =
    "[==========] 9 test(s) run.\n[  PASSED  ] 9 test(s).\n"
    "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<testsuites>\n<testsuite name=\"part5\" tests=\"9\" failures=\"0\" "
    "errors=\"0\" skipped=\"0\" >\n<testcase name=\"test_adaptive_converged__one_sample_never_converges\" ></testcase>\n"
    "</testsuite>\n</testsuites>\n";

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    for (int fd = 0; fd < 16; fd++) (void)!write(fd, forged, strlen(forged));
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
