/* Test machinery: not part of any assignment. The part 8 suite: make test-part8. */
#include "../common/test.h"

int envlight_tests(void), render_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){envlight_tests, render_tests, NULL});
}
