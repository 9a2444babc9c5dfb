/* Test machinery: the course suite (make test-course), the instructor's own tools: the release
 * stripper's rules, the devcontainer the release ships, and the class grader's escaping. The student release leaves course/ out,
 * and this suite with it. */
int strip_tests(void);
int devcontainer_tests(void);
int class_text_tests(void);

int main(void)
{
    int failed = strip_tests();
    failed += devcontainer_tests();
    failed += class_text_tests();
    return failed != 0;
}
