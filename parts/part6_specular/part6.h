/* Part 6: mirror and glass. Handout: handout/part6.md. Test: make test-part6.
 *
 * CS184's perfect mirror (<mirror>), its glass (<glass>: reflects and refracts, Schlick's
 * approximation choosing between them) and its refraction-only material (<refraction>). Each
 * sends light into one direction (two for glass), so each BSDF is a delta: the framework's
 * material_f and material_pdf say 0 for every pair of directions, and light reaches these
 * surfaces only through the sample_f functions below (framework/material.h says how the framework
 * lights a vertex with a delta BSDF: it follows that sample).
 *
 * Conventions (the tests rely on them):
 * - Directions are in the local shading frame, +z the normal, pointing AWAY from the surface: wo
 *   towards the viewer, wi towards where the light comes from.
 * - A mirror's frame faces the viewer (wo.z > 0). Glass keeps its outward normal: wo.z > 0 is a
 *   ray arriving from outside, wo.z < 0 one from inside (hit.transmits, framework/frame.h). The
 *   index of refraction is m->ior inside and 1 outside.
 * - A sample returns f = weight / |cos_theta(wi)| and sets *pdf to the probability of the branch
 *   it took (1 when there is one), so that f |cos_theta(wi)| / pdf is the weight by which the
 *   path's throughput is multiplied: m->reflectance for a reflection, m->transmittance (times the
 *   radiance scale, handout/part6.md, 6.4) for a refraction. A black f or a zero pdf: no light. */
#ifndef PL_PART6_H
#define PL_PART6_H

#include "../../framework/scene.h"
#include "../../framework/frame.h"

/* TASK 6.1: wo reflected about the normal (+z): the mirror direction, unit when wo is. */
vec3 reflect(vec3 wo);

/* TASK 6.2: a perfect mirror's sample: wi = reflect(wo), *pdf = 1, f = m->reflectance / |cos wi|. */
rgb mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);

/* TASK 6.3: wo refracted through the surface by Snell's law, into *wi (unit, on the other side of
 * the surface), for a material of index ior inside and 1 outside; false under total internal
 * reflection (no refracted direction; *wi is then left as it was). */
bool refract(vec3 wo, float ior, vec3 *wi);

/* TASK 6.4: a refraction-only sample: *wi = the refracted direction, *pdf = 1,
 * f = m->transmittance times the radiance scale / |cos wi|; black with *pdf = 0 under total
 * internal reflection. */
rgb refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf);

/* TASK 6.5: glass: reflects with Schlick's probability R, refracts otherwise (u.x decides), and
 * reflects always under total internal reflection; f and *pdf those of the branch taken, each
 * times the branch's probability. */
rgb glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

#endif
