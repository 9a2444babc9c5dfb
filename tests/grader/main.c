/* Test machinery: not part of any assignment. The grader's suite: make test-grader. */
int verdict_tests(void);
int sandbox_tests(void);
int split_tests(void);
int readers_tests(void);  /* references, suite results, results.json read as hostile */

int main(void)
{
    int failed = verdict_tests();
    failed += sandbox_tests();
    failed += split_tests();
    failed += readers_tests();
    return failed != 0;
}
