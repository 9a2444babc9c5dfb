/* Grader machinery: not part of any assignment. Keeping the answers from student code (grade_guard.c). */
#ifndef PL_GRADE_GUARD_H
#define PL_GRADE_GUARD_H

#include <stdbool.h>
#include <stddef.h>

#include "grade_plan.h"
#include "grade_sandbox.h"

/* When children run as another user: the plan's secrets (grade_plan_secrets: the references, the
 * hidden cases, the course's solutions and tools, the report and results.json) become root's alone
 * (folders 0700, files 0600). False with why when one cannot be protected (grading must then not run). */
bool grade_guard_secrets(const grade_secrets *secrets, const grade_sandbox *s, char *why, size_t size);

/* A fresh, empty folder at path (whatever was there is removed) for a child to write into: owned by
 * the child's user when contained and the grader is root. */
bool grade_guard_child_dir(const char *path, const grade_sandbox *s, bool contained);

/* A fresh, empty folder at path for the grader's own logs and films of a part (a grading's or a
 * calibration's): root's alone (0700), whoever else can list --out. What the course renders there is
 * its reference's twin for a deterministic case, so no other user may read it; the children get
 * folders of their own inside. */
bool grade_guard_own_dir(const char *path);

/* Opens a file a child wrote, for reading: -1 when it is a symlink, not a regular file, or over
 * max_bytes. The caller reads through the descriptor (or /proc/self/fd/N), never the name again. */
int grade_guard_open_child_file(const char *path, long max_bytes);

#endif
