/* Instructor tooling: not part of any assignment.
 * The release stripper's core, shared by course/release/strip_solutions.c and its tests.
 *
 * Marker grammar, line by line (a marker line holds its marker and nothing else but blanks):
 *   BEGIN SOLUTION marker ... END SOLUTION marker   removed, both lines included;
 *   a STUB line directly after an END marker        becomes its code at the same indentation.
 * A region at file scope (brace depth 0) may have no STUB line: it removes solution-only helpers
 * whole. A region inside a function body must have one. A STUB line anywhere else, a nested BEGIN,
 * an END without BEGIN, a region left open, and a comment that looks like a marker but is not
 * spelt exactly like one (a line comment, other blanks, other letter case) are errors. Line endings (LF or
 * CRLF) are kept as they are. The exact marker texts are in STYLE.md's task example; this code
 * spells them as split string literals, so the stripper's own sources hold no marker and pass
 * through a release unchanged. */
#ifndef PL_STRIP_H
#define PL_STRIP_H

#include <stddef.h>
#include "../../framework/status.h"

/* Replaces every solution region of in[0..len) by its stub. On PL_OK, *out is a NUL-terminated,
 * malloc'ed copy of the result (the caller frees it); out may be NULL to validate only. On
 * PL_ERR_PARSE, diag says "name:line: what was expected" and *out is untouched. */
pl_status strip_text(const char *in, size_t len, const char *name, char **out, pl_diag *diag);

/* One student task, as its banner names it: `=== PART 2 | TASK 2.2 | bvh_build ===`. */
typedef struct {
    int part;           /* N of PART N */
    char id[16];        /* "2.2" */
    char function[64];  /* "bvh_build" */
    int line;           /* the banner's line, 1-based */
} strip_task;

/* Validates the markers (as strip_text does) and every banner: it names its part, task and
 * function consistently; the function is defined right after it; its body holds a solution region
 * whose STUB calls a PL_TODO macro with the same task id and function. A STUB naming a task must
 * sit under that task's banner. On PL_OK, *tasks (malloc'ed, caller frees; NULL when none) and
 * *num_tasks list the banners in file order. */
pl_status strip_tasks(const char *in, size_t len, const char *name, strip_task **tasks, int *num_tasks,
                      pl_diag *diag);

#endif
