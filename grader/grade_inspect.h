/* Grader machinery: not part of any assignment.
 * The object inspection: a part's compiled objects read as data, by allow-list, before anything
 * links or runs them (grade_inspect.c says what is allowed and why). The grader runs it on a
 * submission, confined (grade_inspect_part); a student's own `make test-partN` runs the same checks
 * on their objects in their own tree (bin/inspect-part), with the same words. */
#ifndef PL_GRADE_INSPECT_H
#define PL_GRADE_INSPECT_H

#include "grade_names.h"
#include <stdbool.h>
#include <stddef.h>

/* ---- the allow-list (grade_allow.c) ----------------------------------------------------------- */

/* True when part code may refer to name: the allow-list, not counting the parts' own functions. */
bool grade_allowed_symbol(const char *name);
/* The framework functions on that list, NULL-terminated: the ones the framework headers mark
 * PL_PART_API (tests/grader/test_allow.c checks that the two agree). */
const char *const *grade_allowed_framework(void);
/* Adds every name of the allow-list to set (libm's in all three precisions); false when out of memory. */
bool grade_allowed_add_all(grade_names *set);

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

typedef enum {
    GRADE_INSPECT_OK = 0,
    GRADE_INSPECT_UNREADABLE,     /* not a relocatable ELF object of the course's machine */
    GRADE_INSPECT_BOUND,          /* over one of the bounds below */
    GRADE_INSPECT_BYTECODE,       /* link-time optimisation bytecode, not machine code */
    GRADE_INSPECT_BEFORE_MAIN,    /* a section the C runtime runs code from (.init_array, .ctors, .init, ...) */
    GRADE_INSPECT_SECTION,        /* a section of a kind plain C does not compile to */
    GRADE_INSPECT_IFUNC,          /* an indirect function: its resolver runs while the program loads */
    GRADE_INSPECT_SYMBOL_KIND,    /* a symbol of a type, binding or section plain C does not make */
    GRADE_INSPECT_RESERVED,       /* defines a global name reserved to the C implementation */
    GRADE_INSPECT_REDEFINES,      /* defines a name a library or the framework already defines */
    GRADE_INSPECT_CALL,           /* refers to a name that is not on the allow-list nor the part's own */
    GRADE_INSPECT_CODES
} grade_inspect_code;

#define GRADE_INSPECT_NAME 128    /* a name the verdict carries (longer ones are cut: never quoted then) */
/* Bounds: an object past any of them is refused whole (the course's largest holds ~60 sections and
 * ~400 symbols); every step of the inspection is then linear in the object's size. */
#define GRADE_INSPECT_SECTIONS 4096
#define GRADE_INSPECT_SYMBOLS 65536
#define GRADE_INSPECT_NAME_BYTES 1024

typedef struct {
    int code;                     /* grade_inspect_code */
    int object;                   /* the index of the object at fault */
    char name[GRADE_INSPECT_NAME];/* the symbol or section at fault, as the object spells it */
    long bound;                   /* for GRADE_INSPECT_BOUND: the bound passed */
} grade_inspect_verdict;

/* Inspects the n objects of one part against the course. Reads hostile files: the grader calls it
 * only in a confined child (grade_inspect_part). */
grade_inspect_verdict grade_inspect_objects(const char *const objects[], int n, const grade_inspect_course *c);

/* The verdict in the grader's words, for the student: the object's file name (names[v->object]),
 * what is wrong and what to do. A name is quoted only when the course knows it (a library's, the
 * framework's, a section the C runtime runs): the student's own names are described, never quoted. */
void grade_inspect_describe(const grade_inspect_verdict *v, const grade_inspect_course *c, const char *const names[],
                            char *out, size_t size);

/* ---- the grader's stage ----------------------------------------------------------------------- */

/* Inspects the objects the build made from the .c files of parts/<folder> in the tree (built
 * without LTO), before anything is linked from them, with its logs in work (a folder the child
 * cannot write): the files the compiler read (its dependency files), then the objects, in a child
 * confined as an untrusted stage (grade_run_function), within GRADE_INSPECT_SECONDS and the grading's
 * deadline (clock_seconds(), 0 for none). The course's names come
 * from course (its built tree): its bin/subject-part<n> and its own objects of the part. True when
 * every object keeps to the allow-list; otherwise false with why = "parts/<folder>/<file>: <what>". */
bool grade_inspect_part(const char *tree, const char *course, const char *folder, int n, const char *work,
                        double deadline, char *why, size_t size);

/* The files the compiler read for one object (its dependency file dep_file), each the part's own
 * (parts/<folder>/), a framework header or a part's header; false with what = why not. */
bool grade_inspect_dependencies(const char *folder, const char *dep_file, char *what, size_t size);

#endif
