/* Test machinery: not part of any assignment. The part 2 suite: one binary, one group per file. */
#include <stdio.h>

int slab_tests(void);
int build_tests(void);
int oracle_tests(void);
int images_tests(void);
int complexity_tests(void);

int main(void)
{
    int failed = 0;
    failed += slab_tests();
    failed += build_tests();
    failed += oracle_tests();
    failed += images_tests();
    failed += complexity_tests();
    return failed ? 1 : 0;
}
