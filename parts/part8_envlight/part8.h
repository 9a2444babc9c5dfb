/* Part 8: the environment light. Handout: handout/part8.md. Test: make test-part8.
 *
 * `-e map.exr` surrounds the scene with a latitude-longitude image of radiance arriving from far
 * away in every direction (framework/envmap.h: the map, its texels and CS184's mapping between a
 * direction and its angles theta, phi). The framework shows it where camera rays leave the scene;
 * this part makes it a light. Part 3's direct_importance samples it like any other light, through
 * light_sample_L, which asks this part for one incident direction wi, its radiance and its density
 * pdf (per steradian); there is no shadow-ray end: the light is at infinity.
 *
 * Two ways to pick wi, two renders that agree on average:
 *   --env-uniform   every direction of the sphere alike (task 8.1): simple, but a small bright sun
 *                   is found by few samples, and the image is speckled;
 *   (default)       in proportion to the map's brightness (tasks 8.2-8.4): a texel is drawn with
 *                   probability proportional to its luminance times sin(theta), then a point within
 *                   it; the density per steradian carries the Jacobian of the mapping,
 *                   dw = sin(theta) dtheta dphi = sin(theta) (pi / height) (2 pi / width) per texel. */
#ifndef PL_PART8_H
#define PL_PART8_H

#include "../../framework/envmap.h"

/* TASK 8.1: a direction uniform over the sphere: sets *wi (unit) and *pdf (per steradian), and
 * returns the map's radiance arriving from *wi. */
rgb env_sample_uniform(const envmap *e, vec2 u, vec3 *wi, float *pdf);

/* TASK 8.2: fills d's marginal and conditional CDFs (envmap.h) for drawing texel (x, y) with
 * probability proportional to its luminance times the sine of its row's polar angle. */
void env_build_distribution(const envmap *e, env_distribution *d);

/* TASK 8.3: the density per steradian with which env_sample_importance picks direction wi. */
float env_pdf(const envmap *e, const env_distribution *d, vec3 wi);

/* TASK 8.4: draws a texel from d's CDFs with u.y (the row) and u.x (the column), and a point within
 * it from what is left of each number; sets *wi (unit) and *pdf = env_pdf(e, d, *wi), and returns
 * the texel's radiance. */
rgb env_sample_importance(const envmap *e, const env_distribution *d, vec2 u, vec3 *wi, float *pdf);

#endif
