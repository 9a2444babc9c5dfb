/* Grader machinery: not part of any assignment. The link-time allow-list of a part (see grade_inspect.c). */
#ifndef PL_GRADE_INSPECT_H
#define PL_GRADE_INSPECT_H

#include <stdbool.h>
#include <stddef.h>

/* Inspects the .c files of parts/<folder> in the built tree (scratch under work). True when every file keeps to
 * the allow-list; otherwise false with why = "parts/<folder>/<file>: <what>". untrusted: compile
 * contained, as the build was. */
bool grade_inspect_part(const char *tree, const char *folder, const char *work, bool untrusted, char *why,
                        size_t size);

#endif
