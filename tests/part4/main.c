/* Test machinery: not part of any assignment. The part 4 suite: make test-part4. */
#include "../common/test.h"

int furnace_tests(void), roulette_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){furnace_tests, roulette_tests, NULL});
}
