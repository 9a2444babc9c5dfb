/* Adversary: opens the course's reference EXRs (relative and absolute paths, hidden ones too) and
 * answers from their bytes. File calls are refused by the allow-list, and references are
 * unreadable to student code.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdio.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static const char *const paths[] = {
        "reference_images/part5/spheres_adaptive.exr", "../../../../reference_images/part5/spheres_adaptive.exr",
        "/autograder/source/reference_images/part5/spheres_adaptive.exr",
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
        printf("read %zu bytes of a reference\n", got);
        return buf[(unsigned)n % got] & 1;
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
