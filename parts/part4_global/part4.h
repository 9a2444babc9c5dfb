/* Part 4: global illumination. Handout: handout/part4.md. Test: make test-part4. */
#ifndef PL_PART4_H
#define PL_PART4_H

#include "../../framework/scene.h"
#include "../../framework/ray.h"
#include "../../framework/rng.h"

struct render_ctx;

/* TASK 4.1: radiance reflected at h after at least one bounce, up to opts->max_depth. */
rgb at_least_one_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);

#endif
