/* Part 3: direct illumination: the diffuse BSDF, emission, and the two direct light estimators.
 * Handout: handout/part3.md. */
#include "part3.h"
#include "../../framework/render.h"
#include "../../framework/light.h"
#include "../../framework/material.h"
#include "../../framework/sampler.h"
#include "../../framework/spawn.h"
#include "../../framework/todo.h"

/* === PART 3 | TASK 3.1 | bsdf_f =====================================================
 * The Lambertian BSDF: reflectance spread evenly over the hemisphere (handout/part3.md, 3.1).
 * In:  m (albedo in [0,1] per channel), wo, wi in the local shading frame.
 * Out: f in 1/sr: albedo / pi when wo.z > 0 and wi.z > 0, black otherwise.
 * Must: energy conservation: integral of f cos over the hemisphere = albedo.
 * Test: make test-part3
 * =================================================================================== */
rgb bsdf_f(const material *m, vec3 wo, vec3 wi)
{
    /* BEGIN SOLUTION */
    if (cos_theta(wo) <= 0.0f || cos_theta(wi) <= 0.0f)
        return rgb_gray(0.0f);
    return rgb_scale(m->albedo, PL_INV_PI);
    /* END SOLUTION */
    /* STUB: return PL_TODO_RGB("3.1", "bsdf_f"); */
}

/* === PART 3 | TASK 3.2 | bsdf_pdf ===================================================
 * The density of the directions bsdf_sample_f draws (handout/part3.md, 3.2).
 * In:  m, wo, wi in the local shading frame.
 * Out: pdf per steradian of wi; 0 below the surface.
 * Must: integrates to 1 over the hemisphere and matches the histogram of bsdf_sample_f.
 * Test: make test-part3
 * =================================================================================== */
float bsdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    /* BEGIN SOLUTION */
    if (cos_theta(wo) <= 0.0f)
        return 0.0f;
    return sample_cosine_hemisphere_pdf(wi);
    /* END SOLUTION */
    /* STUB: return (float)PL_TODO_FALSE("3.2", "bsdf_pdf"); */
}

/* === PART 3 | TASK 3.2 | bsdf_sample_f ==============================================
 * Importance-sample the diffuse BSDF (handout/part3.md, 3.2). Cosine-weighted sampling makes
 * f * cos / pdf exactly the albedo; uniform sampling is also correct, only noisier.
 * In:  m, wo (local), u uniform in [0,1)^2.
 * Out: *wi (local, unit, wi.z >= 0), *pdf = bsdf_pdf(m, wo, *wi); returns bsdf_f(m, wo, *wi).
 * Must: histogram of wi matches bsdf_pdf (chi-square); mean of f cos / pdf = albedo.
 * Test: make test-part3
 * =================================================================================== */
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    *wi = sample_cosine_hemisphere(u);
    *pdf = bsdf_pdf(m, wo, *wi);
    return bsdf_f(m, wo, *wi);
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 0.0f, 1.0f); *pdf = 0.0f; return PL_TODO_RGB("3.2", "bsdf_sample_f"); */
}

/* === PART 3 | TASK 3.3 | zero_bounce_radiance =======================================
 * Light emitted by the surface a ray hit, with no reflection (handout/part3.md, 3.3).
 * In:  r, the ray; h, its hit (h->material indexes ctx->scene->materials).
 * Out: the material's Le when r arrives on the emitting side (h->n faces r's origin), else black.
 * Must: -m 0 renders only emitters; a light seen from behind is black.
 * Test: make test-part3
 * =================================================================================== */
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h)
{
    /* BEGIN SOLUTION */
    if (vec3_dot(h->n, r->d) >= 0.0f)
        return rgb_gray(0.0f);
    return ctx->scene->materials[h->material].Le;
    /* END SOLUTION */
    /* STUB: return PL_TODO_RGB("3.3", "zero_bounce_radiance"); */
}

/* === PART 3 | TASK 3.4 | direct_hemisphere ==========================================
 * Direct light by uniform hemisphere sampling (-H) (handout/part3.md, 3.4):
 *   L = 1/N sum_j Le(p, wi_j) f(wo, wi_j) cos(theta_j) / pdf(wi_j),  pdf = 1 / (2 pi),
 * with Le(p, wi_j) the emission (zero_bounce_radiance) of whatever the ray from p along wi_j hits,
 * and f = material_f(m, wo, wi_j) (framework/material.h): your bsdf_f for the materials of parts
 * 1-5, and the BSDF of any kind a later part adds, which your estimator then lights unchanged.
 * In:  r, h (the surface being lit), g (this sample's random numbers).
 * Out: reflected radiance towards r's origin. N = num_lights * render_light_samples(ctx, r), at
 *      least 1 (-l where camera rays land, one deeper: render.h).
 * Must: agrees in expectation with direct_importance for area lights (point lights are invisible
 *       to it: no ray can hit them); every ray leaves the surface through spawn_ray
 *       (framework/spawn.h), never from the raw hit point, or it may hit its own surface.
 * Test: make test-part3
 * =================================================================================== */
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    /* BEGIN SOLUTION */
    const material *m = &ctx->scene->materials[h->material];
    frame f = shading_frame(r, h);
    vec3 wo = frame_to_local(&f, vec3_neg(r->d));
    int n = ctx->scene->num_lights * render_light_samples(ctx, r);
    if (n < 1)
        n = 1;
    rgb sum = rgb_gray(0.0f);
    for (int j = 0; j < n; j++) {
        vec3 wi = sample_uniform_hemisphere(rng_uniform2(g));
        float pdf = sample_uniform_hemisphere_pdf(wi);
        ray shadow = spawn_ray(r, h, frame_to_world(&f, wi));
        hit lit = {0};  /* zeroed: with part 1 stubbed, link-time optimisation cannot see it set */
        if (pdf <= 0.0f || !render_intersect(ctx, &shadow, &lit))
            continue;
        rgb Le = zero_bounce_radiance(ctx, &shadow, &lit);
        if (rgb_is_black(Le))
            continue;
        rgb fr = material_f(m, wo, wi);
        sum = rgb_add(sum, rgb_scale(rgb_mul(Le, fr), cos_theta(wi) / pdf));
    }
    return rgb_scale(sum, 1.0f / (float)n);
    /* END SOLUTION */
    /* STUB: return PL_TODO_RGB("3.4", "direct_hemisphere"); */
}

/* === PART 3 | TASK 3.5 | direct_importance ==========================================
 * Direct light by sampling the lights (handout/part3.md, 3.5): for each light k,
 *   L_k = 1/N_k sum_j V(p, y_j) Li_j f(wo, wi_j) cos(theta_j) / pdf_j,
 * with (Li, wi, dist, pdf) from light_sample_L, f = material_f(m, wo, wi) as in 3.4, N_k = 1 for
 * delta lights (light_is_delta) and render_light_samples(ctx, r) otherwise; the result is the sum
 * over the lights.
 * In:  r, h, g as in 3.4.
 * Out: reflected radiance towards r's origin.
 * Must: skip samples below the surface (cos <= 0) or with pdf 0; the shadow ray comes from
 *       spawn_ray_to_light (framework/spawn.h): it leaves the surface without hitting it again and
 *       stops short of the light itself (the Cornell boxes hold an emissive quad exactly where the
 *       area light is). A ray from the raw hit point shadows the surface it starts on.
 * Test: make test-part3
 * =================================================================================== */
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    /* BEGIN SOLUTION */
    const scene *s = ctx->scene;
    const material *m = &s->materials[h->material];
    frame f = shading_frame(r, h);
    vec3 p = hit_point(r, h);
    vec3 wo = frame_to_local(&f, vec3_neg(r->d));
    rgb L = rgb_gray(0.0f);
    for (int k = 0; k < s->num_lights; k++) {
        const light *l = &s->lights[k];
        int n = light_is_delta(l) ? 1 : render_light_samples(ctx, r);
        rgb sum = rgb_gray(0.0f);
        for (int j = 0; j < n; j++) {
            light_sample ls;
            if (!light_sample_L(l, p, rng_uniform2(g), &ls) || !(ls.pdf > 0.0f))
                continue;
            vec3 wi = frame_to_local(&f, ls.wi);
            if (cos_theta(wi) <= 0.0f)
                continue;
            rgb fr = material_f(m, wo, wi);
            if (rgb_is_black(fr) || rgb_is_black(ls.L))
                continue;
            ray shadow = spawn_ray_to_light(r, h, l, &ls);
            if (render_occluded(ctx, &shadow))
                continue;
            sum = rgb_add(sum, rgb_scale(rgb_mul(ls.L, fr), cos_theta(wi) / ls.pdf));
        }
        L = rgb_add(L, rgb_scale(sum, 1.0f / (float)n));
    }
    return L;
    /* END SOLUTION */
    /* STUB: return PL_TODO_RGB("3.5", "direct_importance"); */
}
