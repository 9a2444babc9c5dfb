/* Part 1, tasks 1.2 and 1.3: ray-triangle and ray-sphere intersection. */
#include "part1.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 1 | TASK 1.2 | triangle_intersect ===========================================
 * Moller-Trumbore ray-triangle intersection (handout/part1.md, section 1.2).
 * In:  tri (vertices p0 p1 p2, vertex normals n0 n1 n2); r (origin, direction, [min_t, max_t]).
 * Out: true on a hit with t in [r->min_t, r->max_t]; then r->max_t = t and h->t = t,
 *      h->b1, h->b2 = barycentrics of p1 and p2, h->n = normalize((1-b1-b2) n0 + b1 n1 + b2 n2).
 *      On a miss, r and h are unchanged.
 * Must: hits on edges and vertices count (b1 >= 0, b2 >= 0, b1 + b2 <= 1); rays parallel to the
 *       triangle's plane miss; a hit farther than r->max_t or nearer than r->min_t is a miss.
 * Test: make test-part1
 * ====================================================================================== */
bool triangle_intersect(const triangle *tri, ray *r, hit *h)
{
    /* BEGIN SOLUTION */
    vec3 e1 = vec3_sub(tri->p1, tri->p0);
    vec3 e2 = vec3_sub(tri->p2, tri->p0);
    vec3 s1 = vec3_cross(r->d, e2);
    float det = vec3_dot(e1, s1);
    if (det == 0.0f) return false;  /* parallel to the plane (or a degenerate triangle) */
    float inv_det = 1.0f / det;

    vec3 s = vec3_sub(r->o, tri->p0);
    float b1 = vec3_dot(s, s1) * inv_det;
    if (!(b1 >= 0.0f && b1 <= 1.0f)) return false;  /* written so that NaN also misses */
    vec3 s2 = vec3_cross(s, e1);
    float b2 = vec3_dot(r->d, s2) * inv_det;
    if (!(b2 >= 0.0f && b1 + b2 <= 1.0f)) return false;

    float t = vec3_dot(e2, s2) * inv_det;
    if (!(t >= r->min_t && t <= r->max_t)) return false;

    r->max_t = t;
    h->t = t;
    h->b1 = b1;
    h->b2 = b2;
    vec3 n = vec3_add(vec3_add(vec3_scale(tri->n0, 1.0f - b1 - b2), vec3_scale(tri->n1, b1)),
                      vec3_scale(tri->n2, b2));
    h->n = vec3_normalize(n);
    return true;
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("1.2", "triangle_intersect"); */
}

/* === PART 1 | TASK 1.3 | sphere_intersect =============================================
 * Ray-sphere intersection (handout/part1.md, section 1.3).
 * In:  s (center, radius); r (origin, direction (any length), [min_t, max_t]).
 * Out: true when a root of |o + t d - center|^2 = radius^2 lies in [r->min_t, r->max_t]; the nearer
 *      such root is taken; then r->max_t = t, h->t = t, h->n = unit outward normal at the hit,
 *      h->b1 = h->b2 = 0. On a miss, r and h are unchanged.
 * Must: from outside, the near root; from inside, the far root; a tangent ray hits once; a sphere
 *       behind the ray misses.
 * Test: make test-part1
 * ====================================================================================== */
bool sphere_intersect(const sphere *s, ray *r, hit *h)
{
    /* BEGIN SOLUTION */
    /* Solve a t^2 + 2 b' t + c = 0 with b' = d.(o - center): the half-b form loses less precision. */
    vec3 oc = vec3_sub(r->o, s->center);
    float a = vec3_dot(r->d, r->d);
    float half_b = vec3_dot(oc, r->d);
    float c = vec3_dot(oc, oc) - s->radius * s->radius;
    float disc = half_b * half_b - a * c;
    if (disc < 0.0f || a == 0.0f) return false;
    float root = sqrtf(disc);
    /* The stable pair of roots: q avoids subtracting nearly equal numbers. */
    float q = -(half_b + copysignf(root, half_b));
    float t0 = q / a, t1 = (q != 0.0f) ? c / q : t0;
    if (t0 > t1) {
        float swap = t0;
        t0 = t1;
        t1 = swap;
    }
    float t = t0;
    if (!(t >= r->min_t && t <= r->max_t)) {
        t = t1;
        if (!(t >= r->min_t && t <= r->max_t)) return false;
    }
    r->max_t = t;
    h->t = t;
    h->b1 = h->b2 = 0.0f;
    h->n = vec3_scale(vec3_sub(ray_at(r, t), s->center), 1.0f / s->radius);
    return true;
    /* END SOLUTION */
    /* STUB: return PL_TODO_FALSE("1.3", "sphere_intersect"); */
}
