/* Part 3 placeholder: the solution is being written. */
#include "part3.h"
#include "../../framework/todo.h"

rgb bsdf_f(const material *m, vec3 wo, vec3 wi) { return PL_TODO_RGB("3.1", "bsdf_f"); }
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    *wi = vec3_make(0, 0, 1);
    *pdf = 0.0f;
    return PL_TODO_RGB("3.2", "bsdf_sample_f");
}
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h) { return PL_TODO_RGB("3.3", "zero_bounce_radiance"); }
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g) { return PL_TODO_RGB("3.4", "direct_hemisphere"); }
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g) { return PL_TODO_RGB("3.5", "direct_importance"); }
