/* Grader machinery: not part of any assignment. The image verdict; the statistic is explained in verdict.h. */
#include "verdict.h"
#include "../framework/stats.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

verdict_params verdict_params_default(int candidate_spp)
{
    verdict_params p = {.family_alpha = 1e-3, .candidate_spp = candidate_spp > 0 ? candidate_spp : 1,
                        .min_block_pixels = 64, .min_block_samples = 8192, .tolerance = VERDICT_ROUNDING_TOLERANCE,
                        .tie_pixels = VERDICT_TIE_PIXELS};
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

/* Known variance: z = sum(d) / sqrt(sum of the predicted variances of d). Every pixel's variance
 * includes its rounding (pixel_variance), so no block has none, and none gets p = 0 from it. */
static double known_p(const diff_acc *a, double *t)
{
    *t = a->var > 0.0 ? a->s1 / sqrt(a->var) : 0.0;
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
    static const struct { double factor; const char *code, *text; } known[] = {
        {2.0, "factor_2", "about 2x the reference: a term counted twice (emission?) or a pdf half what it should be"},
        {0.5, "factor_1/2", "about 1/2 of the reference: a lost factor 2 (a hemisphere pdf of 1/pi instead of 1/(2 pi)?)"},
        {M_PI, "factor_pi", "about pi x the reference: a missing 1/pi (the diffuse BSDF is albedo / pi)"},
        {1.0 / M_PI, "factor_1/pi", "about 1/pi of the reference: an extra 1/pi (the BSDF or a pdf applied twice?)"},
    };
    v->hint[0] = '\0';
    v->hint_code = NULL;
    long lit = 0, black = 0;
    for (long i = 0; i < (long)ref->width * ref->height; i++) {
        const float *r = ref->rgb + 3 * i, *c = cand->rgb + 3 * i;
        if (r[0] + r[1] + r[2] > 0.03f) {
            lit++;
            black += c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f;
        }
    }
    if (lit > 0 && black * 4 > lit) {
        /* No count: how many pixels are black is the candidate's choice (grade_figure.h). */
        snprintf(v->hint, sizeof v->hint, "black where the reference is lit (more than a quarter of its lit pixels)");
        v->hint_code = "black";
        return;
    }
    /* The factor is measured where it is telling: light reflected by the surfaces. A pixel that sees
     * an emitter directly holds its Le, which no BSDF or pdf scales, so on a Cornell box the image's
     * ratio for a missing 1/pi is about 1.8, not pi. Emitters are the image's brightest pixels: those
     * within a quarter of the brightest are left out (a scene with no visible emitter only loses
     * its brightest pixels, whose ratio is the same as the rest's), and so are pixels the reference
     * saw the same in every sample (zero variance, when known): a dimmer emitter beside a bright one
     * (cornell_two_lights) is constant over its pixels, and no surface lit by sampling is. */
    double brightest = 0.0, sum_c[3] = {0, 0, 0}, sum_r[3] = {0, 0, 0}, ratio[3];
    for (long i = 0; i < (long)ref->width * ref->height; i++) {
        const float *r = ref->rgb + 3 * i;
        if (isfinite(r[0] + r[1] + r[2])) brightest = fmax(brightest, (double)r[0] + r[1] + r[2]);
    }
    for (long i = 0; i < (long)ref->width * ref->height; i++) {
        const float *r = ref->rgb + 3 * i, *c = cand->rgb + 3 * i;
        double rs = (double)r[0] + r[1] + r[2];
        bool constant = ref->var && rs > 0.0 && ref->var[3 * i] == 0.0f && ref->var[3 * i + 1] == 0.0f &&
                        ref->var[3 * i + 2] == 0.0f;
        if (!(rs <= 0.25 * brightest) || constant || !isfinite(c[0] + c[1] + c[2])) continue;
        for (int ch = 0; ch < 3; ch++) sum_c[ch] += c[ch], sum_r[ch] += r[ch];
    }
    for (int ch = 0; ch < 3; ch++) ratio[ch] = sum_r[ch] > 0.0 ? sum_c[ch] / sum_r[ch] : NAN;
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        bool all = true, any = false;
        for (int ch = 0; ch < 3; ch++) {
            if (!(ratio[ch] > 0.0) || !isfinite(ratio[ch])) continue;  /* channel unlit */
            any = true;
            all = all && fabs(ratio[ch] / known[k].factor - 1.0) < 0.08;
        }
        if (any && all) {
            snprintf(v->hint, sizeof v->hint, "%s", known[k].text);
            v->hint_code = known[k].code;
            return;
        }
    }
}

/* The largest value of the reference's 3x3 neighbourhood of pixel (x, y), in channel ch. */
static double local_max(const verdict_image *ref, int x, int y, int ch)
{
    double m = 0.0;
    for (int j = y > 0 ? y - 1 : 0; j <= y + 1 && j < ref->height; j++)
        for (int i = x > 0 ? x - 1 : 0; i <= x + 1 && i < ref->width; i++)
            m = fmax(m, (double)ref->rgb[3 * ((long)j * ref->width + i) + ch]);
    return m;
}

/* The predicted variance of one difference d = candidate - reference at pixel (x, y), channel ch,
 * known_variance only: Var(candidate) + Var(reference), the first from the reference's per-sample
 * variance (its variance of the mean times its samples) over the candidate's samples, plus the
 * rounding of two correct implementations (VERDICT_ROUNDING_SD).
 * Where the reference's samples all agreed, coverage is a Bernoulli event it did not see, and the
 * z test must not give p = 0 for one candidate sample that hit the sliver (verdict.h). The
 * candidate's own variance of the mean says what its hits weigh, but it is the candidate's number
 * (a forged film claims any sum of squares), so it counts only up to a bound from the reference's
 * side and the course's sample count:
 * - the reference bounds the chance of a hit: all reference_spp samples missed, so it is about
 *   1 / (reference_spp + 1) or less; a candidate's n samples then hit at most once, bar chance, and
 *   its mean moves by steps of 1/n of the contrast. A z test of so rare an event is honest only
 *   when that one step weighs about one standard deviation, so the bound is the variance of the
 *   mean of a Bernoulli with p = 1/n: p (1 - p) / n times the contrast squared, what one hit in n
 *   weighs (a bound of p = 1 / (reference_spp + 1) made one hit z = sqrt(reference_spp / n), 8 at
 *   1024 and 16: p = 0 again);
 * - the contrast: samples are non-negative, so a hit and a miss differ by at most the larger of
 *   their values: the pixel's own, or that of the surface the hit found, which borders the pixel and
 *   so shows in its neighbourhood (local_max, the 3x3 maximum, the pixel included).
 * So an honest candidate keeps its own variance (zero on flat faces: the strict floor), and a forged
 * one buys at most one hit's worth per pixel: a block off by that everywhere still has z = sqrt(m)
 * over its m pixels, and a flat grey forged over a black or white face, no leniency at all. */
static double pixel_variance(const verdict_params *p, const verdict_image *ref, const verdict_image *cand, int x,
                             int y, int ch)
{
    long k = 3 * ((long)y * ref->width + x) + ch;
    double ref_var = ref->var[k], per_sample = ref_var * p->reference_spp, var;
    if (per_sample > VERDICT_NO_SPREAD * VERDICT_NO_SPREAD)
        var = ref_var * ((double)p->reference_spp / p->candidate_spp + 1.0);
    else {
        double n = p->candidate_spp, contrast = local_max(ref, x, y, ch);
        double one_hit = (1.0 / n) * (1.0 - 1.0 / n) / n * contrast * contrast;
        double cand_var = cand->var && cand->var[k] > 0.0 ? cand->var[k] : 0.0;  /* NaN: none */
        var = fmin(cand_var, one_hit) + ref_var;
    }
    return var + VERDICT_ROUNDING_SD * VERDICT_ROUNDING_SD;
}

/* A deterministic pixel: its largest difference, and each block's largest signed one (in units of
 * the tolerance, for the z-map). Returns whether some channel is beyond the tolerance. */
static bool compare_pixel(verdict *v, const float *c, const float *r, int x, int y, long block)
{
    bool beyond = false;
    for (int ch = 0; ch < 3; ch++) {
        double d = (double)c[ch] - (double)r[ch], ad = fabs(d);
        if (ad > v->max_diff) {
            v->max_diff = ad;
            v->max_x = x;
            v->max_y = y;
            v->max_channel = ch;
        }
        beyond = beyond || ad > v->tolerance;
        float *t = &v->t[block * 3 + ch];
        if (fabs(d / v->tolerance) > fabsf(*t)) *t = (float)(d / v->tolerance);
    }
    return beyond;
}

/* A bad candidate pixel (NaN, Inf, negative): counted, and the first one located. */
static bool bad_pixel(verdict *v, const float *c, int x, int y)
{
    if (isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2]) && c[0] >= 0 && c[1] >= 0 && c[2] >= 0) return false;
    if (v->bad_pixels++ == 0) {
        v->bad_x = x;
        v->bad_y = y;
    }
    return true;
}

/* One pass over the pixels: bad values, relMSE, the ratio, and either the differences per block and
 * over the image (acc: blocks x 3, then the 3 whole-image channels) or the deterministic comparison. */
static void scan_pixels(verdict *v, const verdict_image *cand, const verdict_image *ref, const verdict_params *p,
                        diff_acc *acc)
{
    int w = ref->width, h = ref->height;
    diff_acc *whole = acc + (size_t)v->blocks_x * v->blocks_y * 3;
    double cand_total[3] = {0, 0, 0}, ref_total[3] = {0, 0, 0}, se = 0.0;
    for (int y = 0; y < h; y++) {
        int by = (int)((long)y * v->blocks_y / h);
        for (int x = 0; x < w; x++) {
            long i = (long)y * w + x, block = (long)by * v->blocks_x + (int)((long)x * v->blocks_x / w);
            const float *c = cand->rgb + 3 * i, *r = ref->rgb + 3 * i;
            if (bad_pixel(v, c, x, h - 1 - y)) continue;
            if (p->deterministic) v->beyond_tolerance += compare_pixel(v, c, r, x, h - 1 - y, block);
            for (int ch = 0; ch < 3; ch++) {
                double d = (double)c[ch] - (double)r[ch];
                double var = p->known_variance && ref->var ? pixel_variance(p, ref, cand, x, y, ch) : 0.0;
                diff_add(&acc[block * 3 + ch], d, r[ch], var);
                diff_add(&whole[ch], d, r[ch], var);
                cand_total[ch] += c[ch];
                ref_total[ch] += r[ch];
                se += d * d / ((double)r[ch] * r[ch] + 0.01);
            }
        }
    }
    v->rel_mse = se / (3.0 * (double)w * h);
    for (int ch = 0; ch < 3; ch++) v->ratio[ch] = ref_total[ch] > 0 ? cand_total[ch] / ref_total[ch] : NAN;
}

/* A test's differences with the relative tolerance taken off: the sum moved towards zero by
 * tolerance x the reference's sum (no further), each difference by its share of that. */
static diff_acc tolerate(diff_acc a, double tolerance)
{
    if (!(tolerance > 0.0) || a.n == 0) return a;
    double slack = tolerance * fabs(a.ref), keep = fabs(a.s1) > slack ? (fabs(a.s1) - slack) / fabs(a.s1) : 0.0;
    double shift = (a.s1 - keep * a.s1) / (double)a.n;  /* per difference */
    /* The sums of d - shift: the mean moves, the spread stays. */
    double n = (double)a.n, s1 = a.s1 - n * shift;
    double s2 = a.s2 - 2.0 * shift * a.s1 + n * shift * shift;
    double s3 = a.s3 - 3.0 * shift * a.s2 + 3.0 * shift * shift * a.s1 - n * shift * shift * shift;
    a.s1 = s1, a.s2 = s2, a.s3 = s3;
    return a;
}

/* Every test, the smallest p-value, and Sidak over all of them. */
static void run_tests(verdict *v, const verdict_params *p, bool known, const diff_acc *acc)
{
    long nblocks = (long)v->blocks_x * v->blocks_y;
    v->num_tests = (int)(nblocks * 3 + 3);
    double p_min = 1.0;
    v->worst_block_x = v->worst_block_y = -1;
    for (long k = 0; k < nblocks * 3 + 3; k++) {
        diff_acc a = tolerate(acc[k], p->relative_tolerance);
        double t, pk = known ? known_p(&a, &t) : paired_p(&a, &t);
        if (k < nblocks * 3) v->t[k] = (float)t;
        if (pk < p_min || k == 0) {
            p_min = pk;
            v->worst_t = t;
            v->worst_channel = (int)(k % 3);
            bool block = k < nblocks * 3;
            v->worst_block_x = block ? (int)(k / 3 % v->blocks_x) : -1;
            v->worst_block_y = block ? (int)(k / 3 / v->blocks_x) : -1;
        }
    }
    v->p_value = -expm1((double)v->num_tests * log1p(-fmin(p_min, 1.0)));
    v->pass = v->bad_pixels == 0 && v->p_value >= p->family_alpha;
}

/* Whether the candidate is the reference times one factor wherever the image is lit, up to noise:
 * the factor f of their sums, then in each block a paired t test of c - f r over its pixels, none of
 * which may stand out (|t| >= 4: a correct factor's image keeps every block below it but about once
 * in 300 verdicts of 60 blocks, where 3 would fail one in six). Pixels that see an emitter are left out, as the hint
 * leaves them: those whose reference is lit but was the same in every sample (zero variance), the
 * light's own Le, which no BSDF or pdf scales, so a missing 1/pi leaves them alone and is still one
 * factor elsewhere. A bug confined to one object (a glass's radiance scale, a flipped row of an
 * environment map) leaves its blocks off that factor, however far the image's mean ratio moves. */
static bool seen_emitter(const verdict_image *ref, long i)
{
    const float *r = ref->rgb + 3 * i, *var = ref->var ? ref->var + 3 * i : NULL;
    return var && r[0] + r[1] + r[2] > 0.0f && var[0] == 0.0f && var[1] == 0.0f && var[2] == 0.0f;
}

static bool one_factor(const verdict *v, const verdict_image *cand, const verdict_image *ref)
{
    int w = ref->width, h = ref->height;
    long nblocks = (long)v->blocks_x * v->blocks_y;
    double csum = 0.0, rsum = 0.0;
    for (long i = 0; i < (long)w * h; i++) {
        double r = (double)ref->rgb[3 * i] + ref->rgb[3 * i + 1] + ref->rgb[3 * i + 2];
        double c = (double)cand->rgb[3 * i] + cand->rgb[3 * i + 1] + cand->rgb[3 * i + 2];
        if (!seen_emitter(ref, i) && isfinite(c) && isfinite(r)) csum += c, rsum += r;
    }
    if (!(rsum > 0.0)) return false;
    double f = csum / rsum;
    diff_acc *acc = calloc((size_t)nblocks, sizeof *acc);
    if (!acc) return false;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            long i = (long)y * w + x, b = (long)(y * v->blocks_y / h) * v->blocks_x + x * v->blocks_x / w;
            double r = (double)ref->rgb[3 * i] + ref->rgb[3 * i + 1] + ref->rgb[3 * i + 2];
            double c = (double)cand->rgb[3 * i] + cand->rgb[3 * i + 1] + cand->rgb[3 * i + 2];
            if (!seen_emitter(ref, i) && isfinite(c) && isfinite(r)) diff_add(&acc[b], c - f * r, r, 0.0);
        }
    bool one = true;
    for (long b = 0; b < nblocks && one; b++) {
        double t;
        paired_p(&acc[b], &t);
        one = fabs(t) < 4.0;
    }
    free(acc);
    return one;
}

/* Where a failed statistical verdict differs (verdict.h): the blocks that stand out in its tests,
 * their extent and ratio, and whether the image is off by one factor (one_factor). */
static void find_region(verdict *v, const diff_acc *acc, const verdict_image *cand, const verdict_image *ref)
{
    long nblocks = (long)v->blocks_x * v->blocks_y;
    double cand_sum = 0.0, ref_sum = 0.0;
    v->region_x0 = v->blocks_x, v->region_y0 = v->blocks_y, v->region_x1 = v->region_y1 = -1;
    for (long b = 0; b < nblocks; b++) {
        if (fmaxf(fabsf(v->t[3 * b]), fmaxf(fabsf(v->t[3 * b + 1]), fabsf(v->t[3 * b + 2]))) < VERDICT_REGION_T) continue;
        int bx = (int)(b % v->blocks_x), by = (int)(b / v->blocks_x);
        v->region_blocks++;
        v->region_x0 = bx < v->region_x0 ? bx : v->region_x0, v->region_x1 = bx > v->region_x1 ? bx : v->region_x1;
        v->region_y0 = by < v->region_y0 ? by : v->region_y0, v->region_y1 = by > v->region_y1 ? by : v->region_y1;
        for (int ch = 0; ch < 3; ch++) cand_sum += acc[3 * b + ch].ref + acc[3 * b + ch].s1, ref_sum += acc[3 * b + ch].ref;
    }
    v->region_ratio = ref_sum > 0.0 ? cand_sum / ref_sum : NAN;
    v->uniform_factor = !v->pass && one_factor(v, cand, ref);
}

/* The deterministic verdict: at most tie_pixels pixels beyond the tolerance (verdict.h); the worst
 * block is the one holding the largest difference. */
static void judge_rounding(verdict *v, int width, int height)
{
    v->pass = v->bad_pixels == 0 && v->beyond_tolerance <= v->tie_pixels;
    v->p_value = v->pass ? 1.0 : 0.0;
    v->worst_channel = v->max_channel;
    v->worst_block_x = v->worst_block_y = -1;
    if (v->max_x < 0) return;  /* no difference at all */
    v->worst_block_x = (int)((long)v->max_x * v->blocks_x / width);
    v->worst_block_y = (int)((long)(height - 1 - v->max_y) * v->blocks_y / height);
    v->worst_t = v->t[((long)v->worst_block_y * v->blocks_x + v->worst_block_x) * 3 + v->max_channel];
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
    v->hint_code = "self_shadowing";
}

pl_status verdict_compute(const verdict_image *cand, const verdict_image *ref, const verdict_params *p,
                          verdict *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    if (cand->width != ref->width || cand->height != ref->height || cand->width <= 0 || cand->height <= 0)
        return pl_fail(diag, PL_ERR_INVALID, "the candidate is %dx%d, the reference %dx%d: expected the same size",
                       cand->width, cand->height, ref->width, ref->height);
    if (p->deterministic && !(p->tolerance > 0.0 && p->tie_pixels >= 0))
        return pl_fail(diag, PL_ERR_INVALID, "a deterministic verdict needs a tolerance > 0 and tie pixels >= 0");
    int w = ref->width, h = ref->height, b = block_side(p);
    out->blocks_x = w / b > 0 ? w / b : 1;
    out->blocks_y = h / b > 0 ? h / b : 1;
    long nblocks = (long)out->blocks_x * out->blocks_y;
    out->t = calloc((size_t)nblocks * 3, sizeof *out->t);
    diff_acc *acc = calloc((size_t)nblocks * 3 + 3, sizeof *acc);
    if (!out->t || !acc) {
        free(acc);
        verdict_free(out);
        return pl_fail(diag, PL_ERR_NOMEM, "out of memory comparing %dx%d images", w, h);
    }
    out->bad_x = out->bad_y = out->max_x = out->max_y = -1;
    out->deterministic = p->deterministic;
    out->tolerance = p->tolerance;
    out->tie_pixels = p->tie_pixels;
    scan_pixels(out, cand, ref, p, acc);
    if (p->deterministic) judge_rounding(out, w, h);
    else {
        run_tests(out, p, p->known_variance && ref->var, acc);
        find_region(out, acc, cand, ref);
    }
    free(acc);
    out->alpha = p->family_alpha;
    find_hint(out, cand, ref);
    self_shadow_hint(out, p);
    return PL_OK;
}

double verdict_noise_ratio(const verdict_image *cand, const verdict_image *ref, int cand_spp, int ref_spp)
{
    if (!cand->var || !ref->var || cand->width != ref->width || cand->height != ref->height) return NAN;
    double sum = 0.0;
    long pixels = 0;
    for (long i = 0; i < (long)ref->width * ref->height; i++) {
        const float *c = cand->var + 3 * i, *r = ref->var + 3 * i;
        double rv = ((double)r[0] + r[1] + r[2]) * ref_spp, cv = ((double)c[0] + c[1] + c[2]) * cand_spp;
        if (!(rv > 0.0)) continue;  /* no noise to compare with */
        sum += isfinite(cv) ? fmin(cv / rv, VERDICT_NOISE_CAP) : VERDICT_NOISE_CAP;
        pixels++;
    }
    return pixels > 0 ? sum / pixels : NAN;
}
