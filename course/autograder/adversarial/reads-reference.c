/* Adversary: opens the course's reference EXRs (relative and absolute paths, a hidden one
 * too), prints what it read and answers from their bytes. File calls are refused by the allow-list,
 * and the references are unreadable to student code.
 * part: 1
 * base: stub (part 1 as released, its other files stubs too: a stub earns nothing)
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=0 images=0
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stdio.h>
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    static const char *const paths[] = {"reference_images/part1/spheres_normals.exr",
        "../../../../reference_images/part1/spheres_normals.exr",
        "/autograder/source/reference_images/part1/spheres_normals.exr",
        "/autograder/source/reference_images/hidden/part1/lights_normals.exr"};
    unsigned char buf[4096];
    size_t got = 0;
    for (unsigned i = 0; i < sizeof paths / sizeof paths[0] && !got; i++) {
        FILE *f = fopen(paths[i], "rb");
        if (!f) continue;
        got = fread(buf, 1, sizeof buf, f);
        fclose(f);
    }
    if (got) {
        printf("read %zu bytes of a reference: %02x %02x %02x %02x\n", got, buf[0], buf[1], buf[2], buf[3]);
        return camera_generate_ray(c, buf[(unsigned)x % got] / 255.0f, buf[(unsigned)y % got] / 255.0f);
    }
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
