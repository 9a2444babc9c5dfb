/* An environment map: radiance arriving from infinitely far away in every direction, stored as a
 * latitude-longitude (equirectangular) image, read from an OpenEXR file (`-e map.exr`).
 *
 * The mapping is CS184's, so its maps and its renders line up with ours:
 *   theta = acos(d.y)             in [0, pi]:  0 is straight up (world +Y), the top row;
 *   phi   = atan2(-d.z, d.x) + pi in [0, 2 pi]: the column, left to right;
 *   texel (x, y) spans phi in [x, x + 1) * 2 pi / width and theta in [y, y + 1) * pi / height.
 * Radiance is piecewise constant: a direction sees the texel it falls in, with no filtering, so
 * the radiance a sampler returns and the one a ray that leaves the scene sees are the same
 * function, and a texel's share of the sphere is exactly what its solid angle says. (CS184 shows
 * rays the map filtered bilinearly; pathlab keeps the one function, which a sampler's density,
 * constant on each texel, describes exactly, and the graded references show.)
 * Parts may not call: envmap_load, envmap_make_constant, envmap_free, envmap_texel_coords,
 * env_distribution_alloc, env_distribution_free, env_distribution_check (the grader refuses them; the
 * functions marked PL_PART_API are theirs). */
#ifndef PL_ENVMAP_H
#define PL_ENVMAP_H

#include "part_api.h"
#include "status.h"
#include "vec.h"
#include <stddef.h>

/* The maps a render accepts: 8192 texels a side, 2^24 in all (a 4096x2048 HDRI is 2^23). A map is
 * read whole into memory, 12 bytes a texel. */
#define ENVMAP_MAX_SIDE 8192
#define ENVMAP_MAX_TEXELS (1L << 24)

typedef struct envmap {
    int width, height;  /* texels: phi across, theta down */
    rgb *texels;        /* width * height, row-major, row 0 at theta = 0 (owned) */
    char path[512];     /* the file it came from ("" for a map made in code) */
} envmap;

/* Reads a map (exr.h's exr_read_rgb: any single-part scanline RGB file, every value finite; values
 * below 0 read as 0, with a warning). Errors name the file and what was expected. */
pl_status envmap_load(const char *path, envmap *e, pl_diag *diag);
/* A map of width x height texels, every one radiance L (tests, the constant sky). */
pl_status envmap_make_constant(envmap *e, int width, int height, rgb L);
/* Releases the texels and zeroes e. NULL-safe. */
void envmap_free(envmap *e);

/* The angles of direction d (need not be unit): (theta, phi) as above. */
PL_PART_API vec2 envmap_angles(vec3 d);
/* The unit direction of angles (theta, phi): the inverse of envmap_angles. */
PL_PART_API vec3 envmap_direction(float theta, float phi);
/* Where direction d falls on the map, in texels: (x, y) with texel (floor x, floor y) holding it and
 * the fractions saying where within it (envmap_radiance and the trace read it; not clamped). */
vec2 envmap_texel_coords(const envmap *e, vec3 d);
/* The radiance arriving from direction d: the texel d falls in. */
PL_PART_API rgb envmap_radiance(const envmap *e, vec3 d);
/* The texel (x, y) itself; x in [0, width), y in [0, height). */
PL_PART_API rgb envmap_texel(const envmap *e, int x, int y);

/* ---- importance sampling the map: part 8's tables -----------------------------------------------
 * A texel (x, y) is drawn in two steps, each inverting a cumulative distribution (CDF): first its
 * row y from the marginal CDF, then its column x from row y's conditional CDF. The framework
 * allocates the tables (zeroed) and frees them; part 8's env_build_distribution fills them. */
typedef struct env_distribution {
    int width, height;       /* the map's */
    float *marginal_cdf;     /* height + 1 entries: P(row < y); [0] = 0, [height] = 1 */
    float *conditional_cdf;  /* height rows of width + 1 entries: row y's P(column < x | y); each row
                                [0] = 0, [width] = 1 (a row of no weight: any CDF, it is never drawn) */
    bool valid;              /* env_distribution_check found them to be CDFs */
} env_distribution;

pl_status env_distribution_alloc(env_distribution *d, int width, int height);
/* Releases the tables and zeroes d. NULL-safe. */
void env_distribution_free(env_distribution *d);
/* Whether d's tables are CDFs: finite, from 0, never decreasing, ending at 1 (within 1e-5, the
 * rounding of a float sum). Sets d->valid; when they are not, why names the first entry that is
 * not ("conditional_cdf row 3: entry 5 is 0.2, below entry 4's 0.3"). */
bool env_distribution_check(env_distribution *d, char *why, size_t size);

#endif
