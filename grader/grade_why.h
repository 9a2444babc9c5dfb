/* Grader machinery: not part of any assignment.
 * Why something did not happen, as a fact: every stage says why a part did not build, a suite could
 * not be judged, a test did not finish or a case did not run, with a code and the few values the
 * words need; the report alone turns it into words (grade_report_why), and facts.json into the class
 * report's categories. A why never holds the candidate's own text or numbers: its values are the
 * grader's (a limit, a count of tests), a submitted file's name the manifest took ([a-z0-9_]+.c), the
 * course's or the framework's own words (a course file's error, a film the framework refused), and
 * the ending of a child as the kernel reported it. */
#ifndef PL_GRADE_WHY_H
#define PL_GRADE_WHY_H

#include <stdbool.h>
#include "grade_limits.h"
#include "grade_run.h"

/* ---- the inspection's verdict (grade_inspect.c): which rule an object broke ---------------------- */

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

/* What the verdict's name is, once the grader kept it (grade_inspect_keep_known): a name is shown
 * only when the course knows it; the student's own is described, never quoted. */
typedef enum {
    GRADE_NAME_UNKNOWN,           /* the student's: emptied */
    GRADE_NAME_LIBRARY,           /* a function or object a library of the program defines */
    GRADE_NAME_FRAMEWORK,         /* one the framework (or another part, or a test) defines */
    GRADE_NAME_RUNTIME,           /* a section the C runtime runs code from (the list's spelling) */
    GRADE_NAME_BOUND              /* the bound's own words ("sections", "symbols", ...) */
} grade_name_known;

typedef struct {
    int code;                     /* grade_inspect_code */
    int object;                   /* the index of the object at fault */
    char name[GRADE_INSPECT_NAME];/* the symbol or section at fault: as the object spells it in the child's
                                     verdict, then kept only when known (grade_inspect_keep_known) */
    long bound;                   /* for GRADE_INSPECT_BOUND: the bound passed */
    int known;                    /* grade_name_known */
} grade_inspect_verdict;

/* ---- why ---------------------------------------------------------------------------------------- */

typedef enum {
    GRADE_WHY_NONE = 0,
    /* the spec stage: the submitted part's folder (grade_manifest.c) */
    GRADE_WHY_NO_FOLDER,              /* the submission has no parts/<folder> */
    GRADE_WHY_ENTRY_UNREADABLE,       /* an entry cannot be read */
    GRADE_WHY_NOT_A_FILE,             /* an entry named like code is a folder, a link or a special file (count: which) */
    GRADE_WHY_BAD_NAME,               /* a .c or .h whose name is not [a-z0-9_]+ */
    GRADE_WHY_FILE_TOO_BIG,           /* file: over GRADE_SOURCE_BYTES */
    GRADE_WHY_TOO_MANY_FILES,         /* over GRADE_SOURCE_FILES */
    GRADE_WHY_FILE_UNREADABLE,        /* file: cannot be read as a file */
    GRADE_WHY_NOT_TEXT,               /* file: not UTF-8 text */
    GRADE_WHY_NO_C_FILE,              /* no .c file at all */
    /* the build (grade_build.c, grade_inspect.c; a student's own tree: its make) */
    GRADE_WHY_BUILD_OUT_OF_TIME,      /* step, file: the grading's deadline came first */
    GRADE_WHY_BUILD_TIMED_OUT,        /* step, file, limit (seconds) */
    GRADE_WHY_BUILD_OUTPUT,           /* step, file: printed more than GRADE_LOG_MAX */
    GRADE_WHY_BUILD_MEMORY,           /* step, file: its memory limit or CPU time */
    GRADE_WHY_BUILD_FAILS,            /* step, file: does not compile, or does not link */
    GRADE_WHY_NO_OBJECT,              /* file: the compiler made no usable object */
    GRADE_WHY_INCLUDES,               /* file: it read a file that is neither its part's nor a header */
    GRADE_WHY_INSPECTION,             /* inspect: the objects break the allow-list */
    GRADE_WHY_NOT_INSPECTED,          /* the inspection itself did not finish (run) */
    GRADE_WHY_OWN_BUILD,              /* a student's own tree's make failed (run) */
    /* the course's or the grader's own problems: never a student's fault */
    GRADE_WHY_COURSE,                 /* detail: the course's files (recipes, a scene, a reference) */
    GRADE_WHY_GRADER,                 /* detail: the grader could not lay out a folder, or ran out of memory */
    /* the suite (grade_judge.c, grade_suite.c) */
    GRADE_WHY_SUITE_ENDED,            /* run: a student's own suite crashed, timed out */
    GRADE_WHY_SUITE_UNREADABLE,       /* detail: its results are not what the suite writes (the grader's words) */
    GRADE_WHY_SUITE_NO_RESULTS,       /* it wrote no readable results */
    GRADE_WHY_SUITE_STOPPED,          /* count of limit tests run: it stopped early */
    GRADE_WHY_SUITE_TOO_MANY,         /* count, limit: it reported more tests than it has */
    GRADE_WHY_SUITE_STATUS,           /* count: its exit status disagrees with its results */
    /* one test of a split suite (the test's own message otherwise) */
    GRADE_WHY_TEST_OUT_OF_TIME,       /* it did not finish within the grading's deadline */
    GRADE_WHY_TEST_NOT_RUN,           /* the tests before it used the suite's time (limit seconds) */
    GRADE_WHY_JUDGE_UNFINISHED,       /* run: the course's judge of the test did not finish */
    /* one image case's render (grade_render.c, grade_image.c) */
    GRADE_WHY_NOT_BUILT,              /* the part did not build: nothing to render */
    GRADE_WHY_RENDER_OUT_OF_TIME,     /* the grading's deadline came first */
    GRADE_WHY_RENDER_TIMED_OUT,       /* limit: its wall-clock time */
    GRADE_WHY_RENDER_REFUSED,         /* count: the framework refused the part's tree: which rule (GRADE_FRAMEWORK_RULES) */
    GRADE_WHY_RENDER_BUILD_ERROR,     /* bvh_build returned an error */
    GRADE_WHY_RENDER_STUB,            /* the render reached a task still a stub */
    GRADE_WHY_RENDER_STATUS,          /* it exited with an error status */
    GRADE_WHY_RENDER_CPU,             /* it ran past its CPU time */
    GRADE_WHY_RENDER_SYSCALL,         /* it made a system call the sandbox forbids */
    GRADE_WHY_RENDER_MEMORY_ERROR,    /* a segmentation fault or bus error */
    GRADE_WHY_RENDER_SIGNAL,          /* another signal */
    GRADE_WHY_FILM_UNUSABLE,          /* detail: the framework's words about the film it sent */
    GRADE_WHY_FILM_TOO_BIG,           /* it sent more than any film of the case takes */
    GRADE_WHY_FILM_COUNTS,            /* count: its samples per pixel (0: none, or more than the case's; else not the case's) */
    GRADE_WHY_FILM_SUMS,              /* a pixel holds sums no samples can have */
    GRADE_WHY_CODES
} grade_why_code;

/* The framework's reasons for refusing the tree part 2 made (framework/bvh.c, bvh_validate checks a
 * student's tree before any ray uses it), as its log states each (X's first: what the render's log
 * line holds) and as the report says it (its second). The log is the render's, so never echoed:
 * grade_render.c keeps only the index of the rule its line names, and the report the words. */
#define GRADE_FRAMEWORK_RULES(X)                                                                      \
    X("leaf holds", "a leaf holds more primitives than the leaf size allows")                         \
    X("leaf covers slots", "a leaf's slots run past the end of prim_index")                           \
    X("belongs to two leaves", "a slot of prim_index belongs to two leaves")                          \
    X("is not a primitive", "prim_index holds a number that is not a primitive's")                     \
    X("is in two leaves", "a primitive is in two leaves")                                             \
    X("reached twice", "a node is reached twice from the root (a cycle or a shared child)")           \
    X("exceeds BVH_MAX_DEPTH", "the tree is deeper than BVH_MAX_DEPTH")                               \
    X("leaf box is not", "a leaf's box does not bound its primitives")                                \
    X("pokes out", "a child's box pokes out of its parent's")                                         \
    X("not tight", "a node's box is larger than the union of its children's")                         \
    X("not reachable", "a node is not reachable from the root (num_nodes too large?)")                 \
    X("is in no leaf", "a primitive is in no leaf")                                                   \
    X("num_prims is", "num_prims is not the scene's number of primitives")                            \
    X("empty scene", "an empty scene must give num_nodes 0")                                          \
    X("num_nodes is", "num_nodes is not in 1 .. 2n - 1")                                              \
    X("count", "a node's count is negative")                                                          \
    X("child", "a child's index is not a node of the tree")

/* A build's step: the words for it and for its file come from the report. */
typedef enum { GRADE_STEP_NONE, GRADE_STEP_COMPILE, GRADE_STEP_LINK_RENDERER, GRADE_STEP_LINK_SUITE } grade_step;

typedef struct grade_why {
    grade_why_code code;
    grade_step step;
    char file[GRADE_SOURCE_NAME + 1];  /* a submitted file the manifest took, or "" */
    long count, limit;                 /* a count or an index, a limit: the grader's own numbers */
    grade_run_result run;              /* the child whose ending is the reason, where one is */
    grade_inspect_verdict inspect;     /* GRADE_WHY_INSPECTION */
    char detail[256];                  /* the course's or the framework's own words, where the code needs them */
} grade_why;

/* A why of code (and nothing else). */
static inline grade_why grade_why_of(grade_why_code code)
{
    grade_why w = {.code = code};
    return w;
}

#endif
