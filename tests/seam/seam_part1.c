/* Grader machinery: not part of any assignment. Part 1's functions across the split (seam.h):
 * compiled with PL_SEAM_SUBJECT, the wrappers that record them; with PL_SEAM_JUDGE, the functions
 * that replay them. Each call's inputs are hashed by one function both sides share. */
#include "seam.h"
#include "../../parts/part1_raygen/part1.h"


static uint64_t camera_inputs(const camera *c, float x, float y)
{
    float f[] = {x, y};
    return SEAM_HASH(seam_hash_camera(SEAM_HASH_START, c), f);
}

static uint64_t pixel_inputs(const camera *c, int x, int y, int width, int height, vec2 u)
{
    int64_t n[] = {x, y, width, height};
    return SEAM_HASH(SEAM_HASH(seam_hash_camera(SEAM_HASH_START, c), n), u);
}

static uint64_t intersect_inputs(const void *prim, size_t size, const ray *r, const hit *h)
{
    uint64_t k = prim ? seam_hash(SEAM_HASH_START, prim, size) : seam_hash_int(SEAM_HASH_START, -1);
    return seam_hash_int(seam_hash_ray(k, r), h != NULL);
}

static uint64_t shade_inputs(const hit *h) { return seam_hash_hit(SEAM_HASH_START, h); }

_Static_assert(sizeof(triangle) == 19 * 4 && sizeof(sphere) == 5 * 4, "padding in triangle or sphere");

#ifdef PL_SEAM_SUBJECT
ray __real_camera_generate_ray(const camera *c, float x, float y);
bool __real_triangle_intersect(const triangle *tri, ray *r, hit *h);
bool __real_sphere_intersect(const sphere *s, ray *r, hit *h);
ray __real_pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u);
rgb __real_normal_shade(const hit *h);
ray __wrap_camera_generate_ray(const camera *c, float x, float y);
bool __wrap_triangle_intersect(const triangle *tri, ray *r, hit *h);
bool __wrap_sphere_intersect(const sphere *s, ray *r, hit *h);
ray __wrap_pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u);
rgb __wrap_normal_shade(const hit *h);

ray __wrap_camera_generate_ray(const camera *c, float x, float y)
{
    seam_call call;
    uint64_t in = camera_inputs(c, x, y);
    if (!seam_begin(&call)) return __real_camera_generate_ray(c, x, y);
    ray out = __real_camera_generate_ray(c, x, y);
    seam_end(&call, SEAM_CAMERA_GENERATE_RAY, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}

ray __wrap_pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    seam_call call;
    uint64_t in = pixel_inputs(c, x, y, width, height, u);
    if (!seam_begin(&call)) return __real_pixel_sample_ray(c, x, y, width, height, u);
    ray out = __real_pixel_sample_ray(c, x, y, width, height, u);
    seam_end(&call, SEAM_PIXEL_SAMPLE_RAY, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}

bool __wrap_triangle_intersect(const triangle *tri, ray *r, hit *h)
{
    seam_call call;
    uint64_t in = intersect_inputs(tri, sizeof *tri, r, h);
    if (!seam_begin(&call)) return __real_triangle_intersect(tri, r, h);
    bool found = __real_triangle_intersect(tri, r, h);
    seam_end_hit(&call, SEAM_TRIANGLE_INTERSECT, in, found, r, h);
    return found;
}

bool __wrap_sphere_intersect(const sphere *s, ray *r, hit *h)
{
    seam_call call;
    uint64_t in = intersect_inputs(s, sizeof *s, r, h);
    if (!seam_begin(&call)) return __real_sphere_intersect(s, r, h);
    bool found = __real_sphere_intersect(s, r, h);
    seam_end_hit(&call, SEAM_SPHERE_INTERSECT, in, found, r, h);
    return found;
}

rgb __wrap_normal_shade(const hit *h)
{
    seam_call call;
    uint64_t in = shade_inputs(h);
    if (!seam_begin(&call)) return __real_normal_shade(h);
    rgb out = __real_normal_shade(h);
    seam_end(&call, SEAM_NORMAL_SHADE, in, NULL, &out, sizeof out, NULL, NULL, 0);
    return out;
}
#endif

#ifdef PL_SEAM_JUDGE
ray camera_generate_ray(const camera *c, float x, float y)
{
    ray out;
    seam_replay_fixed(SEAM_CAMERA_GENERATE_RAY, camera_inputs(c, x, y), NULL, &out, sizeof out);
    return out;
}

ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    ray out;
    seam_replay_fixed(SEAM_PIXEL_SAMPLE_RAY, pixel_inputs(c, x, y, width, height, u), NULL, &out, sizeof out);
    return out;
}

bool triangle_intersect(const triangle *tri, ray *r, hit *h)
{
    return seam_replay_hit(SEAM_TRIANGLE_INTERSECT, intersect_inputs(tri, sizeof *tri, r, h), r, h);
}

bool sphere_intersect(const sphere *s, ray *r, hit *h)
{
    return seam_replay_hit(SEAM_SPHERE_INTERSECT, intersect_inputs(s, sizeof *s, r, h), r, h);
}

rgb normal_shade(const hit *h)
{
    rgb out;
    seam_replay_fixed(SEAM_NORMAL_SHADE, shade_inputs(h), NULL, &out, sizeof out);
    return out;
}
#endif
