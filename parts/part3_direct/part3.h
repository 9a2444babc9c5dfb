/* Part 3: direct illumination. Handout: handout/part3.md. Test: make test-part3.
 * Directions wo, wi are in the local shading frame (frame.h: +z is the normal) and point away
 * from the surface. */
#ifndef PL_PART3_H
#define PL_PART3_H

#include "../../framework/scene.h"
#include "../../framework/ray.h"
#include "../../framework/rng.h"

struct render_ctx;

/* TASK 3.1: the diffuse BSDF value f(wo, wi). */
rgb bsdf_f(const material *m, vec3 wo, vec3 wi);
/* TASK 3.2: sample wi for wo with uniform numbers u; returns f(wo, *wi), sets *pdf (solid angle). */
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
/* TASK 3.3: emitted radiance seen along r at h (zero bounces). */
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h);
/* TASK 3.4: direct light by uniform hemisphere sampling (-H). */
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);
/* TASK 3.5: direct light by light importance sampling. */
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);

#endif
