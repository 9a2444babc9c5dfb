/* Lights for direct illumination: sampling an incident direction at a shading point.
 * Radiance units per kind are in scene.h (light_kind).
 * Parts may not call: light_make_area, light_area_corner, light_add_environment, light_environment_pdf,
 * light_sample_environment (the grader refuses them; the functions marked PL_PART_API are theirs). */
#ifndef PL_LIGHT_H
#define PL_LIGHT_H

#include "part_api.h"

#include <stdbool.h>
#include "scene.h"
#include "status.h"

typedef struct light_sample {
    rgb L;        /* incident radiance arriving at p along -wi (already attenuated for point/spot) */
    vec3 wi;      /* unit direction from p towards the light, world space */
    float dist;   /* distance from p to the sampled point (INFINITY for directional/ambient) */
    vec3 point;   /* the sampled point: on an area light, a point light's position; unused (zero)
                     at infinity. spawn_ray_to_light ends shadow rays there, not at p + wi dist,
                     whose reconstruction would add its own rounding */
    float pdf;    /* solid-angle density of wi; for delta lights 1 (and is_delta true) */
    bool is_delta;/* point, spot, directional: a single direction, sample once */
} light_sample;

/* Samples light l as seen from point p with uniform numbers u in [0,1)^2. Returns false when the
 * light contributes nothing at p (behind a one-sided area light, outside a spot cone, pdf 0). */
PL_PART_API bool light_sample_L(const light *l, vec3 p, vec2 u, light_sample *out);
/* An area light: the parallelogram position +- edge_u / 2 +- edge_v / 2, emitting radiance towards
 * direction (its unit normal on that side), with no attenuation. Every area light is made here, so
 * that its area and spawn_ray_to_light's offset terms are never left for its maker to fill. */
light light_make_area(vec3 position, vec3 edge_u, vec3 edge_v, vec3 direction, rgb radiance);
/* Corner k (0 to 3) of area light l: position - edge_u / 2 - edge_v / 2, plus edge_u when bit 0 of
 * k is set and edge_v when bit 1 is. */
vec3 light_area_corner(const light *l, int k);

/* Makes s->env a light (LIGHT_ENVIRONMENT) with part 8: with uniform (--env-uniform) sampled by
 * task 8.1; otherwise by task 8.4 from the tables task 8.2 builds here, which are checked first
 * (tables that are not CDFs get a warning naming the entry, and the light shines magenta). */
pl_status light_add_environment(scene *s, bool uniform, pl_diag *diag);

/* The density per steradian with which l's sampler draws direction wi (world, unit), where it is
 * the environment map: part 8's env_pdf over the tables, or 1 / (4 pi) under --env-uniform; 0 for
 * other kinds and in a course without part 8. The trace judges part 8's samples by it (the part's
 * own formula, through the framework: trace_internal.h). */
float light_environment_pdf(const light *l, vec3 wi);
/* One sample of environment light l as light_sample_L draws it, with no report to a trace: the
 * trace's own samples of part 8's sampler (trace_density.c). A path of its own, so light_sample_L
 * keeps its one caller and the inlining the render's speed depends on. false for other kinds. */
bool light_sample_environment(const light *l, vec2 u, light_sample *out);

/* True for lights with a single direction (one sample per shading point suffices). */
PL_PART_API bool light_is_delta(const light *l);

#endif
