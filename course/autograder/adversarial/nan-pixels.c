/* Adversary: part 1 solved, but normal shading returns NaN where the normal's x component is near
 * 0.3 (a thin arc on each sphere: a few pixels of each normal-shaded image). Every image case must
 * fail, naming a bad pixel; so does the unit test that renders normals (the others are earned).
 * part: 1
 * base: solution
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=lost images=0
 */
#include "part1.h"
#include "../../framework/todo.h"

ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    return camera_generate_ray(c, (x + u.x) / (float)width, (y + u.y) / (float)height);
}

static float normal_channel(float n)
{
    float v = 0.5f * n + 0.5f;
    return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
}

rgb normal_shade(const hit *h)
{
    if (h->n.x > 0.27f && h->n.x < 0.33f) return rgb_make(__builtin_nanf(""), 0.5f, 0.5f);
    return rgb_make(normal_channel(h->n.x), normal_channel(h->n.y), normal_channel(h->n.z));
}
