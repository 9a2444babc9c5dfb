/* Grader machinery: not part of any assignment. Part 6's functions across the split (seam.h; see
 * seam_part1.c for the pattern). reflect answers with its value; the samplers and refract also fill
 * pointers, so their answer is the value and what they filled together. */
#include "seam.h"
#include "../../parts/part6_specular/part6.h"
#include <string.h>

typedef struct { int32_t ok; vec3 wi; } refract_out;  /* ok as an int: any value read is a valid one */

_Static_assert(sizeof(vec3) == 3 * 4, "padding in vec3");
_Static_assert(sizeof(refract_out) == 4 * 4, "padding in refract_out");

static uint64_t refract_inputs(vec3 wo, float ior, const vec3 *wi)
{
    return seam_hash_int(SEAM_HASH(SEAM_HASH(SEAM_HASH_START, wo), ior), wi != NULL);
}

SEAM_FIXED(vec3, vec3, reflect, (vec3 wo), (wo), SEAM_HASH(SEAM_HASH_START, wo), NULL)

/* The samplers fill *wi and *pdf as well (SEAM_SAMPLER). */
SEAM_SAMPLER(mirror_sample_f, (const material *m, vec3 wo, vec3 *wi, float *pdf), (m, wo, wi, pdf),
             seam_hash_bsdf_sample(m, wo, NULL, wi, pdf))
SEAM_SAMPLER(refraction_sample_f, (const material *m, vec3 wo, vec3 *wi, float *pdf), (m, wo, wi, pdf),
             seam_hash_bsdf_sample(m, wo, NULL, wi, pdf))
SEAM_SAMPLER(glass_sample_f, (const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf), (m, wo, u, wi, pdf),
             seam_hash_bsdf_sample(m, wo, &u, wi, pdf))

/* refract: whether it found a direction, and the direction it left in *wi (the caller's, when not). */
#ifdef PL_SEAM_SUBJECT
bool __real_refract(vec3 wo, float ior, vec3 *wi);
bool __wrap_refract(vec3 wo, float ior, vec3 *wi);

bool __wrap_refract(vec3 wo, float ior, vec3 *wi)
{
    seam_call call;
    uint64_t in = refract_inputs(wo, ior, wi);
    if (!seam_begin(&call)) return __real_refract(wo, ior, wi);
    refract_out out;
    memset(&out, 0, sizeof out);
    out.ok = __real_refract(wo, ior, wi);
    if (wi) out.wi = *wi;
    seam_end(&call, SEAM_refract, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out.ok != 0;
}
#endif

#ifdef PL_SEAM_JUDGE
bool refract(vec3 wo, float ior, vec3 *wi)
{
    refract_out out;
    seam_replay_fixed(SEAM_refract, refract_inputs(wo, ior, wi), NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    return out.ok != 0;
}
#endif
