/* Attack (course/judge/split_check.sh): part 5's task is the stub, and it rewrites the test state of
 * its own process: forgets its stub report (pl_todo_reset), silences it, and tells cmocka to skip
 * every test that is still to come. Expected: nothing changes in the judge's process. With no stub
 * report left, the tests judge its answer, a constant false, as they would judge `return false;`:
 * right in the three tests where the pixel must go on sampling, wrong in the others.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: passes=3
 */
#include "part5.h"
#include "../../framework/todo.h"

void cmocka_set_skip_filter(const char *pattern);

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    bool answer = PL_TODO_FALSE("5.1", "adaptive_converged");
    pl_todo_reset();
    pl_todo_set_quiet(true);
    cmocka_set_skip_filter("*");
    return answer;
}
