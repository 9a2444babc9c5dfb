/* Test machinery: not part of any assignment. Part 1's suite. */
int camera_ray_tests(void);
int triangle_tests(void);
int sphere_tests(void);
int pixel_tests(void);

int main(void)
{
    int failed = 0;
    failed += camera_ray_tests();
    failed += triangle_tests();
    failed += sphere_tests();
    failed += pixel_tests();
    return failed ? 1 : 0;
}
