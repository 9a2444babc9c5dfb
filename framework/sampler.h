/* Samplers: pure functions from uniform numbers in [0,1)^2 to directions or points, each with a
 * pdf twin that returns the density of the same distribution (per steradian for directions, per
 * unit area for points). Directions are in the local shading frame, where +z is the normal.
 * Parts may not call: none of these (every function here is marked PL_PART_API). */
#ifndef PL_SAMPLER_H
#define PL_SAMPLER_H

#include "part_api.h"

#include "vec.h"

#define PL_INV_PI 0.31830988618379067154f
#define PL_INV_2PI 0.15915494309189533577f

/* Uniform over the hemisphere z >= 0: pdf 1 / (2 pi). */
PL_PART_API vec3 sample_uniform_hemisphere(vec2 u);
PL_PART_API float sample_uniform_hemisphere_pdf(vec3 w);

/* Cosine-weighted over the hemisphere z >= 0: pdf cos(theta) / pi. */
PL_PART_API vec3 sample_cosine_hemisphere(vec2 u);
PL_PART_API float sample_cosine_hemisphere_pdf(vec3 w);

/* Uniform over the unit sphere: pdf 1 / (4 pi). */
PL_PART_API vec3 sample_uniform_sphere(vec2 u);
PL_PART_API float sample_uniform_sphere_pdf(vec3 w);

/* Uniform over the unit disk (concentric map): pdf 1 / pi. */
PL_PART_API vec2 sample_uniform_disk(vec2 u);
PL_PART_API float sample_uniform_disk_pdf(vec2 p);

/* Uniform barycentrics (b1, b2) over a triangle: pdf 2 in barycentric space (1 / area in world). */
PL_PART_API vec2 sample_uniform_triangle(vec2 u);

#endif
