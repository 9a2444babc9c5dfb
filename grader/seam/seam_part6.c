/* Grader machinery: not part of any assignment. Part 6's functions across the split (seam.h; see
 * seam_part1.c for the pattern). reflect answers with its value; the samplers and refract also fill
 * pointers, so their answer is the value and what they filled together. */
#include "seam.h"
#include "../../parts/part6_specular/part6.h"
#include <string.h>

typedef struct { rgb f; vec3 wi; float pdf; } sample_out;
typedef struct { int32_t ok; vec3 wi; } refract_out;  /* ok as an int: any value read is a valid one */

_Static_assert(sizeof(vec3) == 3 * 4, "padding in vec3");
_Static_assert(sizeof(sample_out) == 7 * 4, "padding in sample_out");
_Static_assert(sizeof(refract_out) == 4 * 4, "padding in refract_out");

static uint64_t sample_inputs(const material *m, vec3 wo, const vec2 *u, const vec3 *wi, const float *pdf)
{
    uint64_t h = SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo);
    if (u) h = SEAM_HASH(h, *u);
    return seam_hash_int(h, (wi != NULL) * 2 + (pdf != NULL));
}

static uint64_t refract_inputs(vec3 wo, float ior, const vec3 *wi)
{
    return seam_hash_int(SEAM_HASH(SEAM_HASH(SEAM_HASH_START, wo), ior), wi != NULL);
}

SEAM_FIXED(vec3, vec3, reflect, (vec3 wo), (wo), SEAM_HASH(SEAM_HASH_START, wo), NULL)

#ifdef PL_SEAM_SUBJECT
rgb __real_mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);
rgb __real_refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);
rgb __real_glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
bool __real_refract(vec3 wo, float ior, vec3 *wi);
rgb __wrap_mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);
rgb __wrap_refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);
rgb __wrap_glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
bool __wrap_refract(vec3 wo, float ior, vec3 *wi);

static rgb record_sample(seam_fn fn, uint64_t in, seam_call *call, rgb f, const vec3 *wi, const float *pdf)
{
    sample_out out;
    memset(&out, 0, sizeof out);
    out.f = f;
    if (wi) out.wi = *wi;
    if (pdf) out.pdf = *pdf;
    seam_end(call, fn, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return f;
}

rgb __wrap_mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    seam_call call;
    uint64_t in = sample_inputs(m, wo, NULL, wi, pdf);
    if (!seam_begin(&call)) return __real_mirror_sample_f(m, wo, wi, pdf);
    return record_sample(SEAM_mirror_sample_f, in, &call, __real_mirror_sample_f(m, wo, wi, pdf), wi, pdf);
}

rgb __wrap_refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    seam_call call;
    uint64_t in = sample_inputs(m, wo, NULL, wi, pdf);
    if (!seam_begin(&call)) return __real_refraction_sample_f(m, wo, wi, pdf);
    return record_sample(SEAM_refraction_sample_f, in, &call, __real_refraction_sample_f(m, wo, wi, pdf), wi, pdf);
}

rgb __wrap_glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    seam_call call;
    uint64_t in = sample_inputs(m, wo, &u, wi, pdf);
    if (!seam_begin(&call)) return __real_glass_sample_f(m, wo, u, wi, pdf);
    return record_sample(SEAM_glass_sample_f, in, &call, __real_glass_sample_f(m, wo, u, wi, pdf), wi, pdf);
}

/* refract: whether it found a direction, and the direction it left in *wi (the caller's, when not). */
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
static rgb replay_sample(seam_fn fn, uint64_t in, vec3 *wi, float *pdf)
{
    sample_out out;
    seam_replay_fixed(fn, in, NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    if (pdf) *pdf = out.pdf;
    return out.f;
}

rgb mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    return replay_sample(SEAM_mirror_sample_f, sample_inputs(m, wo, NULL, wi, pdf), wi, pdf);
}

rgb refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    return replay_sample(SEAM_refraction_sample_f, sample_inputs(m, wo, NULL, wi, pdf), wi, pdf);
}

rgb glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    return replay_sample(SEAM_glass_sample_f, sample_inputs(m, wo, &u, wi, pdf), wi, pdf);
}

bool refract(vec3 wo, float ior, vec3 *wi)
{
    refract_out out;
    seam_replay_fixed(SEAM_refract, refract_inputs(wo, ior, wi), NULL, &out, sizeof out);
    if (wi) *wi = out.wi;
    return out.ok != 0;
}
#endif
