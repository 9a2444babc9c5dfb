/* The BSDF of a material, whatever its kind: the one place that chooses whose code shades it.
 *
 * Why. Part 3 writes the diffuse BSDF (bsdf_f, bsdf_pdf, bsdf_sample_f); the second assignment
 * adds other kinds (CS184's mirror and glass in part 6, its microfacet metal in part 7). Parts 3
 * and 4 light and bounce off every surface through these three functions, never through one
 * kind's own, so a course that adds a kind changes no earlier part: this file learns the new
 * kind, and every light sample and every bounce of parts 3 and 4 sees it.
 *
 * Part 6 shades CS184's mirror, glass and refraction-only materials, and part 7 its microfacet
 * metal, where the course has them. A kind the course has no part for stands in as diffuse with its
 * colour (scene.h's material.albedo, with one warning when the scene loads).
 *
 * Delta BSDFs. A mirror or glass reflects or bends light into one direction only: its f is a
 * Dirac delta, which no function of (wo, wi) can be. So material_f and material_pdf say 0 for
 * every pair of directions (a light sample never lands on that one direction), and only
 * material_sample_f finds it: it returns f = weight / |cos_theta(wi)| with a pdf that is the
 * probability of the branch it took (1 for a mirror), so that f |cos| / pdf is the weight the
 * path's throughput takes. The framework lights such a vertex by following that sample
 * (render.c, one_bounce_radiance), since light sampling cannot.
 *
 * Conventions (part 3's, for every kind): directions wo and wi are unit vectors in the local
 * shading frame (frame.h: +z the shading normal), pointing away from the surface. f and pdf are
 * per steradian. A sampled direction may lie below the surface (cos_theta(wi) < 0: light passing
 * through glass), so whoever folds a sample into a path's throughput weighs it by
 * |cos_theta(wi)|.
 * Parts may not call: material_is_delta, material_has_inside, material_kind_shaded (the grader refuses
 * them; the functions marked PL_PART_API are theirs). */
#ifndef PL_MATERIAL_H
#define PL_MATERIAL_H

#include "part_api.h"
#include "scene.h"

/* The BSDF value f(wo, wi) of material m (1/sr). */
PL_PART_API rgb material_f(const material *m, vec3 wo, vec3 wi);
/* The density (per steradian) with which material_sample_f picks wi for wo. */
PL_PART_API float material_pdf(const material *m, vec3 wo, vec3 wi);
/* Samples wi for wo from uniform numbers u in [0,1)^2; returns f(wo, *wi) and sets *pdf to its
 * density. A zero *pdf or a black f means no direction was found: the path ends there. */
PL_PART_API rgb material_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

/* True where m's BSDF is a delta (part 6's mirror, glass and refraction, in a course with part 6):
 * material_f and material_pdf are 0 there, and light comes only through material_sample_f. */
bool material_is_delta(const material *m);
/* True where light passes through m into an inside (glass, refraction): hits on it keep their
 * outward normal in the shading frame (hit.transmits, frame.h). */
bool material_has_inside(const material *m);
/* True where the course has a part that shades kind k (diffuse always): the loader warns about
 * the other kinds, which stand in as diffuse. */
bool material_kind_shaded(material_kind k);

#endif
