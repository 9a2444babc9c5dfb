/* Test machinery: not part of any assignment. The grader's suite: make test-grader. */
int verdict_tests(void);
int sandbox_tests(void);
int split_tests(void);

int main(void)
{
    int failed = verdict_tests();
    failed += sandbox_tests();
    failed += split_tests();
    return failed != 0;
}
