/* Attack (course/judge/split_check.sh): part 5's task is the stub; its first call prints a passing
 * summary and exits with status 0, mid-test, as a suite that passed would. Expected: every test
 * fails ("crashed, exited or stopped"), since the judge never gets the call's answer.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: passes=0
 */
#include "part5.h"
#include <stdio.h>
#include <stdlib.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    printf("[  PASSED  ] 9 test(s).\n");
    exit(0);
}
