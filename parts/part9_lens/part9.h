/* Part 9: a thin lens. Handout: handout/part9.md. Test: make test-part9.
 *
 * A pinhole camera (part 1) sees everything sharp. A real camera gathers light through a lens of
 * some radius, and only the points on one plane, the plane of focus, come out sharp: everything
 * nearer or farther is spread over a disc of confusion, wider the wider the lens. CS184's thin
 * lens, with its two flags:
 *   -b R   the lens radius (camera->lens_radius), in scene units; 0 is a pinhole;
 *   -d D   the focal distance (camera->focal_distance): the plane of focus is the plane z = -D of
 *          camera space, at distance D in front of the camera along its view axis (-Z), not at
 *          distance D along each ray.
 * The lens is the disc of radius R around the camera's position in its local XY plane. The
 * framework's pixel loop asks for a lens ray only when R > 0: it makes the pinhole ray of the
 * sample with part 1's pixel_sample_ray, draws u in [0,1)^2 for the lens and calls thin_lens_ray. */
#ifndef PL_PART9_H
#define PL_PART9_H

#include "../../framework/camera.h"
#include "../../framework/ray.h"

/* TASK 9.1: a point of the unit disc, uniform in area when u is uniform in [0,1)^2. */
vec2 lens_sample_disk(vec2 u);

/* TASK 9.2: the ray of one sample through the thin lens. pinhole is the sample's ray from part 1
 * (from c->position, unit direction); the lens ray starts at the lens point that lens_sample_disk(u)
 * gives (scaled to c->lens_radius, in the camera's local X and Y) and passes through the point
 * where the pinhole ray meets the plane of focus; unit direction; [min_t, max_t] as the pinhole's. */
ray thin_lens_ray(const camera *c, ray pinhole, vec2 u);

#endif
