/* Test machinery: not part of any assignment. The grader's suite: make test-grader. */
int verdict_tests(void);

int main(void)
{
    return verdict_tests() != 0;
}
