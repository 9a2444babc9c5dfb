/* Grader machinery: not part of any assignment.
 * The report stage (grade_report.c): a grading's facts for the people and platforms who read them,
 * in grade_words.c's words. facts.json, the same facts for machines, is grade_facts.c's. */
#ifndef PL_GRADE_REPORT_H
#define PL_GRADE_REPORT_H

#include <stdio.h>
#include "grade_result.h"
#include "../framework/status.h"

/* The most text one results.json entry holds: a part's failures, each message escaped. */
#define GRADE_REPORT_TEXT (GRADE_MAX_TESTS * (4 * GRADE_MESSAGE_MAX + 256))

/* make grade's table: a line per part, the total, then what each part lost and why. */
void grade_report_table(const grade_result *r, FILE *out);
/* results.json (Gradescope's format: a "tests" entry per part's unit tests and per case, Markdown),
 * written atomically. */
pl_status grade_report_results_json(const grade_result *r, const char *path, pl_diag *diag);
/* folder/index.html and the public cases' pictures beside it. */
pl_status grade_report_html(const grade_result *r, const char *folder, pl_diag *diag);

#endif
