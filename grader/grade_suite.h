/* Grader machinery: not part of any assignment.
 * The verdicts of a suite, from the cmocka XML files it wrote (CMOCKA_XML_FILE=<dir>/%g.xml: one file
 * per test group, named after the group; the split suite's judge, one file per test), into the
 * suite's facts (grade_result.h): each test's name, pass or fail, and the course's test's message.
 * The files are read as hostile: no links, a size cap, no DTD, no network. */
#ifndef PL_GRADE_SUITE_H
#define PL_GRADE_SUITE_H

#include "grade_result.h"

/* A suite's tests by name, in the order it runs them. */
typedef struct {
    char names[GRADE_MAX_TESTS][128];
    int count;
} grade_test_list;

/* Adds the tests of every file in dir to s, and accepts only what the suite of part `part` writes:
 * files named "part<N>: <group>.xml" whose one <testsuite> has that group's name, every <testcase>
 * under it counted wherever it sits, one with a <failure>, <error> or <skipped> counted as not
 * passed, and the tests= and failures= + errors= + skipped= attributes agreeing with what was counted.
 * False, with the reason in why (the grader's words), otherwise. The groups are counted in the order
 * of their first test in order (NULL, or a test it lacks: by file name), so the tests are listed as
 * the suite ran them. */
bool grade_suite_read(const char *dir, const grade_test_list *order, int part, grade_suite_facts *s, char *why,
                      size_t size);
/* The same rules for one file at path, whose <testsuite> must be named group (NULL: any name; the
 * grader's judge writes one file per test, under a name of the grader's choosing). */
bool grade_suite_read_file(const char *path, const char *group, grade_suite_facts *s, char *why, size_t size);
/* Reads a whole suite's results (grade_suite_read) and judges them: s->judged, or s->why when they
 * are missing or malformed, hold other than `expected` tests (the suite stopped early, or the files
 * are not its own), or disagree with the exit status. */
void grade_suite_results(const char *dir, const grade_test_list *order, int expected, int status, int part,
                         grade_suite_facts *s);
/* Adds one test to s (in the suite's order), passed or not; its fact, or NULL when the suite holds
 * over GRADE_MAX_TESTS (the count check then fails the suite). */
grade_test_fact *grade_suite_note(grade_suite_facts *s, const char *name, bool passed);

#endif
