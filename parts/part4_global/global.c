/* Part 4: global illumination: paths of many bounces, Russian roulette, k-th bounce images.
 * Handout: handout/part4.md. */
#include "part4.h"
#include "../part3_direct/part3.h"
#include "../../framework/frame.h"
#include "../../framework/material.h"
#include "../../framework/render.h"
#include "../../framework/spawn.h"
#include "../../framework/todo.h"

/* === PART 4 | TASK 4.2 | russian_roulette ===========================================
 * End long paths at random without bias (handout/part4.md, 4.2). A rule that works well:
 * bounces 1, 2 and 3 are always taken; before bounce k >= 4 the path goes on with probability
 *   q = min(1, max(beta.r, beta.g, beta.b)),
 * and a surviving path divides beta by q: it carries the paths that were ended.
 * In:  *beta, the path throughput (product of f cos / pdf so far); next_depth; g.
 * Out: false to end the path; true to go on, with *beta /= q.
 * Must: E[beta after] = beta before (the mean does not change; only the noise does).
 * Test: make test-part4
 * =================================================================================== */
bool russian_roulette(rgb *beta, int next_depth, rng *g)
{
    /* BEGIN SOLUTION */
    if (next_depth < 4)
        return true;
    float q = fminf(1.0f, rgb_max(*beta));
    if (!(q > 0.0f) || rng_uniform(g) >= q)
        return false;
    *beta = rgb_scale(*beta, 1.0f / q);
    return true;
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("4.2", "russian_roulette"); */
}

/* === PART 4 | TASK 4.1 | at_least_one_bounce_radiance ===============================
 * Global illumination (handout/part4.md, 4.1): follow the path from h, one vertex per bounce:
 *   L = sum_{k=1..max_depth} beta_k * one_bounce_radiance(vertex k),
 *   beta_1 = 1,  beta_{k+1} = beta_k * f(wo, wi) |cos(theta_i)| / pdf(wi)
 * with wi, f and pdf from material_sample_f (framework/material.h: part 3's bsdf_sample_f for the
 * diffuse materials of parts 1-5, and whatever BSDF a later part gives a material of its own).
 * The settings are ctx->settings (framework/render.h): max_depth, accumulate, roulette. With -o 0
 * (!accumulate) only the k = max_depth term is kept. Loop or recurse, as you like.
 * The framework spends the -l light samples at the first vertex and one per light deeper, where
 * the path's own noise dominates (render_light_samples reads the depth of the ray that reached the
 * vertex: give each bounce ray its depth; handout/part4.md, 4.1).
 * In:  r, the ray that reached h (depth r->depth); h; g.
 * Out: radiance towards r's origin; the emission of h itself is NOT included (the framework adds
 *      it at the camera), nor the emission of any surface a bounce ray hits (see part4.h).
 * Must: bounce rays leave the surface through spawn_ray (framework/spawn.h), never from the raw
 *       hit point (they would hit their own surface); a path that misses ends; without
 *       settings.roulette (--no-rr) every path goes on to max_depth; with it, call russian_roulette.
 * Test: make test-part4
 * =================================================================================== */
rgb at_least_one_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    /* BEGIN SOLUTION */
    const render_settings *s = &ctx->settings;
    rgb L = rgb_gray(0.0f);
    rgb beta = rgb_gray(1.0f);
    ray cur = *r;
    hit at = *h;
    for (int depth = 1;; depth++) {
        if (s->accumulate || depth == s->max_depth)
            L = rgb_add(L, rgb_mul(beta, one_bounce_radiance(ctx, &cur, &at, g)));
        if (depth >= s->max_depth)
            break;

        /* Sample the next direction from the material's BSDF and fold f |cos| / pdf into the
         * throughput (|cos|: light may pass through a surface, below it). */
        const material *m = &ctx->scene->materials[at.material];
        frame f = shading_frame(&cur, &at);
        vec3 wo = frame_to_local(&f, vec3_neg(cur.d));
        vec3 wi;
        float pdf;
        rgb fr = material_sample_f(m, wo, rng_uniform2(g), &wi, &pdf);
        float cos_i = fabsf(cos_theta(wi));
        if (!(pdf > 0.0f) || rgb_is_black(fr) || cos_i == 0.0f)
            break;
        beta = rgb_mul(beta, rgb_scale(fr, cos_i / pdf));
        if (s->roulette && !russian_roulette(&beta, depth + 1, g))
            break;

        ray next = spawn_ray(&cur, &at, frame_to_world(&f, wi));  /* next.depth = depth */
        hit next_hit = {0};  /* zeroed: with part 1 stubbed, link-time optimisation cannot see it set */
        if (!render_intersect(ctx, &next, &next_hit))
            break;
        cur = next;
        at = next_hit;
    }
    return L;
    /* END SOLUTION */
    /* STUB: return PL_TODO_RGB("4.1", "at_least_one_bounce_radiance"); */
}
