/* The JSON sidecar written beside every render: how it was made and what it cost.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_SIDECAR_H
#define PL_SIDECAR_H

#include <stdio.h>
#include "render.h"

typedef struct {
    const render_ctx *ctx;                              /* the render */
    double load_seconds, build_seconds;                 /* phases before the render */
    const render_stats *render;                         /* the pixel loop's figures */
    const int *samples_per_pixel;                       /* per pixel, top row first; NULL to omit */
} sidecar_info;

/* Writes the command line, seed, resolution, samples, timings, the work the framework counted (rays
 * traced, BVH node visits, primitive tests: counters.h), the BVH's shape and the code version (and,
 * with samples_per_pixel, the per-pixel counts as rows) as JSON to f. user is a sidecar_info (an
 * output_encode_fn). */
pl_status sidecar_encode(FILE *f, const void *user, pl_diag *diag);

#endif
