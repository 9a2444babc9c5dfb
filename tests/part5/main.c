/* Test machinery: not part of any assignment. The part 5 suite: make test-part5. */
int adaptive_tests(void);

int main(void)
{
    return adaptive_tests() != 0;
}
