/* Grader machinery: not part of any assignment. Part 3's functions across the split (seam.h; see
 * seam_part1.c for the pattern). The estimators take a generator: its state after the call travels
 * with the answer, so the test's next draw is the one it would have been. */
#include "seam.h"
#include "../../parts/part3_direct/part3.h"
#include <string.h>

typedef struct { rgb f; vec3 wi; float pdf; } sample_out;

static uint64_t bsdf_inputs(const material *m, vec3 wo, vec3 wi)
{
    return SEAM_HASH(SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo), wi);
}

static uint64_t sample_inputs(const material *m, vec3 wo, vec2 u, const vec3 *wi, const float *pdf)
{
    uint64_t h = SEAM_HASH(SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo), u);
    return seam_hash_int(h, (wi != NULL) * 2 + (pdf != NULL));
}

static uint64_t estimator_inputs(const struct render_ctx *ctx, const ray *r, const hit *h, const rng *g)
{
    return seam_hash_rng(seam_hash_hit(seam_hash_ray(seam_hash_ctx(SEAM_HASH_START, ctx), r), h), g);
}

/* The BSDF's value and density, and the three estimators (their generator's state travels with the
 * answer): one line each, see SEAM_FIXED in seam.h. */
SEAM_FIXED(rgb, rgb, bsdf_f, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), bsdf_inputs(m, wo, wi), NULL)
SEAM_FIXED(float, float, bsdf_pdf, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), bsdf_inputs(m, wo, wi), NULL)
SEAM_FIXED(rgb, rgb, zero_bounce_radiance, (const struct render_ctx *ctx, const ray *r, const hit *h), (ctx, r, h),
           estimator_inputs(ctx, r, h, NULL), NULL)
SEAM_FIXED(rgb, rgb, direct_hemisphere, (const struct render_ctx *ctx, const ray *r, const hit *h, rng *g),
           (ctx, r, h, g), estimator_inputs(ctx, r, h, g), g)
SEAM_FIXED(rgb, rgb, direct_importance, (const struct render_ctx *ctx, const ray *r, const hit *h, rng *g),
           (ctx, r, h, g), estimator_inputs(ctx, r, h, g), g)

/* bsdf_sample_f also fills *wi and *pdf: its answer is the three together (sample_out). */
#ifdef PL_SEAM_SUBJECT
rgb __real_bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
rgb __wrap_bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

rgb __wrap_bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    seam_call call;
    uint64_t in = sample_inputs(m, wo, u, wi, pdf);
    if (!seam_begin(&call)) return __real_bsdf_sample_f(m, wo, u, wi, pdf);
    sample_out out;
    memset(&out, 0, sizeof out);
    out.f = __real_bsdf_sample_f(m, wo, u, wi, pdf);
    if (wi) out.wi = *wi;
    if (pdf) out.pdf = *pdf;
    seam_end(&call, SEAM_bsdf_sample_f, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out.f;
}
#endif

#ifdef PL_SEAM_JUDGE
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    sample_out out;
    seam_replay_fixed(SEAM_bsdf_sample_f, sample_inputs(m, wo, u, wi, pdf), NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    if (pdf) *pdf = out.pdf;
    return out.f;
}
#endif
