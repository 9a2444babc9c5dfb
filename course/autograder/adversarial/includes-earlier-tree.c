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
/* The part as released (its stubs), and /etc/passwd embedded in the object. */
#include "part3.h"
#include "../../framework/render.h"
#include "../../framework/light.h"
#include "../../framework/sampler.h"
#include "../../framework/todo.h"
rgb bsdf_f(const material *m, vec3 wo, vec3 wi)
{
    return PL_TODO_RGB("3.1", "bsdf_f");
}
float bsdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    return (float)PL_TODO_FALSE("3.2", "bsdf_pdf");
}
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    *wi = vec3_make(0.0f, 0.0f, 1.0f); *pdf = 0.0f; return PL_TODO_RGB("3.2", "bsdf_sample_f");
}
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h)
{
    return PL_TODO_RGB("3.3", "zero_bounce_radiance");
}
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return PL_TODO_RGB("3.4", "direct_hemisphere");
}
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return PL_TODO_RGB("3.5", "direct_importance");
}
__asm__(".section .rodata\n.globl pl_passwd\npl_passwd:\n.incbin \"/etc/passwd\"\n.byte 0\n.text\n");
#endif
