/* BVH heat map: a picture of how many BVH nodes each camera ray visits, read from the framework's
 * node-visit counter (counted in bvh_visit: counters.h).
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_HEATMAP_H
#define PL_HEATMAP_H

#include <stdint.h>
#include <stdio.h>
#include "status.h"

struct render_ctx;

/* The picture, legend strip included: 8-bit RGB, top row first (owned). */
typedef struct {
    uint8_t *rgb8;
    int width, height;  /* height: the image's plus the legend strip */
} heatmap;

/* Draws the heat map into out (free with heatmap_free); path only names it in messages. The errors
 * are render_heatmap's. */
pl_status heatmap_render(const struct render_ctx *ctx, const char *path, heatmap *out, pl_diag *diag);
/* Its PNG's bytes to f (user is a const heatmap *): the output module's encoder type. */
pl_status heatmap_encode(FILE *f, const void *user, pl_diag *diag);
void heatmap_free(heatmap *map);  /* NULL-safe */

/* heatmap_render written at path as a PNG on its own (tests, tools; a render's heat map goes out
 * with its other files through output.h): each pixel coloured by the BVH nodes its centre ray
 * visited (blue = few, red = the legend's maximum), with a labelled colour bar in a strip under the image.
 * PL_ERR_INVALID when the BVH is not in use or its traversal reports no visits. */
pl_status render_heatmap(const struct render_ctx *ctx, const char *path, pl_diag *diag);

#endif
