/* Test machinery: not part of any assignment.
 * Direction samplers against their pdfs: a histogram over (cos theta, phi) cells compared with the
 * pdf integrated over each cell by Pearson's chi-square test; on failure, the table of rows and a
 * PNG picture of observed, expected and residual counts (histogram_png.h). Used by the framework's
 * hemisphere samplers and by part 3's BSDF sampler. */
#ifndef PL_DIR_CHECK_H
#define PL_DIR_CHECK_H

#include <stdint.h>
#include "../../framework/vec.h"

#define DIR_BINS_Z 10     /* cos(theta) in [0, 1] */
#define DIR_BINS_PHI 20   /* phi in [0, 2 pi) */
#define DIR_BINS (DIR_BINS_Z * DIR_BINS_PHI + 1)  /* the last bin holds directions below the surface */
#define DIR_SAMPLES 200000

typedef vec3 (*dir_sampler)(void *user, vec2 u, float *pdf_out);
typedef float (*dir_pdf)(void *user, vec3 w);

/* Expected counts for n samples: the pdf integrated over each cell (DIR_BINS entries). Returns the
 * total probability, which must be 1 for a normalised pdf. */
double dir_expected_counts(dir_pdf pdf, void *user, double *expected, double n);

/* DIR_SAMPLES samples from rng_seeded(seed, 0) must be unit vectors whose histogram matches pdf at
 * level alpha; fails at file:line (or the outermost PL_AT call site) naming `name`. */
void dir_check_sampler(const char *name, dir_sampler sample, dir_pdf pdf, void *user, uint64_t seed, double alpha,
                       const char *file, int line);
#define check_sampler(name, sample, pdf, user, seed, alpha) \
    dir_check_sampler((name), (sample), (pdf), (user), (seed), (alpha), __FILE__, __LINE__)

#endif
