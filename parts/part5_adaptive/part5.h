/* Part 5: adaptive sampling. Handout: handout/part5.md. Test: make test-part5.
 *
 * A pixel stops taking samples once its mean luminance is known well enough. The framework's
 * pixel loop keeps, for the n samples taken so far, with x_i the luminance (rgb_luminance) of
 * sample i, s1 = sum x_i and s2 = sum x_i^2, and after every batch of B = opts->adaptive_batch
 * samples (or at opts->spp, whichever is first) asks adaptive_converged whether to stop:
 *   mean = s1 / n, var = (s2 - s1^2 / n) / (n - 1)   (the sample variance of one x_i)
 *   I = 1.96 sqrt(var / n)      (half-width of the 95% confidence interval of the MEAN)
 * and it stops when I <= T * mean, T = opts->adaptive_tol. The framework writes the samples each
 * pixel took to <name>_rate.png and the JSON sidecar. */
#ifndef PL_PART5_H
#define PL_PART5_H

#include <stdbool.h>

/* TASK 5.1: true when the n samples summarised by s1 and s2 pin the mean luminance down to
 * within tol of itself (the rule above). n = 1 never converges: one sample has no variance. */
bool adaptive_converged(int n, double s1, double s2, float tol);

#endif
