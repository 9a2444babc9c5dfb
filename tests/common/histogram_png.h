/* Test machinery: not part of any assignment.
 * Pictures of a failed histogram test, so a student sees where the samples went wrong. */
#ifndef PL_HISTOGRAM_PNG_H
#define PL_HISTOGRAM_PNG_H

#include "../../framework/status.h"

/* Writes a PNG of three panels side by side, each rows x cols cells (row 0 at the top): the
 * observed counts, the expected counts (both coloured blue -> green -> red on one scale from 0 to
 * the largest count), and the residual (observed - expected) / sqrt(expected), grey at 0, red where
 * there are too many samples and blue where there are too few (full colour at 4 standard errors).
 * Bins are laid out row-major; a bin with expected 0 and observed > 0 shows full red. */
pl_status histogram_png_write(const char *path, const double *observed, const double *expected, int rows, int cols,
                              pl_diag *diag);

/* The folder failing tests write pictures into (build/test-output), created if needed; returns a
 * path "build/test-output/<name>.png" in out. */
void histogram_png_path(const char *name, char *out, int out_len);

#endif
