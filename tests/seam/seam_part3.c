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

#ifdef PL_SEAM_SUBJECT
rgb __real_bsdf_f(const material *m, vec3 wo, vec3 wi);
float __real_bsdf_pdf(const material *m, vec3 wo, vec3 wi);
rgb __real_bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
rgb __real_zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h);
rgb __real_direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);
rgb __real_direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);
rgb __wrap_bsdf_f(const material *m, vec3 wo, vec3 wi);
float __wrap_bsdf_pdf(const material *m, vec3 wo, vec3 wi);
rgb __wrap_bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
rgb __wrap_zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h);
rgb __wrap_direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);
rgb __wrap_direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);

rgb __wrap_bsdf_f(const material *m, vec3 wo, vec3 wi)
{
    seam_call call;
    uint64_t in = bsdf_inputs(m, wo, wi);
    if (!seam_begin(&call)) return __real_bsdf_f(m, wo, wi);
    rgb out = __real_bsdf_f(m, wo, wi);
    seam_end(&call, SEAM_BSDF_F, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}

float __wrap_bsdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    seam_call call;
    uint64_t in = bsdf_inputs(m, wo, wi);
    if (!seam_begin(&call)) return __real_bsdf_pdf(m, wo, wi);
    float out = __real_bsdf_pdf(m, wo, wi);
    seam_end(&call, SEAM_BSDF_PDF, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}

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
    seam_end(&call, SEAM_BSDF_SAMPLE_F, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out.f;
}

rgb __wrap_zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h)
{
    seam_call call;
    uint64_t in = estimator_inputs(ctx, r, h, NULL);
    if (!seam_begin(&call)) return __real_zero_bounce_radiance(ctx, r, h);
    rgb out = __real_zero_bounce_radiance(ctx, r, h);
    seam_end(&call, SEAM_ZERO_BOUNCE_RADIANCE, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}

rgb __wrap_direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    seam_call call;
    uint64_t in = estimator_inputs(ctx, r, h, g);
    if (!seam_begin(&call)) return __real_direct_hemisphere(ctx, r, h, g);
    rgb out = __real_direct_hemisphere(ctx, r, h, g);
    seam_end(&call, SEAM_DIRECT_HEMISPHERE, in, g, &out, sizeof out, NULL, NULL, 0);
    return out;
}

rgb __wrap_direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    seam_call call;
    uint64_t in = estimator_inputs(ctx, r, h, g);
    if (!seam_begin(&call)) return __real_direct_importance(ctx, r, h, g);
    rgb out = __real_direct_importance(ctx, r, h, g);
    seam_end(&call, SEAM_DIRECT_IMPORTANCE, in, g, &out, sizeof out, NULL, NULL, 0);
    return out;
}
#endif

#ifdef PL_SEAM_JUDGE
rgb bsdf_f(const material *m, vec3 wo, vec3 wi)
{
    rgb out;
    seam_replay_fixed(SEAM_BSDF_F, bsdf_inputs(m, wo, wi), NULL, &out, sizeof out);
    return out;
}

float bsdf_pdf(const material *m, vec3 wo, vec3 wi)
{
    float out;
    seam_replay_fixed(SEAM_BSDF_PDF, bsdf_inputs(m, wo, wi), NULL, &out, sizeof out);
    return out;
}

rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    sample_out out;
    seam_replay_fixed(SEAM_BSDF_SAMPLE_F, sample_inputs(m, wo, u, wi, pdf), NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    if (pdf) *pdf = out.pdf;
    return out.f;
}

rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h)
{
    rgb out;
    seam_replay_fixed(SEAM_ZERO_BOUNCE_RADIANCE, estimator_inputs(ctx, r, h, NULL), NULL, &out, sizeof out);
    return out;
}

rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    rgb out;
    seam_replay_fixed(SEAM_DIRECT_HEMISPHERE, estimator_inputs(ctx, r, h, g), g, &out, sizeof out);
    return out;
}

rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    rgb out;
    seam_replay_fixed(SEAM_DIRECT_IMPORTANCE, estimator_inputs(ctx, r, h, g), g, &out, sizeof out);
    return out;
}
#endif
