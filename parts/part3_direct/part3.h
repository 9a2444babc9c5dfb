/* Part 3: direct illumination. Handout: handout/part3.md. Test: make test-part3.
 *
 * Conventions (the tests rely on them):
 * - BSDF directions wo, wi are in the local shading frame (frame.h: +z is the normal) and point
 *   AWAY from the surface: wo towards the viewer, wi towards the light.
 * - Every material shades as Lambertian diffuse with reflectance m->albedo; emission m->Le is
 *   one-sided: a surface emits towards the side its normal h->n points to (like the area lights).
 * - The estimators (3.4, 3.5) evaluate f with material_f (framework/material.h), which calls your
 *   bsdf_f for every material of parts 1-5 (and a later part's BSDF for a kind of its own).
 * - Diffuse reflection is two-sided: shading_frame (frame.h) turns the normal towards the viewer.
 * - Secondary rays (hemisphere and shadow rays) leave the surface through framework/spawn.h
 *   (spawn_ray, spawn_ray_to_light), never from the raw hit point: see handout/part3.md, 3.4.
 * - A radiance estimate is never NaN, Inf or negative: the tests fail naming the sample if it is. */
#ifndef PL_PART3_H
#define PL_PART3_H

#include "../../framework/scene.h"
#include "../../framework/frame.h"
#include "../../framework/ray.h"
#include "../../framework/rng.h"
#include "../../framework/spawn.h"

struct render_ctx;

/* TASK 3.1: the diffuse BSDF value f(wo, wi) (1/sr); zero unless wo and wi are above the surface. */
rgb bsdf_f(const material *m, vec3 wo, vec3 wi);
/* TASK 3.2: the density (per steradian) with which bsdf_sample_f picks wi, the pdf twin. */
float bsdf_pdf(const material *m, vec3 wo, vec3 wi);
/* TASK 3.2: samples wi for wo from uniform numbers u; returns f(wo, *wi) and sets *pdf to
 * bsdf_pdf(m, wo, *wi). */
rgb bsdf_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);
/* TASK 3.3: the radiance emitted towards the ray's origin by the surface r hit at h. */
rgb zero_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h);
/* TASK 3.4: radiance reflected at h towards r's origin, lit directly by emitting geometry, by
 * uniform hemisphere sampling (-H): num_lights * render_light_samples(ctx, r) directions, at least
 * one. */
rgb direct_hemisphere(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);
/* TASK 3.5: the same by light importance sampling: render_light_samples(ctx, r) samples per area
 * (and ambient) light, one per point, spot or directional light, each checked with a shadow ray. */
rgb direct_importance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);

#endif
