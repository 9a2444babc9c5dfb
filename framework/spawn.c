/* Leaving a surface: hit point error bounds and offset ray origins (spawn.h says why and how). */
#include "spawn.h"
#include <float.h>
#include <math.h>

/* pbrt's gamma(n) = n u / (1 - n u), u = 2^-24: a bound on the relative error of n float
 * operations. */
static inline float gamma_n(int n)
{
    const float u = FLT_EPSILON * 0.5f;
    return ((float)n * u) / (1.0f - (float)n * u);
}

static inline vec3 vec3_abs(vec3 a) { return vec3_make(fabsf(a.x), fabsf(a.y), fabsf(a.z)); }

/* The error bound p_err across the surface of normal ng, with the safety factor: the origin offset
 * of every ray that leaves a hit (a light sample's four shadow rays share it). */
static inline float leave_distance(vec3 ng, vec3 p_err) { return SPAWN_SAFETY * vec3_dot(vec3_abs(ng), p_err); }
static inline void set_leave(hit *h) { h->leave = leave_distance(h->ng, h->p_err); }

/* ---- the hit's point and its error bound (scene_hit_finish calls these) ----------------------- */

tri_frame tri_frame_make(const triangle *t)
{
    /* The blend b0 p0 + b1 p1 + b2 p2 (b0 = 1 - b1 - b2) errs per axis by at most gamma(7) times
     * sum |b_i p_i|, and for a hit inside the triangle (every b_i >= 0, summing to 1 up to a
     * rounding) that sum is at most the largest |p_i| on that axis: gamma(8) of it covers both. */
    vec3 big = vec3_max(vec3_abs(t->p0), vec3_max(vec3_abs(t->p1), vec3_abs(t->p2)));
    /* Moller-Trumbore decides the side of the plane by the triple product (o - p0).(e1 x e2),
     * computed with an error up to a few u |o - p0| |e1| |e2|: across the plane that is
     * u L |e1| |e2| / |e1 x e2|, L the longer edge at p0, which grows as the triangle thins. */
    vec3 e1 = vec3_sub(t->p1, t->p0), e2 = vec3_sub(t->p2, t->p0), cross = vec3_cross(e1, e2);
    float d1 = vec3_dot(e1, e1), d2 = vec3_dot(e2, e2), cc = vec3_dot(cross, cross);
    float edges2 = (d1 > d2 ? d1 : d2) * d1 * d2;  /* (L |e1| |e2|)^2 */
    tri_frame f;
    float test_err;
    if (!(cc > 0.0f)) {  /* degenerate: part 1 should have missed; leave by the triangle's size */
        f.ng = vec3_make(0.0f, 0.0f, 0.0f);
        test_err = sqrtf(d1 + d2);
    } else {
        float inv_cc = 1.0f / cc;
        test_err = gamma_n(8) * sqrtf(edges2 * inv_cc);
        f.ng = vec3_scale(cross, sqrtf(inv_cc));
    }
    f.p_err = vec3_add(vec3_scale(big, gamma_n(8)), vec3_make(test_err, test_err, test_err));
    f.leave = leave_distance(f.ng, f.p_err);
    return f;
}

void hit_refine_triangle(const triangle *t, const tri_frame *f, hit *h)
{
    /* The barycentric blend lies on the triangle's plane for any b1, b2 (up to the rounding
     * tri_frame_make bounds); the rest depends on the triangle alone. */
    float b0 = 1.0f - h->b1 - h->b2;
    vec3 a = vec3_scale(t->p0, b0), b = vec3_scale(t->p1, h->b1), c = vec3_scale(t->p2, h->b2);
    h->p = vec3_add(vec3_add(a, b), c);
    h->p_err = f->p_err;
    h->ng = f->ng;
    h->leave = f->leave;
    if (f->ng.x == 0.0f && f->ng.y == 0.0f && f->ng.z == 0.0f) {
        /* A degenerate triangle has no plane: the shading normal part 1 gave stands in. */
        h->ng = h->n;
        set_leave(h);
    }
}

void hit_refine_sphere(const sphere *s, const ray *r, hit *h)
{
    /* Reproject the ray's point onto the sphere: its error along the surface is harmless, and
     * what is left across it is the rounding of the reprojection. */
    vec3 q = ray_at(r, h->t);
    vec3 local = vec3_sub(q, s->center);
    float len = vec3_length(local);
    if (!(len > 0.0f) || !isfinite(len)) {
        /* No direction to reproject along (a degenerate or wrong t from part 1): keep q with
         * an error bound as large as the sphere, so rays still leave it. */
        h->p = q;
        h->ng = h->n;
        float e = s->radius + fabsf(q.x) + fabsf(q.y) + fabsf(q.z);
        h->p_err = vec3_make(e, e, e);
        set_leave(h);
        return;
    }
    float inv_len = 1.0f / len;
    h->ng = vec3_scale(local, inv_len);
    local = vec3_scale(h->ng, s->radius);
    h->p = vec3_add(s->center, local);
    h->p_err = vec3_add(vec3_scale(vec3_abs(local), gamma_n(5)), vec3_scale(vec3_abs(h->p), gamma_n(2)));
    set_leave(h);
}

/* ---- offset origins ------------------------------------------------------------------------ */

/* h's point moved off its surface by h->leave along ng, on the side of w. */
static inline vec3 offset_point(const hit *h, vec3 w)
{
    /* pbrt then rounds each coordinate one float away from p. Here the safety factor covers that
     * rounding instead (at most u |o_i| per axis: a fourteenth of d across the surface), and
     * saves six calls to nextafterf per shadow ray. */
    return vec3_add(h->p, vec3_scale(h->ng, vec3_dot(w, h->ng) < 0.0f ? -h->leave : h->leave));
}

ray spawn_ray(const ray *from, const hit *h, vec3 w)
{
    ray r = ray_make(offset_point(h, w), w, FLT_MIN, INFINITY);
    r.depth = from->depth + 1;
    return r;
}

/* ---- towards a light sample -------------------------------------------------------------- */

/* How far the far end moves off an area light, along its normal: a bound on what can put the
 * sampled point y (ls->point) on the wrong side of the emissive quad that sits where the light is.
 * Across the light's plane, per axis: the rounding of y = position + u edge_u + v edge_v and of the
 * quad's own corners (a few u of |position| + |edge_u| + |edge_v|), and the rounding of the segment
 * as part 1 intersects it near its end (its direction y - o and the test's differences from the
 * quad's corners: a few u of its length, dist). Nothing here depends on where p is: every rounding
 * that involves p is of a difference, y - o or o - corner, whose size is the segment's. Both terms
 * depend on the light alone, so light_make_area computes them once. */
void spawn_light_leave(light *l)
{
    vec3 n = vec3_abs(l->direction);
    vec3 own = vec3_add(vec3_abs(l->position), vec3_add(vec3_abs(l->edge_u), vec3_abs(l->edge_v)));
    l->leave_base = SPAWN_SAFETY * gamma_n(8) * vec3_dot(n, own);
    l->leave_per_m = SPAWN_SAFETY * gamma_n(8) * (n.x + n.y + n.z);
}

/* How far short of a point or spot light at y a shadow ray of length dist ends, along the ray.
 * A point light has no surface of its own, but a scene may put one through it (CS184's CBempty.dae
 * hides its point light inside a non-emissive quad at the same height), and a segment that ends
 * at y meets that surface at t = 1, inside the rounding. Across any surface through y the rounding
 * is bounded as for an area light's quad: a few u of |y| (y and the surface's corners) plus a few
 * u of the segment's length (its direction and part 1's differences). Along the ray that distance
 * grows as 1 / sin of the angle between the ray and the surface, whose orientation the light does
 * not know: divide by SPAWN_GRAZING_SIN, the shallowest angle at which a shadow ray must clear it.
 * Returned as the fraction of the segment to drop, at most half of it (a point all but at the
 * light keeps a segment), and at least 4800 u, so 1 minus it is a float below 1. */
static inline float point_light_leave(vec3 y, float dist)
{
    vec3 a = vec3_abs(y);
    float bound = SPAWN_SAFETY * gamma_n(8) * (a.x + a.y + a.z + 3.0f * dist);
    return fminf(bound / (SPAWN_GRAZING_SIN * dist), 0.5f);
}

ray spawn_ray_to_light(const ray *from, const hit *h, const light *l, const light_sample *ls)
{
    if (!isfinite(ls->dist)) return spawn_ray(from, h, ls->wi);  /* directional, ambient */

    /* The far end: the sampled point itself, moved off an area light's surface towards p (the
     * side it emits to: light_sample_L samples only lights p sees the front of). A point or spot
     * light keeps its position as the far point, and the segment stops short of it instead
     * (max_t below): the ray's direction is then the one it always was, and only an occluder
     * within the margin of the light sees a different verdict. */
    vec3 y = ls->point;
    float max_t = 1.0f;
    if (l->kind == LIGHT_AREA) y = vec3_add(y, vec3_scale(l->direction, l->leave_base + ls->dist * l->leave_per_m));
    else max_t = 1.0f - point_light_leave(y, ls->dist);

    /* The near end as for any ray leaving the surface; the segment runs from one to the other.
     * Unnormalised: t = 1 is the far point, and no square root or division is spent on it. */
    vec3 o = offset_point(h, ls->wi);
    ray r = ray_make(o, vec3_sub(y, o), FLT_MIN, max_t);
    r.depth = from->depth + 1;
    return r;
}
