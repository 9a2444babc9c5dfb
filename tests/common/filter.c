/* Test machinery: not part of any assignment.
 * One test at a time: `make test-part3 FILTER=name` runs only the tests whose name matches
 * (cmocka's pattern: * and ? wildcards, e.g. FILTER='*hemisphere*'); `make test-part3 LIST=1`
 * lists a suite's tests (with FILTER: the matching ones). The Makefile passes FILTER as
 * $PL_TEST_FILTER and LIST as $PL_TEST_LIST, and the suite's name as $PL_TEST_SUITE. Every group runs through pl_run_group (test.h
 * redefines cmocka_run_group_tests_name), so no suite's main() needs to know:
 * - a group with no matching test prints nothing;
 * - a FILTER that matches no test of the suite fails the suite (a typo must not look green),
 *   unless $PL_TEST_MATCHED names a file: then `make test` judges over all suites, and a suite
 *   with a match creates that file. */
#include "test.h"
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static const char *pattern;  /* NULL: no filter */
static bool listing;
static int matched;          /* tests of the suite that match the filter, over all groups so far */

/* cmocka's own matcher (c_strmatch in cmocka.c, static there): * any run, ? any one character. */
static bool matches(const char *name, const char *pat)
{
    for (;; name++, pat++) {
        if (*pat == '\0') return *name == '\0';
        if (*pat == '*') {
            while (*pat == '*') pat++;
            if (*pat == '\0') return true;
            for (; *name != '\0'; name++)
                if (matches(name, pat)) return true;
            return false;
        }
        if (*name == '\0' || (*pat != '?' && *pat != *name)) return false;
    }
}

static void judge_filter_at_exit(void)
{
    if (!pattern) return;
    const char *matched_file = getenv("PL_TEST_MATCHED");
    if (matched_file && *matched_file) {
        FILE *f = matched > 0 ? fopen(matched_file, "w") : NULL;
        if (f) fclose(f);
        return;
    }
    if (matched > 0) return;
    const char *suite = getenv("PL_TEST_SUITE");  /* the Makefile's name for it, test-part2 */
    if (!suite || !*suite) suite = "test-<suite>";
    fflush(stdout);
    fprintf(stderr,
            "ERROR: no test matches FILTER='%s' (the suite's tests are listed by `make %s LIST=1`; "
            "* and ? are wildcards, e.g. FILTER='*hemisphere*')\n",
            pattern, suite);
    fflush(NULL);
    _exit(1);  /* from an exit handler: exit() again is undefined */
}

__attribute__((constructor)) static void filter_from_environment(void)
{
    /* A line at a time even into a pipe (tests/common/run_suite.sh): cmocka's lines on stdout and
     * the tests' messages on stderr then appear in the order they were written. */
    setvbuf(stdout, NULL, _IOLBF, 0);
    const char *p = getenv("PL_TEST_FILTER");
    const char *l = getenv("PL_TEST_LIST");
    listing = l && *l && *l != '0';
    if (p && *p) {
        pattern = p;
        cmocka_set_test_filter(p);
    }
    atexit(judge_filter_at_exit);
}

int pl_run_group(const char *group_name, const struct CMUnitTest *tests, size_t count, CMFixtureFunction setup,
                 CMFixtureFunction teardown)
{
    int here = 0;
    for (size_t i = 0; i < count; i++) {
        if (pattern && !matches(tests[i].name, pattern)) continue;
        if (listing && here == 0) printf("%s:\n", group_name);
        if (listing) printf("  %s\n", tests[i].name);
        here++;
    }
    matched += here;
    if (listing || here == 0) return 0;
    /* A framework invariant broken during a test fails that test, it does not abort the suite. */
    pl_check_set_handler(check_failed_invariant);
    return _cmocka_run_group_tests(group_name, tests, count, setup, teardown);
}

int pl_run_groups(const pl_group *groups)
{
    int failed = 0;
    for (; *groups; groups++) failed += (*groups)() != 0;
    return failed != 0;
}
