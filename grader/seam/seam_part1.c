/* Grader machinery: not part of any assignment. Part 1's functions across the split (seam.h):
 * compiled with PL_SEAM_SUBJECT, the wrappers that record them; with PL_SEAM_JUDGE, the functions
 * that replay them, both written by seam.h's macros from one line per function. Each call's inputs
 * are hashed by one function both sides share. */
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

/* Each answers with its value (a ray, a colour) or a hit: see SEAM_FIXED and SEAM_HIT in seam.h. */
SEAM_FIXED(ray, ray, camera_generate_ray, (const camera *c, float x, float y), (c, x, y), camera_inputs(c, x, y), NULL)
SEAM_FIXED(ray, ray, pixel_sample_ray, (const camera *c, int x, int y, int width, int height, vec2 u),
           (c, x, y, width, height, u), pixel_inputs(c, x, y, width, height, u), NULL)
SEAM_HIT(triangle_intersect, (const triangle *tri, ray *r, hit *h), (tri, r, h), intersect_inputs(tri, sizeof *tri, r, h))
SEAM_HIT(sphere_intersect, (const sphere *s, ray *r, hit *h), (s, r, h), intersect_inputs(s, sizeof *s, r, h))
SEAM_FIXED(rgb, rgb, normal_shade, (const hit *h), (h), shade_inputs(h), NULL)
