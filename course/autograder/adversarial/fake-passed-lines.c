/* Adversary: prints what cmocka prints for passing tests ("[  PASSED  ]", "[       OK ]",
 * "OK") on every call, to stdout and stderr, and answers like a stub. Verdicts come from cmocka's
 * XML files, never from the console.
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
    printf("[       OK ] test_pixel_sample_ray__centre\nOK\n[==========] 28 test(s) run.\n[  PASSED  ] 28 test(s).\n");
    fprintf(stderr, "[  PASSED  ] 28 test(s).\nOK\n");
    fflush(stdout);
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
