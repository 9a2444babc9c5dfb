/* Part 1, task 1.4 (the camera ray of one pixel sample) and the worked example (normal shading). */
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

/* A normal component mapped from [-1, 1] to [0, 1]. A unit normal computed in float can have a
 * component a rounding error beyond 1 (a sphere's (p - c) / r at its pole gives -1.0000001), which
 * would map to a tiny negative radiance, and the film counts negative radiance as a bad sample. */
static float normal_channel(float n)
{
    float v = 0.5f * n + 0.5f;
    return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
}

/* Worked example, complete: the pattern every task follows, finished. Maps each component of the
 * unit normal from [-1, 1] to [0, 1], so +X is red, +Y green, +Z blue. */
rgb normal_shade(const hit *h)
{
    return rgb_make(normal_channel(h->n.x), normal_channel(h->n.y), normal_channel(h->n.z));
}
