/* Test machinery: not part of any assignment. Part 1's suite (make test-part1): one group per file. */
#include "../common/test.h"

int camera_ray_tests(void), triangle_tests(void), sphere_tests(void), pixel_tests(void);

int main(void)
{
    return pl_run_groups((const pl_group[]){camera_ray_tests, triangle_tests, sphere_tests, pixel_tests, NULL});
}
