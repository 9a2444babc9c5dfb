/* Test machinery: not part of any assignment. RNG streams: determinism and independence.
 * The generator is deterministic, so these checks use fixed seeds and cannot flake; the
 * uniformity check is a chi-square at alpha = 1e-6 on one fixed stream (a regression guard). */
#include "../common/test.h"
#include "../../framework/rng.h"

static void test_rng_for_sample__same_inputs_same_stream(void **state)
{
    rng a = rng_for_sample(7, 1234, 5), b = rng_for_sample(7, 1234, 5);
    for (int i = 0; i < 100; i++) assert_int_equal(rng_u32(&a), rng_u32(&b));
}

static void test_rng_for_sample__neighbours_differ(void **state)
{
    /* Adjacent pixels, adjacent samples and adjacent seeds must not share their first outputs. */
    uint32_t first[4];
    rng g[4] = {rng_for_sample(0, 10, 0), rng_for_sample(0, 11, 0), rng_for_sample(0, 10, 1), rng_for_sample(1, 10, 0)};
    for (int i = 0; i < 4; i++) first[i] = rng_u32(&g[i]);
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++) assert_int_not_equal(first[i], first[j]);
}

static void test_rng_uniform__in_unit_interval_and_flat(void **state)
{
    enum { BINS = 16, N = 160000 };
    int count[BINS] = {0};
    rng g = rng_seeded(42, 0);
    for (int i = 0; i < N; i++) {
        float u = rng_uniform(&g);
        assert_true(u >= 0.0f && u < 1.0f);
        count[(int)(u * BINS)]++;
    }
    double expected = (double)N / BINS, chi2 = 0;
    for (int b = 0; b < BINS; b++) chi2 += (count[b] - expected) * (count[b] - expected) / expected;
    /* 15 degrees of freedom: the 1 - 1e-6 quantile is about 52.6. */
    if (chi2 > 52.6) fail_msg("rng_uniform is not flat: chi-square %.1f > 52.6 over %d bins", chi2, BINS);
}

int rng_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rng_for_sample__same_inputs_same_stream),
        cmocka_unit_test(test_rng_for_sample__neighbours_differ),
        cmocka_unit_test(test_rng_uniform__in_unit_interval_and_flat),
    };
    return cmocka_run_group_tests_name("rng", tests, NULL, NULL);
}
