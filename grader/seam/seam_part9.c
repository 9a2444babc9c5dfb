/* Grader machinery: not part of any assignment. Part 9's functions across the split (seam.h; see
 * seam_part1.c for the pattern). */
#include "seam.h"
#include "../../parts/part9_lens/part9.h"

static uint64_t disk_inputs(vec2 u) { return SEAM_HASH(SEAM_HASH_START, u); }

static uint64_t lens_inputs(const camera *c, ray pinhole, vec2 u)
{
    return SEAM_HASH(seam_hash_ray(seam_hash_camera(SEAM_HASH_START, c), &pinhole), u);
}

_Static_assert(sizeof(vec2) == 2 * 4, "padding in vec2");

/* Each answers with its value: a point of the disc, a ray. */
SEAM_FIXED(vec2, vec2, lens_sample_disk, (vec2 u), (u), disk_inputs(u), NULL)
SEAM_FIXED(ray, ray, thin_lens_ray, (const camera *c, ray pinhole, vec2 u), (c, pinhole, u), lens_inputs(c, pinhole, u), NULL)
