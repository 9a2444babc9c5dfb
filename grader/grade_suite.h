/* Grader machinery: not part of any assignment. A suite's verdicts, from the cmocka XML files it
 * wrote (CMOCKA_XML_FILE=<dir>/%g.xml: one file per test group, named after the group). */
#ifndef PL_GRADE_SUITE_H
#define PL_GRADE_SUITE_H

#include "grade.h"


/* Adds to r->tests_run, r->tests_failed and r->failures the tests of every file in dir, and accepts
 * only what the suite of part r->part writes: files named "part<N>: <group>.xml" whose one
 * <testsuite> has that group's name, every <testcase> under it counted wherever it sits, one with a
 * <failure>, <error> or <skipped> counted as not passed, and the tests= and failures= + errors= +
 * skipped= attributes agreeing with what was counted. False, with the reason in why, otherwise. */
bool grade_suite_read(const char *dir, grade_part_result *r, char *why, size_t size);
/* The same rules for one file at path, whose <testsuite> must be named group (NULL: any name; the
 * grader's judge writes one file per test, under a name of the grader's choosing). */
bool grade_suite_read_file(const char *path, const char *group, grade_part_result *r, char *why, size_t size);

#endif
