/* Grader machinery: not part of any assignment.
 * The image verdict of one grading case: is a candidate render the reference image, up to Monte
 * Carlo noise? The grader reads both images from files (never from what student code prints) and
 * calls verdict_compute in its own process.
 *
 * The statistic: per block of pixels and per channel, a paired test on the pixel differences
 * d = candidate - reference: Johnson's t for skewed populations (verdict.c, paired_p), that is
 * mean(d) / (sd(d) / sqrt(m)) plus a correction for the skew of d, with m - 1 degrees of freedom;
 * plus the same test over the whole image (the most powerful one for a global factor such as 2 or
 * pi).
 * Why this statistic:
 * - it needs no variance from the candidate's file: the spread of d across the block's pixels
 *   estimates the noise of both renders, so a submission that forges its variance channel cannot
 *   buy a pass;
 * - pixels draw from independent RNG streams, so the d of one block are independent, as the test
 *   assumes; pixels differ in variance, which a sum over many pixels tolerates (the block variance
 *   is their average);
 * - radiance at few samples is heavy-tailed and skewed (rare bright paths): Johnson's correction
 *   takes the first-order effect of the skew out, and a t test is trustworthy only when a block
 *   holds many samples, so blocks are sized to hold at least min_block_samples candidate samples
 *   (and min_block_pixels pixels), never a fixed 8x8.
 * (With known_variance, a z test against the reference's variance instead: verdict_params.)
 * The p-values of all K tests are combined with Sidak: the case p-value is 1 - (1 - p_min)^K, uniform
 * on [0, 1] for a correct render, and the case fails when it is below family_alpha. */
#ifndef PL_VERDICT_H
#define PL_VERDICT_H

#include <stdbool.h>
#include "../framework/status.h"

typedef struct {
    int width, height;
    const float *rgb;  /* width * height * 3 linear means, top row first; not owned */
    const float *var;  /* the same layout: each mean's variance (the reference's; NULL if unknown) */
} verdict_image;

typedef struct {
    double family_alpha;    /* chance a correct render fails the case (1e-3) */
    int candidate_spp;      /* samples per pixel of the candidate render (sizes the blocks) */
    int min_block_pixels;   /* at least this many pixels per block (64) */
    long min_block_samples; /* at least this many candidate samples per block (8192) */
    /* Known variance: test each block's sum of differences against the variance the reference
     * predicts (ref->var, scaled to the candidate's samples: reference_spp / candidate_spp + 1),
     * a z test, instead of the paired t test's spread. For images whose differences are mostly
     * exactly zero (normal shading: only edge pixels vary), where the spread of a few pixels makes
     * a poor estimate and t with m - 1 degrees of freedom rejects far too often. */
    bool known_variance;
    int reference_spp;
    /* The case is lit at grazing angles (its "grazing" field): a candidate that fails dark there
     * gets the self-shadowing hint (issue 22: rays that start at the raw hit point hit their own
     * surface, which darkens exactly where light grazes it). */
    bool grazing;
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
    char hint[200];              /* a likely cause when the ratio matches a known mistake, else "" */
} verdict;

/* Compares cand with ref (same size). Fills out (free with verdict_free); PL_ERR_INVALID with a
 * message for mismatched sizes, PL_ERR_NOMEM when out of memory. A bad pixel fails the case. */
pl_status verdict_compute(const verdict_image *cand, const verdict_image *ref, const verdict_params *p,
                          verdict *out, pl_diag *diag);
void verdict_free(verdict *v);  /* NULL-safe */

#endif
