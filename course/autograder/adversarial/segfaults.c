/* Adversary: writes through a null pointer on its first call (the unit tests and renders that
 * reach it crash).
 * part: 1
 * base: stub (part 1 as released, its other files stubs too: a stub earns nothing)
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=0 images=0
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stddef.h>
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    volatile int *p = NULL;
    *p = x;
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
