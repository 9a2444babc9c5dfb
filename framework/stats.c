/* Statistics (see stats.h).
 * The special functions follow their definitions:
 *   P(a, x) = x^a e^-x / Gamma(a+1) * sum_k x^k / ((a+1)...(a+k))          (series, x < a + 1)
 *   Q(a, x) = x^a e^-x / Gamma(a) * 1 / (x + 1 - a - 1(1-a) / (x + 3 - a - 2(2-a) / ...))
 *                                                                    (continued fraction, x >= a+1)
 *   I_x(a, b) = x^a (1-x)^b / (a B(a, b)) * 1 / (1 + d1 / (1 + d2 / (1 + ...))),
 *     d_2m+1 = -(a+m)(a+b+m) x / ((a+2m)(a+2m+1)),  d_2m = m(b-m) x / ((a+2m-1)(a+2m)),
 *   used directly for x < (a+1)/(a+b+2) and through I_x(a,b) = 1 - I_{1-x}(b,a) otherwise.
 * Continued fractions are evaluated forwards with the modified Lentz method. Student's t tail is
 * P(|T| >= t) = I_{dof/(dof+t^2)}(dof/2, 1/2). */
#include "stats.h"
#include <math.h>
#include <stdlib.h>

#define TINY 1e-300
#define CF_EPS 1e-15
#define CF_MAX_ITER 10000

/* ---- running moments ------------------------------------------------------------------------- */

/* Welford: the mean and the sum of squared deviations updated together, so no large sums of squares
 * cancel (a naive sum(x^2) - n mean^2 loses every digit for values far from zero). */
void stats_acc_add(stats_acc *a, double x)
{
    a->n++;
    double d = x - a->mean;
    a->mean += d / (double)a->n;
    a->m2 += d * (x - a->mean);
}

double stats_acc_var(const stats_acc *a) { return a->n > 1 ? fmax(0.0, a->m2 / (double)(a->n - 1)) : 0.0; }
double stats_acc_sem(const stats_acc *a) { return a->n > 0 ? sqrt(stats_acc_var(a) / (double)a->n) : 0.0; }

/* ---- special functions ------------------------------------------------------------------------- */

/* The series of P(a, x): converges fast below a + 1, where the continued fraction would not. */
static double gamma_series(double a, double x)
{
    double term = 1.0 / a, sum = term;
    for (int k = 1; k < CF_MAX_ITER; k++) {
        term *= x / (a + k);
        sum += term;
        if (fabs(term) < fabs(sum) * CF_EPS)
            break;
    }
    return sum * exp(a * log(x) - x - lgamma(a));
}

/* Lentz on the even form b0 + a1/(b1 + a2/(b2 + ...)) with b_k = x + 2k + 1 - a, a_k = -k(k - a). */
static double gamma_cfrac(double a, double x)
{
    double b = x + 1.0 - a;
    double c = 1.0 / TINY, d = 1.0 / b, h = d;
    for (int k = 1; k < CF_MAX_ITER; k++) {
        double an = -k * (k - a);
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < TINY) d = TINY;
        c = b + an / c;
        if (fabs(c) < TINY) c = TINY;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (fabs(delta - 1.0) < CF_EPS)
            break;
    }
    return h * exp(a * log(x) - x - lgamma(a));
}

double stats_gamma_p(double a, double x)
{
    if (x <= 0.0) return 0.0;
    return x < a + 1.0 ? gamma_series(a, x) : 1.0 - gamma_cfrac(a, x);
}

double stats_gamma_q(double a, double x)
{
    if (x <= 0.0) return 1.0;
    return x < a + 1.0 ? 1.0 - gamma_series(a, x) : gamma_cfrac(a, x);
}

/* The continued fraction 1 / (1 + d1 / (1 + d2 / ...)) of the incomplete beta, by Lentz. */
static double beta_cfrac(double a, double b, double x)
{
    double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
    if (fabs(d) < TINY) d = TINY;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m < CF_MAX_ITER; m++) {
        double even = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
        double odd = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
        for (int half = 0; half < 2; half++) {
            double dm = half == 0 ? even : odd;
            d = 1.0 + dm * d;
            if (fabs(d) < TINY) d = TINY;
            c = 1.0 + dm / c;
            if (fabs(c) < TINY) c = TINY;
            d = 1.0 / d;
            h *= d * c;
        }
        if (fabs(d * c - 1.0) < CF_EPS)
            break;
    }
    return h;
}

double stats_beta_inc(double a, double b, double x)
{
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    double log_front = lgamma(a + b) - lgamma(a) - lgamma(b) + a * log(x) + b * log1p(-x);
    if (x < (a + 1.0) / (a + b + 2.0))
        return exp(log_front) * beta_cfrac(a, b, x) / a;
    return 1.0 - exp(log_front) * beta_cfrac(b, a, 1.0 - x) / b;
}

double stats_chi2_sf(double x, double dof) { return stats_gamma_q(0.5 * dof, 0.5 * x); }

double stats_t_sf2(double t, double dof)
{
    if (!isfinite(t)) return 0.0;
    return stats_beta_inc(0.5 * dof, 0.5, dof / (dof + t * t));
}

/* Bisection on the tail, which falls monotonically in |t|: slow, but only tests call it. */
double stats_t_quantile2(double p, double dof)
{
    double lo = 0.0, hi = 1.0;
    while (stats_t_sf2(hi, dof) > p && hi < 1e12)
        hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if (stats_t_sf2(mid, dof) > p) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

double stats_sidak(double family_alpha, int m)
{
    return -expm1(log1p(-family_alpha) / (double)(m > 0 ? m : 1));
}

/* ---- tests ----------------------------------------------------------------------------------------- */

stats_result stats_ttest_mean(const stats_acc *a, double mu, double alpha)
{
    stats_result r = {0.0, (double)(a->n - 1), 1.0, false};
    double sem = stats_acc_sem(a);
    /* Agreement to float precision passes whatever the variance: an exact estimator (cosine
     * sampling's weight, a delta light) has a variance made only of rounding. */
    if (fabs(a->mean - mu) <= 1e-5 * (1.0 + fabs(mu)))
        return r;
    if (!(sem > 0.0)) {
        r.reject = !(fabs(a->mean - mu) <= 1e-5 * (1.0 + fabs(mu)));
        r.p = r.reject ? 0.0 : 1.0;
        r.stat = r.reject ? INFINITY : 0.0;
        return r;
    }
    /* The t statistic with n - 1 degrees of freedom, and its two-sided tail. */
    r.stat = (a->mean - mu) / sem;
    r.p = stats_t_sf2(r.stat, r.dof);
    r.reject = r.p < alpha;
    return r;
}

stats_result stats_ttest_two(const stats_acc *a, const stats_acc *b, double alpha)
{
    stats_result r = {0.0, 1.0, 1.0, false};
    double va = stats_acc_var(a) / (double)a->n, vb = stats_acc_var(b) / (double)b->n;
    double se2 = va + vb;
    if (!(se2 > 0.0)) {
        r.reject = !(fabs(a->mean - b->mean) <= 1e-5 * (1.0 + fabs(a->mean)));
        r.p = r.reject ? 0.0 : 1.0;
        return r;
    }
    r.stat = (a->mean - b->mean) / sqrt(se2);
    /* Welch-Satterthwaite degrees of freedom; a side without variance contributes nothing. */
    double den = (a->n > 1 ? va * va / (double)(a->n - 1) : 0.0) + (b->n > 1 ? vb * vb / (double)(b->n - 1) : 0.0);
    r.dof = den > 0.0 ? se2 * se2 / den : 1.0;
    r.p = stats_t_sf2(r.stat, r.dof);
    r.reject = r.p < alpha;
    return r;
}

typedef struct { double obs, exp; } bin_pair;

static int by_expected(const void *pa, const void *pb)
{
    double a = ((const bin_pair *)pa)->exp, b = ((const bin_pair *)pb)->exp;
    return (a > b) - (a < b);
}

stats_result stats_chi2_test(const double *observed, const double *expected, int bins,
                             double min_expected, double alpha)
{
    stats_result r = {0.0, 0.0, 1.0, false};
    bin_pair *v = malloc(sizeof *v * (size_t)(bins > 0 ? bins : 1));
    if (!v) { r.reject = true; r.p = 0.0; return r; }
    /* Sparsest bins first, so pooling joins the bins whose counts are too small to trust alone. */
    for (int i = 0; i < bins; i++) { v[i].obs = observed[i]; v[i].exp = expected[i]; }
    qsort(v, (size_t)bins, sizeof *v, by_expected);

    /* Pool the sparsest bins together until the pool is large enough to count as one bin. An
     * observation where nothing is expected is an outright failure (the sampler leaves its pdf). */
    int groups = 0;
    double pool_obs = 0.0, pool_exp = 0.0, chi2 = 0.0;
    for (int i = 0; i < bins; i++) {
        if (v[i].exp <= 0.0 && v[i].obs > 0.0) {
            free(v);
            r.stat = INFINITY; r.p = 0.0; r.reject = true;
            return r;
        }
        pool_obs += v[i].obs;
        pool_exp += v[i].exp;
        if (pool_exp >= min_expected) {
            chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
            groups++;
            pool_obs = pool_exp = 0.0;
        }
    }
    if (pool_exp > 0.0 || pool_obs > 0.0) {  /* leftovers: fold into the chi-square as one more bin */
        double e = pool_exp > 0.0 ? pool_exp : 1e-12;
        chi2 += (pool_obs - e) * (pool_obs - e) / e;
        groups++;
    }
    free(v);
    r.stat = chi2;
    r.dof = groups - 1;
    r.p = r.dof > 0 ? stats_chi2_sf(chi2, r.dof) : 1.0;
    r.reject = r.p < alpha;
    return r;
}

double stats_binomial_p2(long k, long n, double p)
{
    /* The tails through the incomplete beta: P(X <= k) = I_{1-p}(n - k, k + 1), P(X >= k) = I_p(k, n - k + 1). */
    double lower = k >= n ? 1.0 : stats_beta_inc((double)(n - k), (double)k + 1.0, 1.0 - p);
    double upper = k <= 0 ? 1.0 : stats_beta_inc((double)k, (double)(n - k) + 1.0, p);
    double two = 2.0 * (lower < upper ? lower : upper);
    return two < 1.0 ? two : 1.0;
}

/* ---- image error ---------------------------------------------------------------------------- */

double stats_rel_mse(const float *candidate, const float *reference, long count)
{
    double sum = 0.0;
    for (long i = 0; i < count; i++) sum += stats_rel_se(candidate[i], reference[i]);
    return count > 0 ? sum / (double)count : 0.0;
}
