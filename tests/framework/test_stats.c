/* Test machinery: not part of any assignment.
 * The special functions under every statistical test (framework/stats.c), checked against table
 * values. Sources: the closed forms P(1, x) = 1 - e^-x, P(1/2, x) = erf(sqrt x),
 * I_x(1/2, 1/2) = (2 / pi) asin(sqrt x), and the finite sums for integer a, b (Abramowitz & Stegun
 * 6.5.13 and 26.5.4, evaluated in Python); the chi-square and Student t critical values of
 * Abramowitz & Stegun tables 26.8 and 26.10, to the digits scipy.stats gives (chi2.isf, t.isf,
 * norm.isf), re-checked with mpmath at 30 digits. */
#include "../common/test.h"
#include "../../framework/stats.h"
#include <math.h>

static void test_stats_gamma_p__matches_closed_forms(void **state)
{
    (void)state;
    PL_CHECK_NEAR(0.6321205588285577, stats_gamma_p(1.0, 1.0), 1e-12);   /* 1 - e^-1 */
    PL_CHECK_NEAR(0.9544997361036416, stats_gamma_p(0.5, 2.0), 1e-12);   /* erf(sqrt 2) */
    PL_CHECK_NEAR(0.18473675547622792, stats_gamma_p(5.0, 3.0), 1e-12);  /* A&S 6.5.13 */
    PL_CHECK_NEAR(0.06985366069940976, stats_gamma_q(10.0, 15.0), 1e-12);
    PL_CHECK_NEAR(0.34003677030571729, stats_gamma_p(3.5, 2.5), 1e-12);  /* mpmath gammainc */
    PL_CHECK_NEAR(0.24680203440017027, stats_gamma_p(50.0, 45.0), 1e-10);
    PL_CHECK_NEAR(1.0, stats_gamma_p(2.0, 7.0) + stats_gamma_q(2.0, 7.0), 1e-14);
}

static void test_stats_beta_inc__matches_closed_forms(void **state)
{
    (void)state;
    PL_CHECK_NEAR(0.5248, stats_beta_inc(2.0, 3.0, 0.4), 1e-12);                 /* A&S 26.5.4 */
    PL_CHECK_NEAR(0.36901011956554536, stats_beta_inc(0.5, 0.5, 0.3), 1e-12);    /* (2/pi) asin sqrt x */
    PL_CHECK_NEAR(0.36749651990402307, stats_beta_inc(2.5, 7.0, 0.2), 1e-12);    /* mpmath betainc */
    PL_CHECK_NEAR(0.0, stats_beta_inc(2.0, 3.0, 0.0), 0.0);
    PL_CHECK_NEAR(1.0, stats_beta_inc(2.0, 3.0, 1.0), 0.0);
}

static void test_stats_binomial_p2__matches_exact_sums(void **state)
{
    /* Twice the smaller tail, summed exactly in rational arithmetic (Python fractions). */
    PL_CHECK_NEAR(0.34375, stats_binomial_p2(3, 10, 0.5), 1e-12);
    PL_CHECK_NEAR(0.001953125, stats_binomial_p2(0, 10, 0.5), 1e-12);
    PL_CHECK_NEAR(0.001953125, stats_binomial_p2(10, 10, 0.5), 1e-12);
    PL_CHECK_NEAR(0.007560310459460499, stats_binomial_p2(950, 4096, 0.25), 1e-10);
    PL_CHECK_NEAR(0.0006379692244483967, stats_binomial_p2(1120, 4096, 0.25), 1e-11);
    PL_CHECK_NEAR(1.0, stats_binomial_p2(1024, 4096, 0.25), 0.0);
}

static void test_stats_chi2_sf__matches_the_table(void **state)
{
    (void)state;
    PL_CHECK_NEAR(0.05, stats_chi2_sf(3.841458820694124, 1.0), 1e-12);   /* A&S table 26.8 */
    PL_CHECK_NEAR(0.05, stats_chi2_sf(18.307038053275146, 10.0), 1e-12);
}

static void test_stats_t__quantiles_match_the_table(void **state)
{
    (void)state;
    PL_CHECK_NEAR(0.05, stats_t_sf2(2.228138851964938, 10.0), 1e-9);     /* A&S table 26.10 */
    PL_CHECK_NEAR(2.228138851964938, stats_t_quantile2(0.05, 10.0), 1e-9);
    PL_CHECK_NEAR(4.032142983557536, stats_t_quantile2(0.01, 5.0), 1e-9);
    /* Many degrees of freedom: the normal quantiles (A&S 26.2.23's table; Python's NormalDist). */
    PL_CHECK_NEAR(1.9599639845400536, stats_t_quantile2(0.05, 1e9), 1e-6);
    PL_CHECK_NEAR(3.89059188641312, stats_t_quantile2(1e-4, 1e9), 1e-6);
}

static void test_stats_sidak__keeps_the_family_rate(void **state)
{
    (void)state;
    double a = stats_sidak(1e-3, 48);
    PL_CHECK_NEAR(1e-3, 1.0 - pow(1.0 - a, 48), 1e-12);
    PL_CHECK_NEAR(1e-3, stats_sidak(1e-3, 1), 1e-18);
}

/* relMSE by hand: (c - r)^2 / (r^2 + 0.01) per value, averaged; a black reference divides by 0.01. */
static void test_stats_rel_mse__matches_the_definition(void **state)
{
    (void)state;
    const float cand[4] = {1.0f, 0.5f, 0.1f, 2.0f}, ref[4] = {1.0f, 1.0f, 0.0f, 1.0f};
    double want = (0.0 + 0.25 / 1.01 + 0.01 / 0.01 + 1.0 / 1.01) / 4.0;
    PL_CHECK_NEAR(want, stats_rel_mse(cand, ref, 4), 1e-6);  /* 0.1f is not 0.1 */
    PL_CHECK_NEAR(0.0, stats_rel_mse(cand, ref, 0), 0.0);
}

int stats_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stats_gamma_p__matches_closed_forms),
        cmocka_unit_test(test_stats_beta_inc__matches_closed_forms),
        cmocka_unit_test(test_stats_binomial_p2__matches_exact_sums),
        cmocka_unit_test(test_stats_chi2_sf__matches_the_table),
        cmocka_unit_test(test_stats_t__quantiles_match_the_table),
        cmocka_unit_test(test_stats_sidak__keeps_the_family_rate),
        cmocka_unit_test(test_stats_rel_mse__matches_the_definition),
    };
    return cmocka_run_group_tests_name("framework: test statistics (framework/stats.c)", tests, NULL, NULL);
}
