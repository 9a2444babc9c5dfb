/* Attack (course/judge/split_check.sh), on part 1: pixel_sample_ray is right for its first 16 calls
 * and then ends the process with status 0, which in a render happens on a worker thread of the
 * subject; the judge then meets the end of the stream on its own worker thread, where cmocka cannot
 * fail the test, and must end with its own verdict (status 3), never hang or crash. Expected: the
 * tests with at most 16 pixel samples pass, as the right answers earn (the camera, triangle and
 * sphere tests, the two exact pixel_sample_ray tests, the one-sample pixel loop); the three
 * statistical pixel loop tests and the render test fail.
 * part: 1
 * replaces: parts/part1_raygen/pixel.c
 * expect: passes=24
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stdatomic.h>
#include <unistd.h>

ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    static atomic_int calls;
    if (atomic_fetch_add(&calls, 1) >= 16) _exit(0);
    return camera_generate_ray(c, (x + u.x) / (float)width, (y + u.y) / (float)height);
}
