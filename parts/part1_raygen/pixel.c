/* Part 1, task 1.4: the camera ray of one pixel sample. The worked example is in normal.c. */
#include "part1.h"
#include "../../framework/todo.h"

/* === PART 1 | TASK 1.4 | pixel_sample_ray =============================================
 * The camera ray of one sample of pixel (x, y) (handout/part1.md, section 1.4). The framework's
 * pixel loop calls it once per sample, with u drawn for that sample.
 * In:  camera c; pixel (x, y), (0,0) = bottom-left; the film's width and height in pixels;
 *      u in [0,1)^2, where in the pixel the sample lies ((0.5, 0.5) is the centre).
 * Out: camera_generate_ray through film point ((x + u.x) / width, (y + u.y) / height).
 * Must: pixel (x, y) covers film [x/W, (x+1)/W] x [y/H, (y+1)/H], so u = (0, 0) is its
 *       bottom-left corner and uniform u covers the pixel uniformly.
 * Test: make test-part1
 * ====================================================================================== */
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    /* BEGIN SOLUTION */
    return camera_generate_ray(c, (x + u.x) / (float)width, (y + u.y) / (float)height);
    /* END SOLUTION */
    /* STUB: return PL_TODO_RAY("1.4", "pixel_sample_ray"); */
}
