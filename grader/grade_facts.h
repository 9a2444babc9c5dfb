/* Grader machinery: not part of any assignment.
 * The facts of a grading, for machines: `facts.json` in the grading's --out folder, beside the
 * student's results.json and report. Where those say in words what a part lost and why, facts.json
 * says it as data: each part's score, each task's share and tests, each case's outcome and the
 * cause of its failure as a stable code ("factor_1/pi", "noisier", "stub"), with the report's own
 * words for it. Course staff read it (the class report of course/class/ counts causes across a
 * class); it holds hidden cases' names and causes, so it is never shown to a student.
 *
 * The schema is "pathlab-grade-facts/1"; grader/README.md lists its members and the cause codes. */
#ifndef PL_GRADE_FACTS_H
#define PL_GRADE_FACTS_H

#include "grade_result.h"
#include "../framework/status.h"

#define GRADE_FACTS_SCHEMA "pathlab-grade-facts/1"

/* Why case c did not pass, as a stable code, and the report's words for it in *words (both static
 * strings); NULL (and *words "") when it passed. */
const char *grade_facts_case_cause(const grade_part_result *p, const grade_case_result *c, const char **words);

/* Why part p's unit tests earned less than their points: "not_built", "suite_stopped", or "tests"
 * (some test failed: the first is first_failed_test); NULL when they earned everything. */
const char *grade_facts_unit_cause(const grade_part_result *p);

/* Writes r's facts to path, atomically. */
pl_status grade_facts_write(const grade_result *r, const char *path, pl_diag *diag);

#endif
