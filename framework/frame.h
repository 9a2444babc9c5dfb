/* Local shading frames. At a hit, BSDFs work in a frame where the normal is +z, so cos(theta) is
 * just w.z. frame_from_normal builds an orthonormal basis (Duff et al. 2017, "Building an
 * Orthonormal Basis, Revisited"), continuous everywhere but at n = (0, 0, -1).
 * Parts may not call: none of these (every function here is static inline). */
#ifndef PL_FRAME_H
#define PL_FRAME_H

#include "vec.h"
#include "ray.h"

typedef struct { vec3 s, t, n; } frame;  /* tangent, bitangent, normal: a right-handed basis */

static inline frame frame_from_normal(vec3 n)
{
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    frame f;
    f.s = vec3_make(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = vec3_make(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}
/* World direction -> local (z along the normal). */
static inline vec3 frame_to_local(const frame *f, vec3 w)
{
    return vec3_make(vec3_dot(w, f->s), vec3_dot(w, f->t), vec3_dot(w, f->n));
}
/* Local direction -> world. */
static inline vec3 frame_to_world(const frame *f, vec3 w)
{
    return vec3_add(vec3_add(vec3_scale(f->s, w.x), vec3_scale(f->t, w.y)), vec3_scale(f->n, w.z));
}
static inline float cos_theta(vec3 w_local) { return w_local.z; }
static inline float abs_cos_theta(vec3 w_local) { return fabsf(w_local.z); }

/* ---- Shading at a hit (parts 3 and 4 use both) ------------------------------------------------ */

/* The world-space hit point of r at h: the framework's h->p (spawn.h), on the surface within
 * h->p_err. Rays leave it through spawn.h, never from this point itself. */
static inline vec3 hit_point(const ray *r, const hit *h) { (void)r; return h->p; }

/* The shading frame at h, its normal turned to face the ray's origin, so that
 * wo = frame_to_local(&f, -r->d) always has wo.z >= 0: diffuse reflection is two-sided, and so is
 * a mirror. Glass is not: light that enters it bends one way and light that leaves it the other,
 * so on a surface that transmits (h->transmits) the normal stays outward, as the surface gives it,
 * and wo.z < 0 says the ray came from inside. */
static inline frame shading_frame(const ray *r, const hit *h)
{
    vec3 n = h->n;
    if (!h->transmits && vec3_dot(n, r->d) > 0.0f) n = vec3_neg(n);
    return frame_from_normal(n);
}

#endif
