/* Grader machinery: not part of any assignment.
 * The object inspection: a part's compiled objects read as data, by allow-list, before anything
 * links or runs them (grade_inspect.c says what is allowed and why). The grader runs it on a
 * submission, confined (grade_inspect_part); a student's own `make test-part<N>` runs the same checks
 * on their objects in their own tree (bin/inspect-part), with the same words. */
#ifndef PL_GRADE_INSPECT_H
#define PL_GRADE_INSPECT_H

#include "grade_names.h"
#include "grade_sandbox.h"
#include "grade_why.h"
#include <stdbool.h>
#include <stddef.h>

struct grade_plan;

/* ---- what the inspection knows of the course ------------------------------------------------ */

/* Made once per part from trusted files only (the course's program and libraries), before any
 * submitted object is read. */
typedef struct {
    grade_names allowed;   /* names part code may refer to: the allow-list, every part's task functions */
    grade_names library;   /* every name the program's shared libraries define, and theirs in turn */
    grade_names program;   /* every global the course's program defines but part `own`'s code: the
                              framework's, the tests', the other parts' */
    int machine;           /* the program's ELF machine (EM_X86_64, ...): objects must match it */
} grade_inspect_course;

/* Loads the course's names for part `part` from its program (the course's bin/subject-part<N> or
 * bin/test-part<N>, whose libraries are found through the compiler's search path) less the globals
 * of own_objects (the course's own objects of the part, NULL-terminated; NULL: none). False with why. */
bool grade_inspect_course_load(const char *program, const char *const *own_objects, grade_inspect_course *c,
                               char *why, size_t size);
void grade_inspect_course_free(grade_inspect_course *c);  /* NULL-safe */
/* Adds to c's program the names listed in path, one a line: the framework's globals where the
 * program holds too few of them (a link-time optimised build inlines them away: make test-partN
 * lists them from the framework's objects instead, Makefile). False when it cannot be read. */
bool grade_inspect_course_add_names(grade_inspect_course *c, const char *path);

/* ---- the verdict ---------------------------------------------------------------------------- */

/* The verdict's type and codes are facts of a why (grade_why.h). */
/* Bounds: an object past any of them is refused whole (the course's largest holds ~60 sections and
 * ~400 symbols); every step of the inspection is then linear in the object's size. */
#define GRADE_INSPECT_SECTIONS 4096
#define GRADE_INSPECT_SYMBOLS 65536
#define GRADE_INSPECT_NAME_BYTES 1024

/* Inspects the n objects of one part against the course. Reads hostile files: the grader calls it
 * only in a confined child (grade_inspect_part). */
grade_inspect_verdict grade_inspect_objects(const char *const objects[], int n, const grade_inspect_course *c);

/* Keeps v's name only where the course knows it (a library's or the framework's name, a runtime
 * section of the list, a bound's own words), and says which kind it is; empties it otherwise. */
void grade_inspect_keep_known(grade_inspect_verdict *v, const grade_inspect_course *c);

/* ---- the grader's stage ----------------------------------------------------------------------- */

/* Inspects the objects the build made from the part's .c files (plan->sources: built without LTO, so
 * they hold machine code), before anything is linked from them: the files the compiler read (their
 * dependency files), then the objects, in a child confined as an untrusted stage
 * (grade_run_function), within GRADE_INSPECT_SECONDS and the plan's deadline. The course's names
 * come from the plan's course program and the course's own objects of the part. True when every
 * object keeps to the allow-list; otherwise false with why (GRADE_WHY_INCLUDES, GRADE_WHY_INSPECTION
 * and its verdict, GRADE_WHY_NOT_INSPECTED, or GRADE_WHY_COURSE). */
bool grade_inspect_part(const struct grade_plan *plan, const grade_sandbox *sandbox, grade_why *why);

/* Whether the files the compiler read for one object (its dependency file dep_file) are each the
 * part's own (parts/<folder>/), a framework header or a part's header. */
bool grade_inspect_dependencies(const char *folder, const char *dep_file);

#endif
