/* Test machinery: not part of any assignment. The part 3 suite: make test-part3. */
int sampling_tests(void);
int direct_tests(void);
int cornell_tests(void);
int delta_light_tests(void);

int main(void)
{
    int failed = 0;
    failed += sampling_tests();
    failed += direct_tests();
    failed += cornell_tests();
    failed += delta_light_tests();
    return failed != 0;
}
