/* The film: what a render keeps of every pixel's samples, and how ranges of samples merge.
 *
 * Each pixel keeps the count of its samples and, per channel and for luminance, the sum and the
 * sum of squares of their values. From them come the mean (the image) and the variance of the
 * mean (how much to trust it), and two films of disjoint sample ranges add up to the film of
 * both.
 *
 * Why fixed point and not double: a render split into sample ranges (0:100 and 100:256 on two
 * machines) must merge into the same bytes as the render of 0:256 in one go, for any split and
 * any thread count. Double addition is not associative: (a + b) + c and a + (b + c) can differ in
 * the last bit, and the last bit shows in the EXR. So each sample value is first rounded to a
 * whole multiple of 2^-32 (FILM_FRAC_BITS), and the sums are integers: integer addition is exact,
 * so any grouping of the same samples gives the same sums. The rounding error (2^-33 at most per
 * sample) is far below float's precision for any value a pixel shows.
 *
 * Bad samples: a sample value that is NaN, infinite, negative or >= FILM_MAX_VALUE adds nothing
 * to the sums (it counts as black) and is counted in `bad`, so the render reports the pixel and a
 * grader can refuse it; the count n still includes it. FILM_MAX_VALUE = 2^31 keeps every square
 * exact in 128 bits (q < 2^63, q^2 < 2^126) and a sum of 2^31 samples below 2^125.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_FILM_H
#define PL_FILM_H

#include <stdbool.h>
#include <stdint.h>
#include "vec.h"
#include "image.h"
#include "status.h"

#define FILM_FRAC_BITS 32
#define FILM_MAX_VALUE 2147483648.0  /* 2^31 */

__extension__ typedef unsigned __int128 film_sum;  /* a sum of values in units of 2^-FILM_FRAC_BITS */

/* One pixel's accumulators. Channels 0, 1, 2 are r, g, b; 3 is the luminance (rgb_luminance of
 * the sample, rounded like the others). sum_sq holds each square rounded to 2^-32. */
typedef struct {
    film_sum sum[4], sum_sq[4];
    uint32_t n;    /* samples taken */
    uint32_t bad;  /* of which NaN, Inf, negative or too large (added as black) */
} film_pixel;

typedef struct {
    int width, height;
    film_pixel *pixels;  /* width * height, top row first like image; owned */
} film;

pl_status film_alloc(film *f, int width, int height);  /* all zero; PL_ERR_NOMEM on failure */
void film_free(film *f);                              /* NULL-safe */

/* A value in units of 2^-32, rounded to nearest (ties away from zero); false for a bad value. */
bool film_quantise(float v, uint64_t *q);

/* Adds one sample's radiance; false (and p->bad counted) when any channel is bad. */
bool film_pixel_add(film_pixel *p, rgb L);

/* into += from: the pixel of both sample sets (exact, in any order); false, and into unchanged,
 * when the counts would overflow (no render of at most 2^24 samples comes near). */
bool film_pixel_merge(film_pixel *into, const film_pixel *from);

/* Checks that every pixel of f (read from `what`) is one a render could give: n_min <= n <= n_max,
 * bad <= n, and in each channel the sums of the n - bad good samples possible: zero without one,
 * each value below FILM_MAX_VALUE, and sum^2 <= good * sum_sq (Cauchy-Schwarz) allowing each
 * square's rounding. The error names the first pixel (from the top-left) and the field. */
pl_status film_check(const film *f, uint32_t n_min, uint32_t n_max, const char *what, pl_diag *diag);

/* A sum back in radiance units, as a double. */
double film_sum_value(film_sum s);

/* The mean of channel c (0..3) over the n samples; 0 when n = 0. */
double film_pixel_mean(const film_pixel *p, int c);

/* The variance of that mean: the sample variance / n; 0 when n < 2. */
double film_pixel_variance_of_mean(const film_pixel *p, int c);

/* The pixel's colour in the image: the mean per channel, as float. */
rgb film_pixel_rgb(const film_pixel *p);

/* The image of the means (float) and, when samples is not NULL, each pixel's count. */
pl_status film_to_image(const film *f, image *out, int *samples, pl_diag *diag);

#endif
