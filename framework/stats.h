/* Statistics shared by the tests and the grader: running means and variances, Student's t test, Pearson's
 * chi-square test with pooling of sparse bins, the Sidak correction that keeps a whole suite's
 * false-alarm rate at its stated alpha, and relMSE, the image error the grader and imgtool report. The special functions are written from their textbook
 * definitions (series and continued fractions); see stats.c.
 * Parts may not call: any function declared here but the static inline ones (the grader refuses them). */
#ifndef PL_STATS_H
#define PL_STATS_H

#include <stdbool.h>
#include "vec.h"

/* ---- running moments (Welford): stable in one pass --------------------------------------- */
typedef struct { long n; double mean, m2; } stats_acc;

static inline stats_acc stats_acc_make(void) { stats_acc a = {0, 0.0, 0.0}; return a; }
void stats_acc_add(stats_acc *a, double x);
double stats_acc_var(const stats_acc *a);  /* sample variance (n - 1); 0 for n < 2 */
double stats_acc_sem(const stats_acc *a);  /* standard error of the mean */

/* ---- special functions ------------------------------------------------------------------- */
double stats_gamma_p(double a, double x);      /* regularized lower incomplete gamma P(a, x) */
double stats_gamma_q(double a, double x);      /* 1 - P(a, x) */
double stats_beta_inc(double a, double b, double x);  /* regularized incomplete beta I_x(a, b) */
double stats_chi2_sf(double x, double dof);    /* P(X >= x), X ~ chi-square(dof) */
double stats_t_sf2(double t, double dof);      /* P(|T| >= |t|), T ~ Student t(dof) */
double stats_t_quantile2(double p, double dof);/* the t with stats_t_sf2(t, dof) = p */

/* Sidak: the per-check level that keeps the chance of any false alarm among m independent checks
 * at family_alpha: 1 - (1 - family_alpha)^(1/m). */
double stats_sidak(double family_alpha, int m);

/* ---- tests ------------------------------------------------------------------------------- */
typedef struct {
    double stat;    /* t or chi-square */
    double dof;
    double p;       /* p-value */
    bool reject;    /* p < alpha */
} stats_result;

/* One-sample two-sided t test of mean == mu. A mean within 1e-5 (1 + |mu|) of mu always passes
 * (an exact estimator's variance is only rounding), and a sample without variance must be that
 * close. */
stats_result stats_ttest_mean(const stats_acc *a, double mu, double alpha);
/* Welch's two-sample two-sided t test of equal means. */
stats_result stats_ttest_two(const stats_acc *a, const stats_acc *b, double alpha);
/* Pearson's chi-square goodness of fit. Bins with expected count < min_expected are pooled
 * (smallest first) until each pooled bin reaches it; dof = bins after pooling - 1. */
stats_result stats_chi2_test(const double *observed, const double *expected, int bins,
                             double min_expected, double alpha);
/* Exact two-sided binomial test: the p-value of k successes in n trials of probability p, twice the
 * smaller tail (P(X <= k), P(X >= k)), at most 1. Rejecting when it is below alpha fails a correct
 * proportion with probability at most alpha, at any n (no normal approximation). */
double stats_binomial_p2(long k, long n, double p);

/* ---- image error --------------------------------------------------------------------------- */
/* One value's share of relMSE: (c - r)^2 / (r^2 + 0.01), the squared error relative to the
 * reference's brightness; the 0.01 keeps black reference pixels from dividing by zero. */
static inline double stats_rel_se(double c, double r) { return (c - r) * (c - r) / (r * r + 0.01); }
/* relMSE of count values (e.g. 3 x pixels of rgb): the mean of stats_rel_se; 0 for count 0. */
double stats_rel_mse(const float *candidate, const float *reference, long count);

#endif
