/* Grader machinery: not part of any assignment.
 * The image verdict of one grading case: is a candidate render the reference image, up to Monte
 * Carlo noise? The grader reads both images from files (never from what student code prints) and
 * calls verdict_compute in its own process.
 *
 * The statistic: per block of pixels and per channel, a paired t test on the pixel differences
 * d = candidate - reference, t = mean(d) / (sd(d) / sqrt(m)) with m - 1 degrees of freedom, plus
 * the same test over the whole image (the most powerful one for a global factor such as 2 or pi).
 * Why this statistic:
 * - it needs no variance from the candidate's file: the spread of d across the block's pixels
 *   estimates the noise of both renders, so a submission that forges its variance channel cannot
 *   buy a pass;
 * - pixels draw from independent RNG streams, so the d of one block are independent, as the test
 *   assumes; pixels differ in variance, which a sum over many pixels tolerates (the block variance
 *   is their average);
 * - radiance at few samples is heavy-tailed and skewed (rare bright paths): a t test is trustworthy
 *   only when a block holds many samples, so blocks are sized to hold at least
 *   min_block_samples candidate samples (and min_block_pixels pixels), never a fixed 8x8.
 * (With known_variance, a z test against the reference's variance instead: verdict_params.)
 * The p-values of all K tests are combined with Sidak: the case p-value is 1 - (1 - p_min)^K, uniform
 * on [0, 1] for a correct render, and the render fails when it is below family_alpha (the grader
 * then judges a second render before it fails the case: grader/grade_image.h says why).
 *
 * Deterministic cases (one sample per pixel at its centre, normal shading) run no test at all: two
 * correct implementations differ there by rounding only, and a t test divides that rounding by its
 * own spread, which is just as tiny (a geometric sphere test against the quadratic failed at
 * p = 1e-309). They compare each pixel with a tolerance instead (verdict_params.deterministic):
 * - VERDICT_ROUNDING_TOLERANCE per channel: a quarter of one step of the 8-bit output (1/1020),
 *   so a difference within it changes the PNG a student looks at by at most one level. Normal
 *   shading is 0.5 n + 0.5 of a unit normal computed in float; two correct algorithms agree to a
 *   few ulps (1e-7) on flat faces, and a sphere's normal inherits the error of its root, which the
 *   cancellation in b^2 - ac amplifies near the silhouette by about b^2 / disc: 1e-4 within a
 *   pixel of it (measured: geometric against quadratic, grading/README.md), 1e-3 only for rays
 *   a few 1e-5 pixel widths from tangent;
 * - VERDICT_TIE_PIXELS pixels may differ by more: a ray through a shared edge or vertex, or one
 *   that grazes a silhouette, may hit either surface or none, and correct implementations decide
 *   such ties differently. Each tie is a single pixel; a bug moves a whole edge (a half-pixel shift
 *   differs at hundreds of pixels) or a whole surface (a wrong normal: thousands, by 0.1 or more).
 * The case passes when at most tie_pixels pixels differ by more than tolerance in some channel;
 * the verdict names how many did and the largest difference. */
#ifndef PL_VERDICT_H
#define PL_VERDICT_H

#include <stdbool.h>
#include "../framework/status.h"

#define VERDICT_ROUNDING_TOLERANCE (1.0 / 1020.0)  /* per channel, deterministic cases: see above */
#define VERDICT_TIE_PIXELS 8                         /* pixels beyond it, deterministic cases */
/* known_variance: the rounding every pixel's difference may carry (the largest measured between
 * correct implementations, 1.2e-4, rounded down: it pads a block's variance, and a bug's
 * differences are thousands of times larger), and the per-sample spread below which a reference
 * pixel counts as having seen no variation at all (its samples equal up to the rounding of the
 * film's sums). */
#define VERDICT_ROUNDING_SD 1e-4
/* A block differs when some channel's |t| (or z) is at least this (the region of a failed verdict). */
#define VERDICT_REGION_T 3.0
#define VERDICT_NO_SPREAD 1e-6

typedef struct {
    int width, height;
    const float *rgb;  /* width * height * 3 linear means, top row first; not owned */
    const float *var;  /* the same layout: each mean's variance (NULL if unknown); the candidate's
                          is used only where the reference's is zero, and only up to a bound of the
                          reference's (known_variance, below) */
} verdict_image;

typedef struct {
    double family_alpha;    /* chance a correct render fails (default 1e-3; the grader sets cases.json's) */
    int candidate_spp;      /* samples per pixel of the candidate render (sizes the blocks) */
    int min_block_pixels;   /* at least this many pixels per block (64) */
    long min_block_samples; /* at least this many candidate samples per block (4096) */
    /* Known variance: test each block's sum of differences against the variance the reference
     * predicts (ref->var, scaled to the candidate's samples: reference_spp / candidate_spp + 1),
     * a z test, instead of the paired t test's spread. For images whose differences are mostly
     * exactly zero (normal shading: only edge pixels vary), where the spread of a few pixels makes
     * a poor estimate and t with m - 1 degrees of freedom rejects far too often.
     * Coverage at an edge is a Bernoulli event: a sliver that the reference's samples all missed
     * (zero variance) may be hit by a candidate sample. Such a pixel takes the candidate's own
     * variance of the mean instead (cand->var), which is what that one hit weighs, but never more
     * than one hit in candidate_spp samples could weigh against the brightest value of the
     * reference's neighbourhood (verdict.c, pixel_variance): never p = 0 for a difference the
     * reference could not predict, no leniency where the reference varies, and no statistic the
     * candidate supplies loosens its own test beyond the reference's bound. */
    bool known_variance;
    int reference_spp;
    /* The case is lit at grazing angles (its "grazing" field): a candidate that fails dark there
     * gets the self-shadowing hint (rays that start at the raw hit point hit their own surface,
     * which darkens exactly where light grazes it: framework/spawn.h). */
    bool grazing;
    /* A relative tolerance (0 for none): each test's summed difference is shrunk towards zero by this
     * share of the reference's sum before it is tested, so a block (or the image) off by less than
     * that passes whatever its noise. For a case where the handout accepts two conventions whose
     * images differ slightly (Schlick's cosine inside or outside the glass: the glass 1.6-2.7%
     * darker), so that either passes with margin whatever the sample count; a bug that moves a block
     * by more still fails as before, by its excess. */
    double relative_tolerance;
    /* Deterministic: no test, a per-pixel tolerance and a number of tie pixels (above). */
    bool deterministic;
    double tolerance;       /* VERDICT_ROUNDING_TOLERANCE */
    long tie_pixels;        /* VERDICT_TIE_PIXELS */
} verdict_params;

verdict_params verdict_params_default(int candidate_spp);

typedef struct {
    bool pass;
    double p_value;              /* case p-value (Sidak-adjusted smallest test p-value) */
    double alpha;                /* the case fails when p_value is below this (params' family_alpha) */
    int num_tests;               /* K: blocks x 3 channels + 3 whole-image tests */
    int blocks_x, blocks_y;      /* block grid; block (0, 0) is at the top-left */
    float *t;                    /* blocks_y * blocks_x * 3 signed t statistics, top row first (owned) */
    double worst_t;              /* the statistic with the smallest p-value ... */
    int worst_block_x, worst_block_y, worst_channel;  /* ... where (-1, -1: the whole image) */
    double rel_mse;              /* mean over pixels and channels of (c - r)^2 / (r^2 + 0.01) */
    double ratio[3];             /* sum of candidate / sum of reference, per channel */
    long bad_pixels;             /* candidate pixels with NaN, Inf or negative values */
    int bad_x, bad_y;            /* the first one, counted from the bottom-left as the renderer does */
    /* Where a statistical verdict differs (find_region): the blocks whose |t| in some channel is at
     * least VERDICT_REGION_T, their extent and their brightness against the reference's, and
     * whether the image is off by one factor wherever it is lit (those blocks cover most of the lit
     * ones and agree on their ratio) or in a region only. */
    bool uniform_factor;
    int region_blocks;           /* how many blocks differ; 0: none stands out */
    int region_x0, region_y0, region_x1, region_y1;  /* their extent in blocks, from the top-left */
    double region_ratio;         /* candidate over reference, summed over those blocks' pixels */
    char hint[200];              /* a likely cause when the ratio matches a known mistake, else "" */
    const char *hint_code;       /* the same cause as a stable code for machines ("factor_1/pi", "black",
                                    "self_shadowing": grade_facts.h), or NULL with no hint */
    /* Deterministic cases (p_value is 1 on a pass, 0 on a failure; t holds each block's largest
     * signed difference in units of the tolerance): */
    bool deterministic;
    long beyond_tolerance;       /* pixels differing by more than tolerance in some channel */
    double max_diff;             /* the largest |candidate - reference| of any pixel and channel */
    int max_x, max_y, max_channel;  /* where (from the bottom-left, as the renderer counts) */
    double tolerance;            /* params' tolerance ... */
    long tie_pixels;             /* ... and how many pixels may exceed it */
} verdict;

/* Compares cand with ref (same size). Fills out (free with verdict_free); PL_ERR_INVALID with a
 * message for mismatched sizes, PL_ERR_NOMEM when out of memory. A bad pixel fails the case. */
pl_status verdict_compute(const verdict_image *cand, const verdict_image *ref, const verdict_params *p,
                          verdict *out, pl_diag *diag);
void verdict_free(verdict *v);  /* NULL-safe */

/* The candidate's noise against the reference's, for a fixed-rate case rendered with the same flags:
 * per pixel, the candidate's per-sample variance (its mean's variance times its samples, summed
 * over channels) over the reference's, capped at VERDICT_NOISE_CAP, averaged over the pixels where
 * the reference varies. About 1 for a render whose samples are as noisy as the course's (a little
 * below: a variance estimated from few samples of a skewed radiance is more often low than high);
 * the cap keeps one firefly from deciding it (an uncapped ratio of sums varied by 20% between
 * seeds). Both variances come from the framework's sums of the samples (the film), never from a
 * number student code reports. A render that reuses one light sample for all -l, or spends the
 * light samples where the course does not, is unbiased but noisier: its means pass, this ratio does
 * not (grader/grade_image.c judges it against GRADE_NOISE_FACTOR). NAN when the reference has no
 * variance at all. */
#define VERDICT_NOISE_CAP 4.0
double verdict_noise_ratio(const verdict_image *cand, const verdict_image *ref, int cand_spp, int ref_spp);

#endif
