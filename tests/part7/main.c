/* Test machinery: not part of any assignment. The part 7 suite: make test-part7. */
#include "../common/test.h"

int microfacet_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){microfacet_tests, NULL});
}
