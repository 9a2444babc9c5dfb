/* Test machinery: the course suite (make test-course), the instructor's own tools: the release
 * stripper's rules. The student release leaves course/ out, and this suite with it. */
int strip_tests(void);

int main(void)
{
    return strip_tests() != 0;
}
