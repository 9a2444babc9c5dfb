/* Grader machinery: not part of any assignment.
 * Formatting into the grader's fixed buffers, two ways chosen by what a cut would do (grade_fmt.c
 * says why), and text made safe for Markdown. Paths are formatted by the plan alone (grade_plan.c):
 * every other module takes the paths it is handed. */
#ifndef PL_GRADE_FMT_H
#define PL_GRADE_FMT_H

#include <stdbool.h>
#include <stddef.h>

/* Every path the grader keeps fits one of these: the course's, --out's and --submission's folders
 * are at most GRADE_ROOT_MAX bytes (grade_limits.h), and every name joined onto them is short. */
#define GRADE_PATH 4096
typedef char grade_path_buf[GRADE_PATH];

/* A path, never cut: false (and a line on stderr) when it does not fit, with out emptied; the
 * caller gives up on what the path was for. For grade_plan.c alone. */
bool grade_path(char *out, size_t size, const char *format, ...) __attribute__((format(printf, 3, 4)));
/* A file named `name` (a name a folder's listing gave) in folder dir, into out: the one way a module
 * but the plan makes a path, from a folder the plan made; false (out empty) when it does not fit. */
bool grade_join(const char *dir, const char *name, char *out, size_t size);
/* A message for a person, cut to fit with "..." at the end (on a character boundary). */
void grade_msg(char *out, size_t size, const char *format, ...) __attribute__((format(printf, 3, 4)));
/* Text for Markdown (results.json's "md" outputs): the first len bytes of in (to its NUL), every
 * character CommonMark could read as markup escaped with a backslash, cut to fit out (never inside a
 * character, a backslash never left alone). A text escaped so shows as itself, whatever it holds. */
void grade_md_escape(const char *in, size_t len, char *out, size_t size);

#endif
