/* Test machinery: not part of any assignment. The class grader's escaping (course/class/class_text.h):
 * every name a submission brings reaches the grade book and the report only through these. */
#include "../../tests/common/test.h"  /* a test suite (make test-course), so it shares the suites' asserts */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "class_text.h"

/* What a writer (class_text_html, class_text_csv) writes for s. */
static char *written(void (*writer)(FILE *, const char *), const char *s)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    writer(f, s);
    fclose(f);
    return text;
}

static void assert_shown(const char *in, size_t size, const char *want)
{
    char out[256];
    assert_true(size <= sizeof out);
    assert_string_equal(want, class_text_shown(in, strlen(in), out, size));
}

static void test_class_text__shown_escapes_what_is_not_plain_text(void **state)
{
    assert_shown("alice", 256, "alice");
    assert_shown("caf\xc3\xa9", 256, "caf\xc3\xa9");           /* valid UTF-8 stays */
    assert_shown("caf\xe9", 256, "caf\\xE9");                   /* Latin-1: not UTF-8 */
    assert_shown("a\nb\tc\x7f", 256, "a\\x0Ab\\x09c\\x7F");    /* control characters */
    assert_shown("back\\slash", 256, "back\\\\slash");         /* so no name shows as another's escape */
    assert_shown("x\xe2\x80\xaey", 256, "x\\u202Ey");          /* a right-to-left override */
    assert_shown("x\xc2\x85y", 256, "x\\u0085y");              /* a C1 control */
    assert_shown("\xc3", 256, "\\xC3");                        /* a character cut short */
}

static void test_class_text__shown_never_cuts_an_escape_or_a_character(void **state)
{
    assert_shown("\xff\xff", 6, "\\xFF");           /* room for one escape and the NUL */
    assert_shown("a\xc3\xa9", 3, "a");              /* "é" would need 2 more bytes than fit */
    assert_shown("abc", 1, "");
}

static void test_class_text__html_escapes_markup(void **state)
{
    char *out = written(class_text_html, "<img src=\"x\" onerror='y'>&");
    assert_string_equal("&lt;img src=&quot;x&quot; onerror=&#39;y&#39;&gt;&amp;", out);
    free(out);
}

static void test_class_text__csv_quotes_and_neutralises_formulas(void **state)
{
    static const char *const cases[][2] = {
        {"plain", "\"plain\""},         {"Doe, Alice", "\"Doe, Alice\""}, {"a\"b", "\"a\"\"b\""},
        {"=1+1", "\"'=1+1\""},         {"+cmd", "\"'+cmd\""},            {"-2", "\"'-2\""},
        {"@SUM(A1)", "\"'@SUM(A1)\""}, {"", "\"\""},                     {"7.5", "\"7.5\""},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *out = written(class_text_csv, cases[i][0]);
        if (strcmp(out, cases[i][1])) fail_msg("%s: expected %s, got %s", cases[i][0], cases[i][1], out);
        free(out);
    }
}

static void test_class_text__numbers_print_at_most_two_decimals(void **state)
{
    char n[32];
    assert_string_equal("7.5", class_text_number(7.5, n, sizeof n));
    assert_string_equal("10", class_text_number(10.0, n, sizeof n));
    assert_string_equal("0.33", class_text_number(1.0 / 3.0, n, sizeof n));
    assert_string_equal("0", class_text_number(-0.0, n, sizeof n));
    assert_string_equal("0", class_text_number(0.0 / 0.0, n, sizeof n));
}

int class_text_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_class_text__shown_escapes_what_is_not_plain_text),
        cmocka_unit_test(test_class_text__shown_never_cuts_an_escape_or_a_character),
        cmocka_unit_test(test_class_text__html_escapes_markup),
        cmocka_unit_test(test_class_text__csv_quotes_and_neutralises_formulas),
        cmocka_unit_test(test_class_text__numbers_print_at_most_two_decimals),
    };
    return cmocka_run_group_tests_name("class_text", tests, NULL, NULL);
}
