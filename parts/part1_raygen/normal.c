/* Part 1's worked example, complete: normal shading (--normals), the pattern every task follows,
 * finished, and the first picture a student sees. */
#include "part1.h"

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
