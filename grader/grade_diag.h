/* Grader machinery: not part of any assignment. The compiler's messages a student may see. */
#ifndef PL_GRADE_DIAG_H
#define PL_GRADE_DIAG_H

#include <stdbool.h>
#include <stddef.h>

/* The first max_lines lines of the build log that concern parts/<folder>/ itself (grade_diag.c says
 * which), at most size - 1 bytes, valid UTF-8 with no control character but tabs and newlines (a
 * bad byte becomes '?'), into out ("" when none, or the log is unreadable). */
void grade_diagnostics(const char *log, const char *folder, int max_lines, char *out, size_t size);

/* The last `lines` lines of the log at path, less make's progress lines, at most size - 1 bytes ("" when
 * unreadable): a child's own end, for the staff log or a limit's traces. */
void grade_log_tail(const char *path, int lines, char *out, size_t size);

#endif
