/* Adversary (issue 46): part 3 with light sampling (task 3.5) replaced by the hemisphere estimator
 * (task 3.4): unbiased where the scene has no delta light, so its images match on average, but far
 * noisier. Before, grazing_direct and a hidden case judged the mean only, and gave it 4 points
 * without task 3.5. Every case whose passing depends on the estimator now checks the noise too.
 * part: 3
 * base: solution
 * replaces: parts/part3_direct/direct.c
 * expect: unit=lost images=lost
 * other: none
 * present: noisier than it should be
 */
#include "part3.h"
#include "../../framework/render.h"
#include "../../framework/light.h"
#include "../../framework/material.h"
#include "../../framework/sampler.h"
#include "../../framework/spawn.h"

rgb bsdf_f(const material *m, vec3 wo, vec3 wi)
{
    if (cos_theta(wo) <= 0.0f || cos_theta(wi) <= 0.0f) return rgb_gray(0.0f);
    return rgb_scale(m->albedo, PL_INV_PI);
}

float bsdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    (void)m;
    return cos_theta(wo) <= 0.0f ? 0.0f : sample_cosine_hemisphere_pdf(wi);
}

rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    *wi = sample_cosine_hemisphere(u);
    *pdf = bsdf_pdf(m, wo, *wi);
    return bsdf_f(m, wo, *wi);
}

rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h)
{
    if (vec3_dot(h->n, r->d) >= 0.0f) return rgb_gray(0.0f);
    return ctx->scene->materials[h->material].Le;
}

rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    const material *m = &ctx->scene->materials[h->material];
    frame f = shading_frame(r, h);
    vec3 wo = frame_to_local(&f, vec3_neg(r->d));
    int n = ctx->scene->num_lights * render_light_samples(ctx, r);
    if (n < 1) n = 1;
    rgb sum = rgb_gray(0.0f);
    for (int j = 0; j < n; j++) {
        vec3 wi = sample_uniform_hemisphere(rng_uniform2(g));
        float pdf = sample_uniform_hemisphere_pdf(wi);
        ray shadow = spawn_ray(r, h, frame_to_world(&f, wi));
        hit lit = {0};
        if (pdf <= 0.0f || !render_intersect(ctx, &shadow, &lit)) continue;
        rgb Le = zero_bounce_radiance(ctx, &shadow, &lit);
        if (rgb_is_black(Le)) continue;
        sum = rgb_add(sum, rgb_scale(rgb_mul(Le, material_f(m, wo, wi)), cos_theta(wi) / pdf));
    }
    return rgb_scale(sum, 1.0f / (float)n);
}

rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return direct_hemisphere(ctx, r, h, g);
}
