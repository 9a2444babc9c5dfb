/* Part 1: ray generation and ray-scene intersection.
 * Handout: handout/part1.md. Test: make test-part1.
 *
 * Conventions (the tests rely on them):
 * - Film coordinates (x, y) in [0,1]^2 have (0, 0) at the bottom-left of the image.
 * - The camera looks down its local -Z with +Y up; the sensor is the plane z = -1 in camera
 *   space, spanning [-tan(hfov/2), tan(hfov/2)] x [-tan(vfov/2), tan(vfov/2)].
 * - An intersection routine reports a hit only for t in [r->min_t, r->max_t]; on a hit it sets
 *   r->max_t = t, so the next primitive must be nearer to count. On a miss it changes nothing. */
#ifndef PL_PART1_H
#define PL_PART1_H

#include <stdbool.h>
#include "../../framework/scene.h"
#include "../../framework/ray.h"

/* TASK 1.1: the camera ray through film point (x, y); unit direction; [min_t, max_t] = [znear, zfar]. */
ray camera_generate_ray(const camera *c, float x, float y);

/* TASK 1.2: Moller-Trumbore. On a hit: h->t, h->n (barycentric blend of the vertex normals,
 * normalised), h->b1, h->b2. Rays parallel to the plane miss. */
bool triangle_intersect(const triangle *tri, ray *r, hit *h);

/* TASK 1.3: the nearest root of |o + t d - c|^2 = R^2 inside [min_t, max_t]; h->n points outwards. */
bool sphere_intersect(const sphere *s, ray *r, hit *h);

/* TASK 1.4: the camera ray of one sample of pixel (x, y): through film point
 * ((x + u.x) / width, (y + u.y) / height), u in [0,1)^2 drawn by the framework's pixel loop. */
ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u);

/* Worked example (complete): a colour for the surface normal, n * 0.5 + 0.5 per channel. */
rgb normal_shade(const hit *h);

#endif
