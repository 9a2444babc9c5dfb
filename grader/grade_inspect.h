/* Grader machinery: not part of any assignment. The link-time allow-list of a part (see grade_inspect.c). */
#ifndef PL_GRADE_INSPECT_H
#define PL_GRADE_INSPECT_H

#include <stdbool.h>
#include <stddef.h>

/* Inspects the objects the build made from the .c files of parts/<folder> in the tree (built
 * without LTO), before anything is linked from them, with its logs in work (a folder the child
 * cannot write); `program` is the course's test program of the part, whose libraries (and theirs)
 * a part may not redefine. True when every object keeps to the allow-list; otherwise false with
 * why = "parts/<folder>/<file>: <what>". untrusted: run the inspecting tools contained. */
bool grade_inspect_part(const char *tree, const char *folder, const char *program, const char *work, bool untrusted,
                        char *why, size_t size);

/* True when part code may refer to name: the allow-list (grade_allow.c), not counting the parts'
 * own functions, which grade_inspect_part adds. */
bool grade_allowed_symbol(const char *name);
/* The framework functions on that list, NULL-terminated: the ones the framework headers mark PL_PART_API
 * (tests/grader/test_allow.c checks that the two agree). */
const char *const *grade_allowed_framework(void);

#endif
