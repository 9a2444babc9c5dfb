/* Test machinery: not part of any assignment. The part 6 suite: make test-part6. */
#include "../common/test.h"

int specular_tests(void), render_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){specular_tests, render_tests, NULL});
}
