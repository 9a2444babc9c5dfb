/* Adversary (issue 17): includes the course's part 3 through a system include folder (so that -MMD
 * leaves it out of the dependency file), from the tree of a part graded earlier, from the grader's
 * copy of the course and from the bundle, marked a system header. The trees hold no part's source
 * but the submission's, earlier trees are gone, and the rest is root's alone: no path is found and
 * the stubs below are what is built. Also embeds /etc/passwd with .incbin (readable, not secret).
 * part: 3
 * base: stub
 * replaces: parts/part3_direct/direct.c
 * expect: unit=0 images=0
 * other: none
 * absent: root:x:0:0
 */
#pragma GCC system_header
#if __has_include(<../../proc/self/cwd/../../part1/tree/parts/part3_direct/direct.c>)
#include <../../proc/self/cwd/../../part1/tree/parts/part3_direct/direct.c>
#elif __has_include(<../../proc/self/cwd/../part1/parts/part3_direct/direct.c>)
#include <../../proc/self/cwd/../part1/parts/part3_direct/direct.c>
#elif __has_include(<../../autograder/source/parts/part3_direct/direct.c>)
#include <../../autograder/source/parts/part3_direct/direct.c>
#elif __has_include(<../../proc/self/cwd/../../../work/course/parts/part3_direct/direct.c>)
#include <../../proc/self/cwd/../../../work/course/parts/part3_direct/direct.c>
#else
#include "part3.h"
#include "../../framework/todo.h"
__asm__(".section .rodata\n.globl pl_passwd\npl_passwd:\n.incbin \"/etc/passwd\"\n.byte 0\n.text\n");
extern const char pl_passwd[];

rgb bsdf_f(const material *m, vec3 wo, vec3 wi) { return rgb_make(pl_passwd[0] * 0.0f, 0, 0); }
float bsdf_pdf(const material *m, vec3 wo, vec3 wi) { return 0.0f; }
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf) { *pdf = 0.0f; *wi = wo; return rgb_make(0, 0, 0); }
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h) { return rgb_make(1, 0, 1); }
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g) { return rgb_make(1, 0, 1); }
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g) { return rgb_make(1, 0, 1); }
#endif
