/* Test machinery: not part of any assignment. The part 3 suite: make test-part3. */
#include "../common/test.h"

int sampling_tests(void), direct_tests(void), cornell_tests(void), leaving_tests(void), grazing_tests(void),
    delta_light_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){sampling_tests, direct_tests, cornell_tests, leaving_tests, grazing_tests,
                                            delta_light_tests, NULL});
}
