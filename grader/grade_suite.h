/* Grader machinery: not part of any assignment. A suite's verdicts, from the cmocka XML files it
 * wrote (CMOCKA_XML_FILE=<dir>/%g.xml: one file per test group, named after the group). */
#ifndef PL_GRADE_SUITE_H
#define PL_GRADE_SUITE_H

#include "grade.h"


/* A suite's tests by name, in the order it runs them. */
typedef struct {
    char names[GRADE_MAX_TESTS][128];
    int count;
} grade_test_list;

/* The tests of the suite or judge at program, listed by itself (PL_TEST_LIST=1: a "  name" line per
 * test, tests/common/filter.c), run with o (its env replaced) and read back from o->log_path; false
 * when it lists none. */
bool grade_suite_list(const char *program, const grade_run_opts *o, grade_test_list *list);

/* Adds to r->tests_run, r->tests_failed and r->failures the tests of every file in dir, and accepts
 * only what the suite of part r->part writes: files named "part<N>: <group>.xml" whose one
 * <testsuite> has that group's name, every <testcase> under it counted wherever it sits, one with a
 * <failure>, <error> or <skipped> counted as not passed, and the tests= and failures= + errors= +
 * skipped= attributes agreeing with what was counted. False, with the reason in why, otherwise. The
 * groups are counted in the order of their first test in order (NULL, or a test it lacks: by file
 * name), so the failures are listed as the suite ran them. */
bool grade_suite_read(const char *dir, const grade_test_list *order, grade_part_result *r, char *why, size_t size);
/* Reads the cmocka XML files in dir into r's tests run and failed (grade_score_part makes points of
 * them), or leaves a reason in r->suite_reason when the results are missing or malformed, or hold
 * other than `expected` tests (the suite stopped early, or the files are not its own), or disagree
 * with the exit status. The failures are listed in order (see grade_suite_read). */
void grade_suite_results(const char *dir, const grade_test_list *order, int expected, int status, grade_part_result *r);
/* The same rules for one file at path, whose <testsuite> must be named group (NULL: any name; the
 * grader's judge writes one file per test, under a name of the grader's choosing). */
bool grade_suite_read_file(const char *path, const char *group, grade_part_result *r, char *why, size_t size);

#endif
