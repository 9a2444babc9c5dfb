/* Rays: origin, unit-or-not direction, and the parametric interval [min_t, max_t] a hit must fall in.
 * Intersection routines shrink max_t to the nearest hit found so far, so the interval doubles as
 * the "closest hit so far" of a traversal.
 * Parts may not call: none of these (every function here is static inline). */
#ifndef PL_RAY_H
#define PL_RAY_H

#include "vec.h"

/* CS184's fixed offset for secondary rays. Renders no longer use it to leave a surface (a fixed
 * epsilon fails at grazing angles and at other scales: spawn.h); tests and benchmarks that make
 * up rays of their own still may. */
#define EPS_F 1e-5f

typedef struct {
    vec3 o;       /* origin, world space */
    vec3 d;       /* direction, world space; camera and bounce rays are unit length */
    float min_t;  /* hits with t < min_t are ignored */
    float max_t;  /* hits with t > max_t are ignored; shrunk to the nearest hit found */
    int depth;    /* bounces taken before this ray: 0 for camera rays */
} ray;

static inline ray ray_make(vec3 o, vec3 d, float min_t, float max_t)
{
    ray r = {o, d, min_t, max_t, 0};
    return r;
}
static inline vec3 ray_at(const ray *r, float t) { return vec3_add(r->o, vec3_scale(r->d, t)); }

/* What a ray hit: filled by the intersection routines, read by the shaders. Part 1 fills t, n,
 * b1, b2; the framework the rest (prim and material in scene_prim_intersect, the point, its
 * error bound and transmits in scene_hit_finish, for every hit accel_intersect and render_intersect
 * return). */
typedef struct {
    float t;       /* ray parameter of the hit */
    vec3 n;        /* unit shading normal, world space (interpolated for triangles) */
    float b1, b2;  /* triangle barycentrics of p1 and p2 (p0 has 1 - b1 - b2); 0 for spheres */
    int prim;      /* primitive index in the scene (see scene_prim_count) */
    int material;  /* index into scene.materials */
    vec3 p;        /* the hit point, world space: the barycentric blend on a triangle, the ray's
                      point reprojected onto a sphere (spawn.h) */
    vec3 p_err;    /* per-axis bound on |p - the exact surface point|, world units, widened by the
                      intersection test's own rounding (spawn.h) */
    vec3 ng;       /* unit geometric normal: the face normal (p1 - p0) x (p2 - p0), or outward */
    float leave;   /* how far from p, along ng, a ray leaving the surface starts: p_err across the
                      surface, times a safety factor (spawn.h); once per hit, not per ray */
    int transmits; /* 1 on a surface light passes through (part 6's glass): it has an inside, so
                      shading_frame (frame.h) keeps n as the surface gives it, outward; 0 elsewhere */
} hit;

#endif
