/* Adversary: allocates without bound (64 MiB at a time, touching each block, never freeing);
 * when malloc finally fails at the sandbox's address-space limit it writes through the null
 * pointer. Malloc is allowed: the limit and the crash must score zero.
 * part: 1
 * base: stub (part 1 as released, its other files stubs too: a stub earns nothing)
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=0 images=0
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stdlib.h>
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    for (;;) {
        volatile char *p = malloc((size_t)64 << 20);
        p[0] = 1;  /* a null p: SIGSEGV */
        p[((size_t)64 << 20) - 1] = 1;
        if (width < 0) break;  /* never: keeps the compiler from proving the loop endless */
    }
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
