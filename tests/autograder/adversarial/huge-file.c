/* Adversary: writes a file without bound (1 MiB blocks), and answers like a stub. File calls are
 * refused by the allow-list; where it runs, the sandbox's file-size limit stops it.
 * part: 5
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 */
#include "part5.h"
#include "../../framework/todo.h"
#include <stdio.h>
#include <string.h>

bool adaptive_converged(int n, double s1, double s2, float tol)
{
    static char block[1 << 20];
    memset(block, 'x', sizeof block);
    FILE *f = fopen("flood.bin", "wb");
    while (f && fwrite(block, 1, sizeof block, f) == sizeof block) {}
    if (f) fclose(f);
    return PL_TODO_FALSE("5.1", "adaptive_converged");
}
