/* Test machinery: not part of any assignment. The part 2 suite (make test-part2): one group per file. */
#include "../common/test.h"

int slab_tests(void), build_tests(void), oracle_tests(void), images_tests(void), complexity_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){slab_tests, build_tests, oracle_tests, images_tests, complexity_tests, NULL});
}
