/* Grader machinery: not part of any assignment.
 * The run stage of a part's unit tests (grade_tests.c): a submission's suite split in two processes
 * per test (the subject runs the submission's code, confined; the judge, the course's, alone gives the
 * verdict), or a student's own suite run whole. Either fills the suite's facts. */
#ifndef PL_GRADE_TESTS_H
#define PL_GRADE_TESTS_H

#include "grade_env.h"
#include "grade_plan.h"
#include "grade_suite.h"

/* Part p's tests, each run as the subject (the plan's bin/subject-part<N>: the submission's code,
 * contained by env's sandbox) piped into the judge (the course's bin/judge-part<N>, trusted, no student
 * code), scored from the judge's results only; within the suite's limit and the plan's deadline (the
 * tests left then fail as not run). */
void grade_tests_split(const grade_plan *plan, const grade_env *env, const grade_part_spec *p, grade_suite_facts *s);

/* A student's own tree: its test-part<N> run whole, its cmocka XML read back (grade_suite_results). */
void grade_tests_own(const grade_plan *plan, const grade_part_spec *p, grade_suite_facts *s);

#endif
