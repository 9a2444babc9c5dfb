/* Vectors and colours: small value types passed by copy.
 * vec3 is a point or direction in metres (world or local shading frame: the caller says which);
 * rgb is linear radiance or reflectance per channel. They are distinct types on purpose, so adding
 * a colour to a position does not compile.
 * Parts may not call: none of these (every function here is static inline). */
#ifndef PL_VEC_H
#define PL_VEC_H

#include <math.h>
#include <stdbool.h>

/* pi, and angles: files and flags speak degrees (fields of view, cone angles, <rotate>), the maths
 * radians. */
#define PL_PI 3.14159265358979323846f
/* M_PI, for the double arithmetic of statistics and tests: it is X/Open's, in neither C11 nor POSIX's
 * base, so a strict build's <math.h> (included above) may leave it out. */
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
static inline float deg_to_rad(float degrees) { return degrees * (PL_PI / 180.0f); }
static inline float rad_to_deg(float radians) { return radians * (180.0f / PL_PI); }

typedef struct { float x, y; } vec2;
typedef struct { float x, y, z; } vec3;
typedef struct { float r, g, b; } rgb;

static inline vec2 vec2_make(float x, float y) { vec2 v = {x, y}; return v; }

static inline vec3 vec3_make(float x, float y, float z) { vec3 v = {x, y, z}; return v; }
static inline vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vec3_mul(vec3 a, vec3 b) { return vec3_make(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 vec3_scale(vec3 a, float s) { return vec3_make(a.x * s, a.y * s, a.z * s); }
static inline vec3 vec3_neg(vec3 a) { return vec3_make(-a.x, -a.y, -a.z); }
static inline float vec3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float vec3_length(vec3 a) { return sqrtf(vec3_dot(a, a)); }
/* Returns the zero vector for a zero input rather than NaNs. */
static inline vec3 vec3_normalize(vec3 a)
{
    float len = vec3_length(a);
    return len > 0.0f ? vec3_scale(a, 1.0f / len) : a;
}
/* Per-component minimum and maximum by one comparison each, which compiles to one minss / maxss.
 * fminf / fmaxf would be a library call per component at -O2 (they must skip a NaN), and boxes are
 * grown by these in every BVH build and check; the loaders refuse NaN coordinates. With a NaN,
 * these return b. */
static inline float float_min(float a, float b) { return a < b ? a : b; }
static inline float float_max(float a, float b) { return a > b ? a : b; }
static inline vec3 vec3_min(vec3 a, vec3 b)
{
    return vec3_make(float_min(a.x, b.x), float_min(a.y, b.y), float_min(a.z, b.z));
}
static inline vec3 vec3_max(vec3 a, vec3 b)
{
    return vec3_make(float_max(a.x, b.x), float_max(a.y, b.y), float_max(a.z, b.z));
}
/* Component by axis index: 0 = x, 1 = y, 2 = z. */
static inline float vec3_get(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline bool vec3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
/* Linear interpolation a + t (b - a). */
static inline vec3 vec3_lerp(vec3 a, vec3 b, float t) { return vec3_add(a, vec3_scale(vec3_sub(b, a), t)); }

static inline rgb rgb_make(float r, float g, float b) { rgb c = {r, g, b}; return c; }
static inline rgb rgb_gray(float v) { return rgb_make(v, v, v); }
static inline rgb rgb_add(rgb a, rgb b) { return rgb_make(a.r + b.r, a.g + b.g, a.b + b.b); }
static inline rgb rgb_mul(rgb a, rgb b) { return rgb_make(a.r * b.r, a.g * b.g, a.b * b.b); }
static inline rgb rgb_scale(rgb a, float s) { return rgb_make(a.r * s, a.g * s, a.b * s); }
static inline bool rgb_is_black(rgb a) { return a.r == 0.0f && a.g == 0.0f && a.b == 0.0f; }
static inline float rgb_max(rgb a) { return fmaxf(a.r, fmaxf(a.g, a.b)); }
/* Rec. 709 luminance, the statistic adaptive sampling tests (CS184's Vector3D::illum). */
static inline float rgb_luminance(rgb a) { return 0.2126f * a.r + 0.7152f * a.g + 0.0722f * a.b; }
static inline bool rgb_is_finite(rgb a) { return isfinite(a.r) && isfinite(a.g) && isfinite(a.b); }
/* The colour stubs return, so a missing part is visible in the picture, never silently black. */
static inline rgb rgb_magenta(void) { return rgb_make(1.0f, 0.0f, 1.0f); }

#endif
