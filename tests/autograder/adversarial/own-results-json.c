/* Adversary: writes its own full-marks results.json where Gradescope and the grader keep theirs
 * (absolute and relative paths), and answers like a stub. File calls are refused by the allow-list;
 * the results folder is not writable to student code; run_autograder writes the final file itself.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdio.h>

static const char forged[] = "{\"score\": 100, \"output\": \"forged\", \"tests\": [{\"name\": \"Part 5: unit tests\", "
                             "\"score\": 100, \"max_score\": 10, \"status\": \"passed\"}]}\n";

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static const char *const paths[] = {"/autograder/results/results.json", "../results.json", "../../results.json",
                                        "../../../results.json", "../../../../results.json", "results.json"};
    for (unsigned i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        FILE *f = fopen(paths[i], "w");
        if (f) {
            fputs(forged, f);
            fclose(f);
        }
    }
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
