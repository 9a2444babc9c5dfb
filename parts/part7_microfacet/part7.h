/* Part 7: microfacet conductors. Handout: handout/part7.md. Test: make test-part7.
 *
 * CS184's <microfacet> material: a metal whose surface is a field of tiny mirrors (microfacets)
 * tilted at random, with the Beckmann distribution of roughness alpha, reflecting by the
 * conductor's Fresnel term of its complex index of refraction eta + i k (per channel, m->eta and
 * m->k). Its BSDF (Cook and Torrance; Walter et al. 2007):
 *   f(wo, wi) = F(wi . h) G(wo, wi) D(h) / (4 cos_theta(wo) cos_theta(wi)),  h = normalize(wo + wi)
 * with D the distribution of the microfacets' normals, F the fraction a microfacet reflects and G the
 * fraction of microfacets neither hidden from wo nor shadowed from wi. Unlike part 6's mirror it is
 * no delta: material_f and material_pdf call microfacet_f and microfacet_pdf, so part 3's light
 * sampling lights it, and part 4's paths bounce off it by microfacet_sample_f.
 *
 * Conventions (the tests rely on them): directions in the local shading frame (frame.h: +z the
 * normal, which faces the viewer), unit, pointing away from the surface; a conductor reflects
 * only: f and pdf are 0 unless both wo and wi are above the surface (z > 0). */
#ifndef PL_PART7_H
#define PL_PART7_H

#include "../../framework/scene.h"
#include "../../framework/frame.h"

/* TASK 7.1: the Beckmann distribution of microfacet normals, D(h) for a unit h (local frame) and
 * roughness alpha > 0, per steradian; normalised so that the integral of D(h) cos_theta(h) over
 * the hemisphere is 1. 0 for h.z <= 0. */
float beckmann_d(float alpha, vec3 h);

/* TASK 7.2: the Fresnel reflectance of a conductor of index eta + i k (per channel) for light
 * meeting it at angle theta with cos_theta = cos_i in [0, 1], from air. */
rgb fresnel_conductor(float cos_i, rgb eta, rgb k);

/* TASK 7.3: Smith's shadowing-masking term for the Beckmann distribution,
 * G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi)), in [0, 1]. */
float microfacet_g(float alpha, vec3 wo, vec3 wi);

/* TASK 7.4: the BSDF value f(wo, wi) of microfacet material m (1/sr): m->alpha, m->eta, m->k. */
rgb microfacet_f(const material *m, vec3 wo, vec3 wi);

/* TASK 7.5: the density (per steradian of wi) with which microfacet_sample_f picks wi for wo. */
float microfacet_pdf(const material *m, vec3 wo, vec3 wi);

/* TASK 7.6: samples a microfacet normal h from D(h) cos_theta(h) with u, reflects wo about it into
 * *wi; returns microfacet_f(m, wo, *wi) and sets *pdf = microfacet_pdf(m, wo, *wi); black with
 * *pdf = 0 where the reflected direction falls below the surface. */
rgb microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

#endif
