/* Grader machinery: not part of any assignment. Part 7's functions across the split (seam.h; see
 * seam_part1.c for the pattern). The terms and the BSDF answer with their values; the sampler also
 * fills *wi and *pdf, so its answer is the three together. */
#include "seam.h"
#include "../../parts/part7_microfacet/part7.h"

_Static_assert(sizeof(vec3) == 3 * 4 && sizeof(rgb) == 3 * 4, "padding in vec3 or rgb");

static uint64_t d_inputs(float alpha, vec3 h) { return SEAM_HASH(SEAM_HASH(SEAM_HASH_START, alpha), h); }
static uint64_t fresnel_inputs(float c, rgb eta, rgb k) { return SEAM_HASH(SEAM_HASH(SEAM_HASH(SEAM_HASH_START, c), eta), k); }
static uint64_t g_inputs(float alpha, vec3 wo, vec3 wi) { return SEAM_HASH(SEAM_HASH(d_inputs(alpha, wo), wi), alpha); }

SEAM_FIXED(float, float, beckmann_d, (float alpha, vec3 h), (alpha, h), d_inputs(alpha, h), NULL)
SEAM_FIXED(rgb, rgb, fresnel_conductor, (float cos_i, rgb eta, rgb k), (cos_i, eta, k), fresnel_inputs(cos_i, eta, k), NULL)
SEAM_FIXED(float, float, microfacet_g, (float alpha, vec3 wo, vec3 wi), (alpha, wo, wi), g_inputs(alpha, wo, wi), NULL)
SEAM_FIXED(rgb, rgb, microfacet_f, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), seam_hash_bsdf(m, wo, wi), NULL)
SEAM_FIXED(float, float, microfacet_pdf, (const material *m, vec3 wo, vec3 wi), (m, wo, wi), seam_hash_bsdf(m, wo, wi), NULL)

/* The sampler fills *wi and *pdf as well (SEAM_SAMPLER). */
SEAM_SAMPLER(microfacet_sample_f, (const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf), (m, wo, u, wi, pdf),
             seam_hash_bsdf_sample(m, wo, &u, wi, pdf))
