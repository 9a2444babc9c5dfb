/* Adversary (issue 17): `#include "/dev/zero"` made the compiler reach 2 GB in 8 s. The compiler on
 * student files runs under its own memory limit: the build ends in about a second, the part scores
 * zero with "part 5's build ran past its memory limit", the grading goes on.
 * part: 5
 * base: solution
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * present: part 5's build ran past its memory limit
 */
#include "part5.h"
#include "/dev/zero"
