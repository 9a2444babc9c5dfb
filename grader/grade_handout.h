/* Grader machinery: not part of any assignment.
 * The handout's grading tables from grading/cases.json (grade_handout.c). */
#ifndef PL_GRADE_HANDOUT_H
#define PL_GRADE_HANDOUT_H

#include <stddef.h>
#include "grade_spec.h"

/* Part p's grading table as Markdown: its unit tasks (task, functions, tests, points), then its
 * public image cases (name, what it shows, render flags, points, reference picture). False when
 * it does not fit in size bytes. */
bool grade_handout_table(const grade_part_spec *p, char *out, size_t size);

/* The generated table of the handout file at path, between its BEGIN GENERATED and END GENERATED
 * lines, against part p's: rewritten (atomically) when write, else any difference is an error. */
pl_status grade_handout_update(const char *path, const grade_part_spec *p, bool write, pl_diag *diag);

#endif
