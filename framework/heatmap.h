/* BVH heat map: a picture of how many BVH nodes each camera ray visits, and the per-thread
 * node-visit counter behind it (part 2's traversals feed it through bvh_count_visits). */
#ifndef PL_HEATMAP_H
#define PL_HEATMAP_H

#include <stdint.h>
#include "status.h"

struct render_ctx;

/* Writes a PNG at path colouring each pixel by the BVH nodes its centre ray visited (blue = few,
 * red = the legend's maximum), with a labelled colour bar in a strip under the image.
 * PL_ERR_INVALID when the BVH is not in use or its traversal reports no visits. */
pl_status render_heatmap(const struct render_ctx *ctx, const char *path, pl_diag *diag);

/* BVH nodes visited (boxes tested) on the calling thread since the last call; resets the count. */
uint64_t bvh_take_visits(void);

#endif
