/* The film: fixed-point per-pixel accumulators (see film.h for why fixed point). */
#include "film.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* ---- the film ------------------------------------------------------------------------------------ */

/* Zeroed: every pixel starts with no samples and zero sums. */
pl_status film_alloc(film *f, int width, int height)
{
    f->width = width;
    f->height = height;
    f->pixels = calloc((size_t)width * (size_t)height, sizeof *f->pixels);
    return f->pixels ? PL_OK : PL_ERR_NOMEM;
}

void film_free(film *f)
{
    if (!f) return;
    free(f->pixels);
    f->pixels = NULL;
}

bool film_quantise(float v, uint64_t *q)
{
    /* The tests reject NaN too: every comparison with NaN is false. */
    if (!(v >= 0.0f && (double)v < FILM_MAX_VALUE)) return false;
    /* v * 2^32 is exact in double (float has 24 bits), and so is adding 0.5 to it when it has a
     * fraction (it is then below 2^52); the cast truncates: round half up, as llround for v >= 0. */
    *q = (uint64_t)((double)v * 4294967296.0 + 0.5);
    return true;
}

/* q^2 in units of 2^-32, rounded to nearest: exact integer arithmetic, so the same everywhere. */
static film_sum square_of(uint64_t q)
{
    film_sum sq = (film_sum)q * q;
    return (sq + ((film_sum)1 << (FILM_FRAC_BITS - 1))) >> FILM_FRAC_BITS;
}

/* ---- one pixel's accumulators ------------------------------------------------------------------ */

/* All four values (r, g, b and luminance) are checked before any is added, so a bad sample leaves
 * the sums untouched and counts only in n and bad. */
bool film_pixel_add(film_pixel *p, rgb L)
{
    float v[4] = {L.r, L.g, L.b, rgb_luminance(L)};
    uint64_t q[4];
    p->n++;
    for (int c = 0; c < 4; c++)
        if (!film_quantise(v[c], &q[c])) {
            p->bad++;  /* the whole sample counts as black */
            return false;
        }
    for (int c = 0; c < 4; c++) {
        p->sum[c] += q[c];
        p->sum_sq[c] += square_of(q[c]);
    }
    return true;
}

/* Integer sums: adding two ranges' accumulators gives exactly the accumulators of both. */
bool film_pixel_merge(film_pixel *into, const film_pixel *from)
{
    if (from->n > UINT32_MAX - into->n || from->bad > UINT32_MAX - into->bad) return false;
    for (int c = 0; c < 4; c++) {
        into->sum[c] += from->sum[c];
        into->sum_sq[c] += from->sum_sq[c];
    }
    into->n += from->n;
    into->bad += from->bad;
    return true;
}

/* What is wrong with channel c of a pixel with `good` good samples, or NULL. */
static const char *channel_impossible(const film_pixel *p, int c, uint32_t good)
{
    /* A good value q is below 2^63 units (FILM_MAX_VALUE = 2^31), its rounded square below 2^94. */
    if (good == 0) return p->sum[c] || p->sum_sq[c] ? "sums without a good sample" : NULL;
    if (p->sum[c] >> 63 >= good) return "a sum above good samples times the largest value";
    if (p->sum_sq[c] >> 94 >= good) return "a sum of squares above good samples times the largest square";
    /* Cauchy-Schwarz: (sum q)^2 <= good * sum q^2, and sum q^2 <= 2^32 (sum_sq + good / 2) (each
     * square was rounded to nearest 2^32 units); in double with a margin far above its rounding. */
    double s = (double)p->sum[c], sq = (double)p->sum_sq[c] + 0.5 * good;
    return s * s <= (double)good * 4294967296.0 * sq * (1.0 + 1e-9) ? NULL : "a sum too large for its sum of squares";
}

pl_status film_check(const film *f, uint32_t n_min, uint32_t n_max, const char *what, pl_diag *diag)
{
    static const char *const names[4] = {"R", "G", "B", "Y"};
    long count = (long)f->width * f->height;
    for (long i = 0; i < count; i++) {
        const film_pixel *p = &f->pixels[i];
        int x = (int)(i % f->width), y = (int)(i / f->width);
        if (p->n < n_min || p->n > n_max) {
            char want[64];
            if (n_min == n_max) snprintf(want, sizeof want, "%u, the size of its sample range", n_min);
            else snprintf(want, sizeof want, "%u to %u", n_min, n_max);
            return pl_fail(diag, PL_ERR_PARSE, "%s: pixel (%d, %d): n = %u samples, expected %s", what, x, y, p->n, want);
        }
        if (p->bad > p->n)
            return pl_fail(diag, PL_ERR_PARSE, "%s: pixel (%d, %d): bad = %u, more than its n = %u samples", what, x, y,
                           p->bad, p->n);
        for (int c = 0; c < 4; c++) {
            const char *why = channel_impossible(p, c, p->n - p->bad);
            if (why) return pl_fail(diag, PL_ERR_PARSE, "%s: pixel (%d, %d): acc.sum.%s / acc.sq.%s: %s (n = %u, bad = %u)",
                                    what, x, y, names[c], names[c], why, p->n, p->bad);
        }
    }
    return PL_OK;
}

/* Dividing by a power of two is exact, like ldexp, and the compiler makes it one multiplication:
 * ldexp was a libm call per channel, 4% of a one-sample render's instructions. */
double film_sum_value(film_sum s) { return (double)s / (double)((uint64_t)1 << FILM_FRAC_BITS); }

double film_pixel_mean(const film_pixel *p, int c)
{
    return p->n ? film_sum_value(p->sum[c]) / p->n : 0.0;
}

double film_pixel_variance_of_mean(const film_pixel *p, int c)
{
    if (p->n < 2) return 0.0;
    double n = p->n, s1 = film_sum_value(p->sum[c]), s2 = film_sum_value(p->sum_sq[c]);
    double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));  /* rounding can dip below 0 */
    return var / n;
}

/* ---- what the film shows -------------------------------------------------------------------------- */

pl_status film_to_image(const film *f, image *out, int *samples, pl_diag *diag)
{
    if (out->width != f->width || out->height != f->height)
        return pl_fail(diag, PL_ERR_INVALID, "film_to_image: image is %dx%d, the film %dx%d",
                       out->width, out->height, f->width, f->height);
    long count = (long)f->width * f->height;
    for (long i = 0; i < count; i++) {
        out->pixels[i] = film_pixel_rgb(&f->pixels[i]);
        if (samples) samples[i] = (int)f->pixels[i].n;
    }
    return PL_OK;
}

rgb film_pixel_rgb(const film_pixel *p)
{
    return rgb_make((float)film_pixel_mean(p, 0), (float)film_pixel_mean(p, 1), (float)film_pixel_mean(p, 2));
}
