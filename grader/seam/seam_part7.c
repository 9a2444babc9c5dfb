/* Grader machinery: not part of any assignment. Part 7's functions across the split (seam.h; see
 * seam_part1.c for the pattern). The terms and the BSDF answer with their values; the sampler also
 * fills *wi and *pdf, so its answer is the three together. */
#include "seam.h"
#include "../../parts/part7_microfacet/part7.h"
#include <string.h>

typedef struct { rgb f; vec3 wi; float pdf; } sample_out;

_Static_assert(sizeof(vec3) == 3 * 4 && sizeof(rgb) == 3 * 4, "padding in vec3 or rgb");
_Static_assert(sizeof(sample_out) == 7 * 4, "padding in sample_out");

static uint64_t bsdf_inputs(const material *m, vec3 wo, vec3 wi)
{
    return SEAM_HASH(SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo), wi);
}

static uint64_t sample_inputs(const material *m, vec3 wo, vec2 u, const vec3 *wi, const float *pdf)
{
    uint64_t h = SEAM_HASH(SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo), u);
    return seam_hash_int(h, (wi != NULL) * 2 + (pdf != NULL));
}

static uint64_t d_inputs(float alpha, vec3 h) { return SEAM_HASH(SEAM_HASH(SEAM_HASH_START, alpha), h); }
static uint64_t fresnel_inputs(float c, rgb eta, rgb k) { return SEAM_HASH(SEAM_HASH(SEAM_HASH(SEAM_HASH_START, c), eta), k); }
static uint64_t g_inputs(float alpha, vec3 wo, vec3 wi) { return SEAM_HASH(SEAM_HASH(d_inputs(alpha, wo), wi), alpha); }

SEAM_FIXED(float, float, beckmann_d, (float alpha, vec3 h), (alpha, h), d_inputs(alpha, h), NULL)
SEAM_FIXED(rgb, rgb, fresnel_conductor, (float cos_i, rgb eta, rgb k), (cos_i, eta, k), fresnel_inputs(cos_i, eta, k), NULL)
SEAM_FIXED(float, float, microfacet_g, (float alpha, vec3 wo, vec3 wi), (alpha, wo, wi), g_inputs(alpha, wo, wi), NULL)
SEAM_FIXED(rgb, rgb, microfacet_f, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), bsdf_inputs(m, wo, wi), NULL)
SEAM_FIXED(float, float, microfacet_pdf, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), bsdf_inputs(m, wo, wi), NULL)

#ifdef PL_SEAM_SUBJECT
rgb __real_microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
rgb __wrap_microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

rgb __wrap_microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    seam_call call;
    uint64_t in = sample_inputs(m, wo, u, wi, pdf);
    if (!seam_begin(&call)) return __real_microfacet_sample_f(m, wo, u, wi, pdf);
    sample_out out;
    memset(&out, 0, sizeof out);
    out.f = __real_microfacet_sample_f(m, wo, u, wi, pdf);
    if (wi) out.wi = *wi;
    if (pdf) out.pdf = *pdf;
    seam_end(&call, SEAM_microfacet_sample_f, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out.f;
}
#endif

#ifdef PL_SEAM_JUDGE
rgb microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    sample_out out;
    seam_replay_fixed(SEAM_microfacet_sample_f, sample_inputs(m, wo, u, wi, pdf), NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    if (pdf) *pdf = out.pdf;
    return out.f;
}
#endif
