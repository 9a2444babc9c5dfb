/* Test machinery: not part of any assignment. One include for a test file: cmocka and our asserts. */
#ifndef PL_TEST_H
#define PL_TEST_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include "check.h"

/* Every group runs through pl_run_group (tests/common/filter.c): it skips a group that FILTER leaves
 * empty, lists tests for LIST=1, and lets the suite fail when FILTER matches none of its tests. */
int pl_run_group(const char *group_name, const struct CMUnitTest *tests, size_t count, CMFixtureFunction setup,
                 CMFixtureFunction teardown);
#undef cmocka_run_group_tests_name
#define cmocka_run_group_tests_name(group_name, group_tests, group_setup, group_teardown) \
    pl_run_group((group_name), (group_tests), sizeof(group_tests) / sizeof((group_tests)[0]), (group_setup), (group_teardown))
#undef cmocka_run_group_tests
#define cmocka_run_group_tests(group_tests, group_setup, group_teardown) \
    pl_run_group(#group_tests, (group_tests), sizeof(group_tests) / sizeof((group_tests)[0]), (group_setup), (group_teardown))

#endif
