/* BVH heat map: a picture of how many BVH nodes each camera ray visits, read from the framework's
 * node-visit counter (counted in bvh_visit: counters.h). */
#ifndef PL_HEATMAP_H
#define PL_HEATMAP_H

#include "status.h"

struct render_ctx;

/* Writes a PNG at path colouring each pixel by the BVH nodes its centre ray visited (blue = few,
 * red = the legend's maximum), with a labelled colour bar in a strip under the image.
 * PL_ERR_INVALID when the BVH is not in use or its traversal reports no visits. */
pl_status render_heatmap(const struct render_ctx *ctx, const char *path, pl_diag *diag);

#endif
