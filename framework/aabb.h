/* Axis-aligned bounding boxes. An empty box has min = +inf and max = -inf, so any union fixes it.
 * Parts may not call: none of these (every function here is static inline). */
#ifndef PL_AABB_H
#define PL_AABB_H

#include <math.h>
#include "vec.h"

typedef struct { vec3 min, max; } aabb;

static inline aabb aabb_empty(void)
{
    aabb b = {vec3_make(INFINITY, INFINITY, INFINITY), vec3_make(-INFINITY, -INFINITY, -INFINITY)};
    return b;
}
static inline aabb aabb_union(aabb a, aabb b)
{
    aabb u = {vec3_min(a.min, b.min), vec3_max(a.max, b.max)};
    return u;
}
static inline aabb aabb_extend(aabb a, vec3 p)
{
    aabb u = {vec3_min(a.min, p), vec3_max(a.max, p)};
    return u;
}
static inline bool aabb_is_empty(aabb a) { return !(a.min.x <= a.max.x && a.min.y <= a.max.y && a.min.z <= a.max.z); }
static inline vec3 aabb_extent(aabb a) { return vec3_sub(a.max, a.min); }
static inline vec3 aabb_centroid(aabb a) { return vec3_scale(vec3_add(a.min, a.max), 0.5f); }
static inline float aabb_surface_area(aabb a)
{
    if (aabb_is_empty(a)) return 0.0f;
    vec3 e = aabb_extent(a);
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}
/* Index of the longest axis: 0 = x, 1 = y, 2 = z. */
static inline int aabb_max_axis(aabb a)
{
    vec3 e = aabb_extent(a);
    return (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
}
/* True when b lies inside a (inclusive). */
static inline bool aabb_contains(aabb a, aabb b)
{
    return a.min.x <= b.min.x && a.min.y <= b.min.y && a.min.z <= b.min.z &&
           a.max.x >= b.max.x && a.max.y >= b.max.y && a.max.z >= b.max.z;
}

#endif
