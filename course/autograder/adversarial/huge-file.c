/* Adversary: writes a file without bound (1 MiB blocks), and answers like a stub. File calls are
 * refused by the allow-list; where it runs, the sandbox's file-size limit stops it.
 * part: 1
 * base: stub (part 1 as released, its other files stubs too: a stub earns nothing)
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=0 images=0
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stdio.h>
#include <string.h>
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    static char block[1 << 20];
    memset(block, 120, sizeof block);
    FILE *f = fopen("flood.bin", "wb");
    while (f && fwrite(block, 1, sizeof block, f) == sizeof block) {}
    if (f) fclose(f);
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
