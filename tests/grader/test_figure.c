/* Test machinery: not part of any assignment.
 * What reaches the student (grader/grade_figure.h, grade_words.c): every figure a render decides
 * is rounded to 3 significant digits and clamped before it is shown, and a hidden case shows only
 * its verdict and a coarse mean ratio. A render that reads a secret could otherwise spell it in the
 * low digits of a double the report prints. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_figure.h"
#include "../../grader/grade_report.h"
#include "../../grader/grade_result.h"
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

SCRATCH_FOLDER(scratch, "figure-test")

/* Three significant digits in decimal, the course's range, the floor; NaN kept, infinities clamped. */
static void test_figure__rounded_to_three_digits_and_clamped(void **state)
{
    (void)state;
    assert_true(grade_figure(1.2345678901234567, 3, 0.0, 1000.0) == 1.23);
    assert_true(grade_figure(0.000123456, 3, 0.0, 1.0) == 0.000123);
    assert_true(grade_figure(999.96, 3, 0.0, 1000.0) == 1000.0);
    assert_true(grade_figure(12345.6, 3, 0.0, 1000.0) == 1000.0);
    assert_true(grade_figure(-7.5, 3, 0.0, 1000.0) == 0.0);
    assert_true(grade_figure(-7.5432, 3, -1000.0, 1000.0) == -7.54);
    assert_true(grade_figure(INFINITY, 3, 0.0, 1e6) == 1e6);
    assert_true(grade_figure(-INFINITY, 3, -1000.0, 1000.0) == -1000.0);
    assert_true(grade_figure(1e-7, 3, 0.0, 1.0) == 0.0);  /* below GRADE_FIGURE_FLOOR */
    assert_true(isnan(grade_figure(NAN, 3, 0.0, 1000.0)));
    assert_true(grade_figure(0.0123456, 2, 0.0, 10.0) == 0.012);
    /* Counts and pixels: rounded and clamped to the image (the course's size). */
    assert_int_equal(grade_figure_count(12748, 19200), 12700);
    assert_int_equal(grade_figure_count(1L << 40, 19200), 19200);
    assert_int_equal(grade_figure_count(-3, 19200), 0);
    assert_int_equal(grade_figure_pixel(160, 160), 159);
    assert_int_equal(grade_figure_pixel(-1, 160), 0);
    assert_int_equal(grade_figure_pixel(42, 160), 42);
}

/* A unit test's message about the candidate's answers: its numbers rounded, its places kept. */
static void test_figure__a_test_message_shows_rounded_numbers(void **state)
{
    (void)state;
    char out[256];
    grade_figure_text("tests/part3/test_direct.c:123: bsdf_f: wrong: expected 0.318309886, got 0.12345678901234 "
                      "(tolerance 1e-05)", out, sizeof out);
    assert_string_equal(out, "tests/part3/test_direct.c:123: bsdf_f: wrong: expected 0.318, got 0.123 (tolerance 1e-05)");
    /* Wide whole numbers and hexadecimal ones carry bytes too; names with digits stay as they are. */
    grade_figure_text("part2 visited 1234567 nodes of vec3 table, flags 0x1122334455667788 or 0x5", out, sizeof out);
    assert_string_equal(out, "part2 visited 1230000 nodes of vec3 table, flags 0x... or 0x5");
    /* A count stays written as a count (the same three digits); a longer one goes to the exponent. */
    grade_figure_text("30 of 20000 rays, 11283 of 19200 pixels, 12345678901 bytes", out, sizeof out);
    assert_string_equal(out, "30 of 20000 rays, 11300 of 19200 pixels, 1.23e+10 bytes");
    /* Cut at a character, never inside one, and never past the buffer. */
    grade_figure_text("\xc3\xa9t\xc3\xa9 1.23456", out, 4);
    assert_string_equal(out, "\xc3\xa9t");
}

/* results.json's text of one case: its "output". */
static char *case_output(const char *path, int index)
{
    json_error_t err;
    json_t *j = json_load_file(path, 0, &err);
    assert_non_null(j);
    const char *o = json_string_value(json_object_get(json_array_get(json_object_get(j, "tests"), (size_t)index), "output"));
    assert_non_null(o);
    char *copy = strdup(o);
    json_decref(j);
    return copy;
}

/* A failing case's figures, as a forged render would choose them (every digit a message): the
 * public case shows them rounded, the hidden one shows its verdict and a 2-digit mean ratio alone. */
static void test_report__figures_rounded_and_a_hidden_case_a_verdict_alone(void **state)
{
    (void)state;
    static grade_result res;
    static grade_case cases[2];
    memset(&res, 0, sizeof res);
    res.num_parts = 1;
    grade_part_result *p = &res.parts[0];
    p->part = 1;
    p->num_cases = 2;
    for (int i = 0; i < 2; i++) {
        snprintf(cases[i].name, sizeof cases[i].name, "case%d", i);
        cases[i].width = 160, cases[i].height = 120, cases[i].hidden = i == 1;
        grade_case_result *c = &p->cases[i];
        c->spec = &cases[i];
        c->ran = true;
        c->v.p_value = 1.2345678901234567e-5;
        c->v.alpha = 1e-3;
        c->v.rel_mse = 0.012345678901234567;
        c->v.ratio[0] = 1.0123456789012345, c->v.ratio[1] = 2.7182818284590452, c->v.ratio[2] = 1e300;
        c->v.blocks_x = 10, c->v.blocks_y = 7;
        c->v.worst_block_x = 3, c->v.worst_block_y = 4, c->v.worst_t = 6.283185307179586;
        c->v.bad_pixels = 12748, c->v.bad_x = 99999, c->v.bad_y = 5;
    }
    char path[256];
    pl_diag d = pl_diag_default();
    snprintf(path, sizeof path, "%s/results.json", scratch);
    assert_int_equal(PL_OK, grade_report_results_json(&res, path, &d));
    char *shown = case_output(path, 1), *hidden = case_output(path, 2);
    print_message("public: %s\nhidden: %s\n", shown, hidden);
    assert_non_null(strstr(shown, "p-value 1.23e-05"));
    assert_non_null(strstr(shown, "mean ratio red 1.01 green 2.72 blue 1e+03."));
    assert_non_null(strstr(shown, "12700 pixels"));
    assert_non_null(strstr(shown, "x=159 y=5"));
    assert_null(strstr(shown, "1.0123"));
    assert_null(strstr(shown, "2.718"));
    assert_null(strstr(shown, "6.28"));
    /* A hidden case shows its verdict alone: not one figure of its render (no digit at all). */
    assert_non_null(strstr(hidden, "**fails** (a hidden case: its verdict alone is shown)"));
    assert_null(strpbrk(hidden, "0123456789"));
    assert_null(strstr(hidden, "p-value"));
    assert_null(strstr(hidden, "x="));
    assert_null(strstr(hidden, "block"));
    assert_null(strstr(hidden, "relMSE"));
    assert_null(strstr(hidden, "1.23"));
    free(shown);
    free(hidden);
    assert_int_equal(PL_OK, grade_report_html(&res, scratch, &d));
}

int figure_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_figure__rounded_to_three_digits_and_clamped),
        cmocka_unit_test(test_figure__a_test_message_shows_rounded_numbers),
        cmocka_unit_test_setup_teardown(test_report__figures_rounded_and_a_hidden_case_a_verdict_alone, scratch_setup,
                                        scratch_teardown),
    };
    return cmocka_run_group_tests_name("figure", tests, NULL, NULL);
}
