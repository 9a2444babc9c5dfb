/* Leaving a surface: the one way a ray starts at a hit (shadow rays, hemisphere rays, bounce rays).
 *
 * Why. A hit point computed in float lies off the exact surface by its rounding error, on either
 * side. A ray started there (with a small min_t such as CS184's EPS_F = 1e-5) hits its own surface
 * again whenever the point landed on the far side and the ray leaves at a grazing angle: it runs
 * err / cos(theta) before it crosses back out. That is shadow acne, and it darkens exactly where
 * light arrives at grazing angles. No fixed epsilon suits every scene: one large enough for a
 * sphere far from the origin eats contact shadows in a small scene.
 *
 * The method, pbrt-v4's (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., 6.8):
 * every hit carries a bound on the error of its point, filled by the framework whatever part 1
 * computed (scene_hit_finish calls hit_refine_triangle / hit_refine_sphere below):
 *   triangle: p = b0 p0 + b1 p1 + b2 p2 with b0 = 1 - b1 - b2, on the triangle's plane however
 *             accurate the barycentrics are; per axis |p - exact| <= gamma(7) sum_i |b_i p_i|
 *             <= gamma(8) max_i |p_i| for a hit inside the triangle, plus gamma(8) L |e1| |e2| /
 *             |e1 x e2| (L the longer edge at p0) for the rounding of part 1's own test
 *             (Moller-Trumbore's triple product), which grows as a triangle thins: a bound that
 *             depends on the triangle alone, so accel_build computes it once (tri_frame);
 *   sphere:   the ray's point q reprojected onto the sphere, p = c + R (q - c) / |q - c|;
 *             per axis |p - exact| <= gamma(5) |p - c| + gamma(2) |p|.
 * (gamma(n) = n u / (1 - n u), u = 2^-24 the unit roundoff.) A ray leaving along w starts at
 *   o = p + d ng,  d = SPAWN_SAFETY * (|ng.x| err.x + |ng.y| err.y + |ng.z| err.z) = h->leave,
 * with ng the unit geometric normal turned to w's side (pbrt then rounds each coordinate one
 * float away from p; the safety factor covers that rounding here), and min_t = FLT_MIN, so
 * t > 0: a root at exactly 0 (the quadratic rounding the origin onto the sphere) is no hit. The
 * origin is on the side the ray leaves to, farther from the surface than any error of p, so the
 * ray cannot meet its own surface near its start: a plane never again, a sphere (convex) only on
 * its far side. The offset scales with the numbers involved,
 * so it works at every size and distance from the origin; no absolute epsilon is involved.
 * tests/framework/test_spawn.c checks it on a million random hits from 1e-3 to 1e3 in size,
 * up to 1e4 from the origin, leaving down to 89.9 degrees from the normal.
 *
 * A ray towards a light sample ends short of the light the same way: the far point is the point
 * the light sampled (light_sample.point), offset along an area light's normal by a bound on its
 * error and on the segment's, so the shadow ray never reaches the emissive quad that sits where
 * the light is; for a point or spot light, the segment ends short of it (max_t < 1) by that bound
 * over the sine of a grazing angle, so a surface through the light (CS184's CBempty.dae hides its point
 * light in a quad) does not shadow it either.
 *
 * Cost. Whatever depends on one triangle or one light alone is computed once: a triangle's normal,
 * error bound and offset when accel_build runs (tri_frame), an area light's offset terms when it is
 * made (light_make_area). A hit on a triangle then costs the blend, a hit on a sphere the
 * reprojection, and a shadow ray two offsets. `make bench-surfaces` measures what that costs a
 * render (bench/RESULTS.md).
 * Parts may not call: tri_frame_make, spawn_light_leave, hit_refine_triangle, hit_refine_sphere (the
 * grader refuses them; the functions marked PL_PART_API are theirs). */
#ifndef PL_SPAWN_H
#define PL_SPAWN_H

#include "part_api.h"
#include "ray.h"
#include "scene.h"
#include "light.h"

/* The offset is this many times the error bound: Moller-Trumbore and the quadratic are not the
 * watertight test pbrt's bound was derived for, so leave room. Measured on the tests' million
 * hits: no self-hit at 1, a few per million at 0.5 (spheres), so 2 is four times the onset. */
#define SPAWN_SAFETY 2.0f

/* A shadow ray towards a point or spot light ends short of it along the segment by the error bound
 * across a surface through the light divided by this sine: such a surface is cleared by every
 * shadow ray that meets it at more than asin(1e-2) = 0.57 degrees (measured on test_spawn.c's
 * 400,000 random lights in quads: none reached it above that angle, 3 between 0.06 and 0.57). What it costs: an occluder within about
 * 1e-4 (|y|_1 + 3 dist) of the light, y its position, is not seen, as pbrt-v4's shadow rays stop
 * 1e-4 of their length short. */
#define SPAWN_GRAZING_SIN 1e-2f

/* A ray leaving the surface of h along w (world space; bounce and hemisphere rays pass a unit
 * vector), on w's side of the surface: origin offset as above, [min_t, max_t] = [FLT_MIN, inf),
 * depth = from->depth + 1 (from is the ray that reached h). */
PL_PART_API ray spawn_ray(const ray *from, const hit *h, vec3 w);

/* A shadow ray from the surface of h towards the light sample ls of light l (ls from
 * light_sample_L(l, hit_point(from, h), ...)). Towards a point, spot or area light it is a segment:
 * d = (far point - origin), not unit length, [min_t, max_t] = [FLT_MIN, max_t], short of the
 * sampled point by a bound on that point's error: towards an area light the far point moves off it
 * along its normal (max_t = 1); towards a point or spot light the far point is the light and
 * max_t < 1 (at least 1/2: SPAWN_GRAZING_SIN above), so that neither the emissive quad at an area
 * light nor a surface through a point light shadows it. For
 * a directional or ambient light it is spawn_ray(from, h, ls->wi). An occluder between the two
 * ends is a hit. */
PL_PART_API ray spawn_ray_to_light(const ray *from, const hit *h, const light *l, const light_sample *ls);

/* What a hit on a triangle takes from the triangle alone: the unit geometric normal, the error
 * bound of any hit point on it, and the offset that bound gives (hit.leave). A degenerate triangle
 * (no area) gets ng = 0 and its size in the bound; its hits take part 1's normal. */
typedef struct tri_frame {
    vec3 ng;
    vec3 p_err;
    float leave;
} tri_frame;
tri_frame tri_frame_make(const triangle *t);

/* Framework-internal: an area light's far-end offset terms, leave_base and leave_per_m (light.h's
 * light_make_area calls it). */
void spawn_light_leave(light *l);

/* Framework-internal: called by scene_hit_finish for the closest hit of a query, so that h->p,
 * h->p_err and h->ng hold whatever part 1 computed. Parts never call them. */
void hit_refine_triangle(const triangle *t, const tri_frame *f, hit *h);
void hit_refine_sphere(const sphere *s, const ray *r, hit *h);

#endif
