/* Part 5: adaptive sampling. Handout: handout/part5.md. Test: make test-part5. */
#ifndef PL_PART5_H
#define PL_PART5_H

#include "../../framework/vec.h"

struct render_ctx;

/* TASK 5.1: the adaptive pixel estimate (-a B T); *samples_taken receives the count. */
rgb pixel_estimate_adaptive(const struct render_ctx *ctx, int x, int y, int *samples_taken);

#endif
