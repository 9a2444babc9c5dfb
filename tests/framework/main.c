/* Test machinery: not part of any assignment. The framework suite: one binary, one group per module. */
int math_tests(void);
int rng_tests(void);
int image_tests(void);
int cli_tests(void);
int render_tests(void);
int film_tests(void);    /* the film and the sample-range merge */
int camera_file_tests(void);
int dae_tests(void);
int scenes_tests(void);
int strip_tests(void);  /* the release stripper (tools/strip.c) */

int main(void)
{
    int failed = 0;
    failed += math_tests();
    failed += rng_tests();
    failed += image_tests();
    failed += cli_tests();
    failed += render_tests();
    failed += film_tests();
    failed += camera_file_tests();
    failed += dae_tests();
    failed += scenes_tests();
    failed += strip_tests();
    return failed ? 1 : 0;
}
