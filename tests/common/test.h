/* Test machinery: not part of any assignment. One include for a test file: cmocka and our asserts. */
#ifndef PL_TEST_H
#define PL_TEST_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "check.h"

/* Failure messages in the results file too. cmocka's XML results (what the grader reads, and shows
 * students) carry only "Failure!" for a failed test: print_error writes to the console, never to
 * the XML. So every print_error of a test also goes into a buffer (check.c), and a failure, fail()
 * included, hands the buffer to cmocka as the failure's text when the output is XML. */
void pl_print_error(const char *format, ...) CMOCKA_PRINTF_ATTRIBUTE(1, 2);
void pl_vprint_error(const char *format, va_list args) CMOCKA_PRINTF_ATTRIBUTE(1, 0);
#define print_error pl_print_error
#define vprint_error pl_vprint_error
#undef fail
#define fail() check_fail(__FILE__, __LINE__)

/* Every group runs through pl_run_group (tests/common/filter.c): it skips a group that FILTER leaves
 * empty, lists tests for LIST=1, and lets the suite fail when FILTER matches none of its tests. */
/* A suite's main: runs each group of the NULL-terminated list in order, every one even after a
 * failure; 1 if any failed, else 0. */
typedef int (*pl_group)(void);
int pl_run_groups(const pl_group *groups);

int pl_run_group(const char *group_name, const struct CMUnitTest *tests, size_t count, CMFixtureFunction setup,
                 CMFixtureFunction teardown);
#undef cmocka_run_group_tests_name
#define cmocka_run_group_tests_name(group_name, group_tests, group_setup, group_teardown) \
    pl_run_group((group_name), (group_tests), sizeof(group_tests) / sizeof((group_tests)[0]), (group_setup), (group_teardown))
#undef cmocka_run_group_tests
#define cmocka_run_group_tests(group_tests, group_setup, group_teardown) \
    pl_run_group(#group_tests, (group_tests), sizeof(group_tests) / sizeof((group_tests)[0]), (group_setup), (group_teardown))

#endif
