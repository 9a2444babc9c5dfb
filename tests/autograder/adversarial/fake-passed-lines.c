/* Adversary: prints what cmocka prints for passing tests ("[  PASSED  ]", "[       OK ]", "OK")
 * on every call, and answers like a stub. Verdicts come from cmocka's XML files, never the console.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdio.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    printf("[       OK ] test_adaptive_converged__one_sample_never_converges\nOK\n");
    printf("[==========] 9 test(s) run.\n[  PASSED  ] 9 test(s).\n");
    fprintf(stderr, "[  PASSED  ] 9 test(s).\nOK\n");
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
