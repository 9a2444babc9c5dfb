/* Grader machinery: not part of any assignment. The image verdict; the statistic is explained in verdict.h. */
#include "verdict.h"
#include "../framework/stats.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

verdict_params verdict_params_default(int candidate_spp)
{
    verdict_params p = {1e-3, candidate_spp > 0 ? candidate_spp : 1, 64, 8192, false, 0, false};
    return p;
}

void verdict_free(verdict *v)
{
    if (!v) return;
    free(v->t);
    v->t = NULL;
}

/* The differences of one test: n, and sums of d, d^2, d^3 (d is small, so plain sums lose nothing
 * that matters at the precision of a p-value). */
typedef struct { long n; double s1, s2, s3, ref, var; } diff_acc;

static void diff_add(diff_acc *a, double d, double ref, double var)
{
    a->n++;
    a->s1 += d;
    a->s2 += d * d;
    a->s3 += d * d * d;
    a->ref += ref;
    a->var += var;
}

/* Known variance: z = sum(d) / sqrt(sum of the predicted variances of d). No predicted variance at
 * all (every pixel of the block the same in every sample) asks for agreement up to rounding. */
static double known_p(const diff_acc *a, double *t)
{
    *t = 0.0;
    if (a->var <= 0.0) return fabs(a->s1) <= 1e-5 * (1.0 + fabs(a->ref)) ? 1.0 : 0.0;
    *t = a->s1 / sqrt(a->var);
    return erfc(fabs(*t) / sqrt(2.0));
}

/* The p-value of one paired test: Johnson's t for skewed populations (N. J. Johnson, JASA 73, 1978),
 *   t = (mean + m3 / (6 s^2 n) + m3 / (3 s^4) mean^2) / (s / sqrt(n)),
 * the t statistic plus the first Cornish-Fisher term of the skew m3 (third central moment). Rare
 * bright paths make radiance skewed; plain t then rejects too often on the dark side.
 * Differences without spread are exact agreement (p = 1) only when their mean is rounding
 * (deterministic images: normal shading at one sample per pixel). */
static double paired_p(const diff_acc *a, double *t)
{
    double n = (double)a->n, mean = a->n ? a->s1 / n : 0.0;
    double var = a->n > 1 ? fmax(0.0, (a->s2 - a->s1 * mean) / (n - 1.0)) : 0.0;
    *t = 0.0;
    if (a->n < 2 || var == 0.0)
        return fabs(mean) <= 1e-5 * (1.0 + fabs(a->ref / fmax(n, 1.0))) ? 1.0 : 0.0;
    double m3 = a->s3 / n - 3.0 * mean * a->s2 / n + 2.0 * mean * mean * mean;
    *t = (mean + m3 / (6.0 * var * n) + m3 / (3.0 * var * var) * mean * mean) / sqrt(var / n);
    return stats_t_sf2(*t, n - 1.0);
}

/* Blocks: square, a power of two from 8 up, big enough for the t test to be trusted (verdict.h). */
static int block_side(const verdict_params *p)
{
    int b = 8;
    while ((long)b * b < p->min_block_pixels || (long)b * b * p->candidate_spp < p->min_block_samples)
        b *= 2;
    return b;
}

/* A hint when every lit channel is off by the same well-known factor, or the image is black where
 * the reference is lit. These are the mistakes students make most (handout/part3.md, part4.md). */
static void find_hint(verdict *v, const verdict_image *cand, const verdict_image *ref)
{
    static const struct { double factor; const char *text; } known[] = {
        {2.0, "about 2x the reference: a term counted twice (emission?) or a pdf half what it should be"},
        {0.5, "about 1/2 of the reference: a lost factor 2 (a hemisphere pdf of 1/pi instead of 1/(2 pi)?)"},
        {M_PI, "about pi x the reference: a missing 1/pi (the diffuse BSDF is albedo / pi)"},
        {1.0 / M_PI, "about 1/pi of the reference: an extra 1/pi (the BSDF or a pdf applied twice?)"},
    };
    v->hint[0] = '\0';
    long lit = 0, black = 0;
    for (long i = 0; i < (long)ref->width * ref->height; i++) {
        const float *r = ref->rgb + 3 * i, *c = cand->rgb + 3 * i;
        if (r[0] + r[1] + r[2] > 0.03f) {
            lit++;
            black += c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f;
        }
    }
    if (lit > 0 && black * 4 > lit) {
        snprintf(v->hint, sizeof v->hint, "black where the reference is lit (%ld of %ld lit pixels)", black, lit);
        return;
    }
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        bool all = true, any = false;
        for (int ch = 0; ch < 3; ch++) {
            if (!(v->ratio[ch] > 0.0) || !isfinite(v->ratio[ch])) continue;  /* channel unlit */
            any = true;
            all = all && fabs(v->ratio[ch] / known[k].factor - 1.0) < 0.08;
        }
        if (any && all) {
            snprintf(v->hint, sizeof v->hint, "%s", known[k].text);
            return;
        }
    }
}

/* Self-shadowing: on a case lit at grazing angles, a failure on the dark side, darker overall in
 * every lit channel (acne steals light whatever its colour), that no known factor explains. */
static void self_shadow_hint(verdict *v, const verdict_params *p)
{
    if (!p->grazing || v->pass || v->hint[0] || !(v->worst_t < 0.0)) return;
    for (int ch = 0; ch < 3; ch++)
        if (isfinite(v->ratio[ch]) && v->ratio[ch] > 0.0 && !(v->ratio[ch] < 1.0)) return;
    snprintf(v->hint, sizeof v->hint, "darker than the reference where light grazes the surfaces: self-shadowing? Rays "
             "from the raw hit point hit their own surface; spawn them with spawn.h (handout/part3.md, 3.4)");
}

pl_status verdict_compute(const verdict_image *cand, const verdict_image *ref, const verdict_params *p,
                          verdict *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    if (cand->width != ref->width || cand->height != ref->height || cand->width <= 0 || cand->height <= 0)
        return pl_fail(diag, PL_ERR_INVALID, "the candidate is %dx%d, the reference %dx%d: expected the same size",
                       cand->width, cand->height, ref->width, ref->height);
    int w = ref->width, h = ref->height, b = block_side(p);
    out->blocks_x = w / b > 0 ? w / b : 1;
    out->blocks_y = h / b > 0 ? h / b : 1;
    int nblocks = out->blocks_x * out->blocks_y;
    out->t = calloc((size_t)nblocks * 3, sizeof *out->t);
    diff_acc *acc = calloc((size_t)nblocks * 3 + 3, sizeof *acc);
    if (!out->t || !acc) {
        free(acc);
        verdict_free(out);
        return pl_fail(diag, PL_ERR_NOMEM, "out of memory comparing %dx%d images", w, h);
    }
    diff_acc *whole = acc + (size_t)nblocks * 3;
    double cand_total[3] = {0, 0, 0}, se = 0.0;

    /* One pass over the pixels: bad values, the differences per block and over the image, relMSE. */
    out->bad_x = out->bad_y = -1;
    for (int y = 0; y < h; y++) {
        int by = (int)((long)y * out->blocks_y / h);
        for (int x = 0; x < w; x++) {
            int bx = (int)((long)x * out->blocks_x / w);
            const float *c = cand->rgb + 3 * ((long)y * w + x), *r = ref->rgb + 3 * ((long)y * w + x);
            if (!(isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2]) && c[0] >= 0 && c[1] >= 0 && c[2] >= 0)) {
                if (out->bad_pixels++ == 0) {
                    out->bad_x = x;
                    out->bad_y = h - 1 - y;
                }
                continue;
            }
            const float *rv = ref->var ? ref->var + 3 * ((long)y * w + x) : NULL;
            for (int ch = 0; ch < 3; ch++) {
                double d = (double)c[ch] - (double)r[ch];
                /* Var(d) = Var(candidate) + Var(reference), the first from the reference's per-sample
                 * variance (its variance of the mean times its samples) over the candidate's samples. */
                double var = rv ? (double)rv[ch] * ((double)p->reference_spp / p->candidate_spp + 1.0) : 0.0;
                long k = ((long)by * out->blocks_x + bx) * 3 + ch;
                diff_add(&acc[k], d, r[ch], var);
                diff_add(&whole[ch], d, r[ch], var);
                cand_total[ch] += c[ch];
                se += stats_rel_se(c[ch], r[ch]);
            }
        }
    }
    out->rel_mse = se / (3.0 * (double)w * h);
    for (int ch = 0; ch < 3; ch++) out->ratio[ch] = whole[ch].ref > 0 ? cand_total[ch] / whole[ch].ref : NAN;

    /* Every test, the smallest p-value, and Sidak over all of them. */
    out->num_tests = nblocks * 3 + 3;
    double p_min = 1.0;
    out->worst_block_x = out->worst_block_y = -1;
    for (long k = 0; k < (long)nblocks * 3 + 3; k++) {
        double t, pk = p->known_variance && ref->var ? known_p(&acc[k], &t) : paired_p(&acc[k], &t);
        if (k < (long)nblocks * 3) out->t[k] = (float)t;
        if (pk < p_min || k == 0) {
            p_min = pk;
            out->worst_t = t;
            out->worst_channel = (int)(k % 3);
            bool block = k < (long)nblocks * 3;
            out->worst_block_x = block ? (int)(k / 3 % out->blocks_x) : -1;
            out->worst_block_y = block ? (int)(k / 3 / out->blocks_x) : -1;
        }
    }
    free(acc);
    out->p_value = -expm1((double)out->num_tests * log1p(-fmin(p_min, 1.0)));
    out->alpha = p->family_alpha;
    out->pass = out->bad_pixels == 0 && out->p_value >= p->family_alpha;
    find_hint(out, cand, ref);
    self_shadow_hint(out, p);
    return PL_OK;
}
