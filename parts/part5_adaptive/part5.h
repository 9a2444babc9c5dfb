/* Part 5: adaptive sampling. Handout: handout/part5.md. Test: make test-part5.
 *
 * A pixel stops taking samples once its mean luminance is known well enough: after every batch of
 * B = opts->adaptive_batch samples, with x_i the luminance (rgb_luminance) of sample i,
 *   s1 = sum x_i, s2 = sum x_i^2, mean = s1 / n, var = (s2 - s1^2 / n) / (n - 1),
 *   I = 1.96 sqrt(var / n)        (half-width of the 95% confidence interval of the mean)
 * and it stops when I <= T * mean, T = opts->adaptive_tol; never beyond opts->spp samples.
 * The framework writes the samples each pixel took to <name>_rate.png and the JSON sidecar. */
#ifndef PL_PART5_H
#define PL_PART5_H

#include "../../framework/vec.h"

struct render_ctx;

/* TASK 5.1: the adaptive pixel estimate (-a B T): the mean radiance of the samples taken;
 * *samples_taken receives their count (1 .. opts->spp). */
rgb pixel_estimate_adaptive(const struct render_ctx *ctx, int x, int y, int *samples_taken);

#endif
