/* Test machinery: not part of any assignment. The part 9 suite: make test-part9. */
#include "../common/test.h"

int lens_tests(void), render_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){lens_tests, render_tests, NULL});
}
