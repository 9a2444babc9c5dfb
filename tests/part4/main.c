/* Test machinery: not part of any assignment. The part 4 suite: make test-part4. */
int furnace_tests(void);
int roulette_tests(void);

int main(void)
{
    int failed = 0;
    failed += furnace_tests();
    failed += roulette_tests();
    return failed != 0;
}
