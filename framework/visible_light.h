/* Area lights as visible geometry, as CS184's second-assignment framework shows them.
 *
 * Why. A CGL area light is a pure light source: light sampling (light.h) finds it, but no ray can
 * hit it. CS184's first-assignment Cornell boxes therefore hold an emissive quad exactly where the
 * light is, and camera rays, bounce rays and mirrors see that. The course's second-assignment copies
 * of nine boxes comment the quad out, because CS184's 3-2 framework adds two emitting triangles for
 * every area light to the scene's primitives; a loader that did not would render those files with a
 * black light, mirrors that never show it, and no caustics.
 *
 * The rule. An area light over which the scene has no emissive mesh becomes two triangles of its
 * own: its parallelogram, wound and with vertex normals so that their front is the side the light
 * emits towards, under an emitter material (Le = the light's radiance, albedo 0: an emitter reflects
 * nothing, CS184's rule). Emission is one-sided (part 3), so they glow on the light's side only.
 * "Covered" means emissive triangles (Le not black) in the light's plane covering at least
 * VISIBLE_LIGHT_COVERED of its area; which way they face does not matter (a file's own quad, seen
 * from behind, stays the file's choice). A covered light stays as it is, so a file that has its
 * quad (the first assignment's, every scene of pathlab's own) renders exactly as before, with no
 * second emitter in the same place. A partly covered light is made visible too, as CS184 does, and
 * the loader warns: where the file's mesh lies over it, two emitters coincide.
 *
 * No double counting: the triangles are emitters like the file's quads, so every estimator already
 * counts them once. Light sampling finds the light; a shadow ray ends short of it along its normal
 * (spawn.h), so its own triangles never shadow it; a path's later vertices add no emission they
 * land on (part 4); hemisphere sampling (-H) and a mirror's or glass's sample (render.c's
 * one_bounce_radiance) see the triangles' Le instead, as they see a file's quad.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_VISIBLE_LIGHT_H
#define PL_VISIBLE_LIGHT_H

#include "scene.h"
#include <stddef.h>

/* A light counts as covered when emissive triangles lie over this share of its area. Below, it is
 * made visible; above VISIBLE_LIGHT_PARTLY and below this, with a warning. */
#define VISIBLE_LIGHT_COVERED 0.99
#define VISIBLE_LIGHT_PARTLY 0.01

/* Coverage compares every area light with every emissive triangle; a scene with more pairs than
 * this (about a second's work) is not compared, and its lights stay pure light sources (the loader
 * warns). A hostile file may hold a million lights over two million emissive triangles. */
#define VISIBLE_LIGHT_MAX_PAIRS (1L << 27)

/* The share of area light l's parallelogram that emissive triangles of s lie over, among its first
 * num_triangles triangles: the sum over those in l's plane (every corner within a tolerance of it:
 * a thousandth of l's size, more far from the origin) of the area of the triangle clipped to l,
 * over l's area. 0 for a light that is not LIGHT_AREA. Overlapping triangles count twice. */
double visible_light_coverage(const scene *s, const light *l, int num_triangles);

/* Adds light `index` of s (an area light) as visible geometry: one emitter material and two
 * triangles, appended after every other triangle. Returns the first triangle's index, or -1 when
 * the scene cannot grow (nothing added then that the scene does not own and free). */
int visible_light_add(scene *s, int index);

/* The status line of a render of s that made area lights visible (scene.visible_lights > 0),
 * without a newline, into buf; "" when it made none. */
void visible_light_status_line(const scene *s, char *buf, size_t size);

#endif
