/* Adversary (issue 17): a compile error inside another file makes the compiler quote that file's
 * lines; the old grader put them in results.json (hidden scene lines, the course's source). Here
 * the part includes a scene of the tree and a framework source, and bytes that are not UTF-8. The
 * report keeps only the compiler's lines about the part's own files, escaped: no line of the scene
 * or the framework file reaches the student, and results.json stays valid with every entry.
 * part: 5
 * base: stub
 * replaces: parts/part5_adaptive/adaptive.c
 * expect: unit=0 images=0
 * other: none
 * absent: <COLLADA
 * absent: estimator dispatch and the tiled
 */
#include "part5.h"
#include "../../scenes/cornell_empty.dae"
#include "../../framework/render.c"
int pl_bad = "ÿþ not UTF-8 in a string the compiler quotes Ã";
