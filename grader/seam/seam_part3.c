/* Grader machinery: not part of any assignment. Part 3's functions across the split (seam.h; see
 * seam_part1.c for the pattern). The estimators take a generator: its state after the call travels
 * with the answer, so the test's next draw is the one it would have been. */
#include "seam.h"
#include "../../parts/part3_direct/part3.h"

static uint64_t estimator_inputs(const struct render_ctx *ctx, const ray *r, const hit *h, const rng *g)
{
    return seam_hash_rng(seam_hash_hit(seam_hash_ray(seam_hash_ctx(SEAM_HASH_START, ctx), r), h), g);
}

/* The BSDF's value and density, and the three estimators (their generator's state travels with the
 * answer): one line each, see SEAM_FIXED in seam.h. */
SEAM_FIXED(rgb, rgb, bsdf_f, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), seam_hash_bsdf(m, wo, wi), NULL)
SEAM_FIXED(float, float, bsdf_pdf, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), seam_hash_bsdf(m, wo, wi), NULL)
SEAM_FIXED(rgb, rgb, zero_bounce_radiance, (const struct render_ctx *ctx, const ray *r, const hit *h), (ctx, r, h),
           estimator_inputs(ctx, r, h, NULL), NULL)
SEAM_FIXED(rgb, rgb, direct_hemisphere, (const struct render_ctx *ctx, const ray *r, const hit *h, rng *g),
           (ctx, r, h, g), estimator_inputs(ctx, r, h, g), g)
SEAM_FIXED(rgb, rgb, direct_importance, (const struct render_ctx *ctx, const ray *r, const hit *h, rng *g),
           (ctx, r, h, g), estimator_inputs(ctx, r, h, g), g)

/* bsdf_sample_f also fills *wi and *pdf: its answer is the three together (SEAM_SAMPLER). */
SEAM_SAMPLER(bsdf_sample_f, (const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf), (m, wo, u, wi, pdf),
             seam_hash_bsdf_sample(m, wo, &u, wi, pdf))
