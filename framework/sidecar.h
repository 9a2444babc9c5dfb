/* The JSON sidecar written beside every render: how it was made and what it cost. */
#ifndef PL_SIDECAR_H
#define PL_SIDECAR_H

#include "render.h"

typedef struct {
    double load_seconds, build_seconds, write_seconds;  /* phases around the render */
    const render_stats *render;                         /* the pixel loop's figures */
    const int *samples_per_pixel;                       /* per pixel, top row first; NULL to omit */
} sidecar_info;

/* Writes path (atomically) with the command line, seed, resolution, samples, timings, rays, the
 * BVH's shape and the code version; with samples_per_pixel, the per-pixel counts as rows. */
pl_status sidecar_write(const char *path, const render_ctx *ctx, const sidecar_info *info, pl_diag *diag);

/* "out.png" -> "out.json", "out.png" + "_rate" -> "out_rate.png": swaps or inserts before the extension. */
char *path_with_suffix(const char *path, const char *suffix, const char *extension);

#endif
