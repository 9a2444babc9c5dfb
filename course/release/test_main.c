/* Test machinery: the course suite (make test-course), the instructor's own tools: the release
 * stripper's rules, and the devcontainer the release ships. The student release leaves course/ out,
 * and this suite with it. */
int strip_tests(void);
int devcontainer_tests(void);

int main(void)
{
    int failed = strip_tests();
    failed += devcontainer_tests();
    return failed != 0;
}
