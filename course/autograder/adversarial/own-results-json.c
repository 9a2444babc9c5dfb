/* Adversary: writes its own full-marks results.json where Gradescope and the grader keep
 * theirs (absolute and relative paths), and answers like a stub. File calls are refused by the
 * allow-list; the results folder is not writable to student code; run_autograder writes the final
 * file itself.
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
    static const char *const paths[] = {"/autograder/results/results.json", "../results.json",
        "../../results.json", "../../../results.json", "../../../../results.json", "results.json"};
    for (unsigned i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        FILE *f = fopen(paths[i], "w");
        if (!f) continue;
        fputs("{\"score\": 100, \"output\": \"forged\", \"tests\": []}\n", f);
        fclose(f);
    }
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
