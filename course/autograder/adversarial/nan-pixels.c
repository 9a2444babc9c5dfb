/* Adversary: part 1 solved, but normal shading returns NaN where the normal's x component is near
 * 0.3 (a thin arc on each sphere: a few pixels of each normal-shaded image). Every image case must
 * fail, naming a bad pixel; so does the unit test that renders normals (the others are earned).
 * part: 1
 * base: solution
 * replaces: parts/part1_raygen/normal.c
 * expect: unit=lost images=0
 */
#include "part1.h"
#include <math.h>

rgb normal_shade(const hit *h)
{
    if (h->n.x > 0.27f && h->n.x < 0.33f) return rgb_make(__builtin_nanf(""), 0.5f, 0.5f);
    /* Otherwise the shipped mapping [-1, 1] -> [0, 1], clamped. */
    float r = fminf(fmaxf(0.5f * h->n.x + 0.5f, 0.0f), 1.0f), g = fminf(fmaxf(0.5f * h->n.y + 0.5f, 0.0f), 1.0f);
    return rgb_make(r, g, fminf(fmaxf(0.5f * h->n.z + 0.5f, 0.0f), 1.0f));
}
