/* Test machinery: not part of any assignment. The part 5 suite: make test-part5. */
#include "../common/test.h"

int adaptive_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){adaptive_tests, NULL});
}
