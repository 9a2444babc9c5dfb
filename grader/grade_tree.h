/* Grader machinery: not part of any assignment. The grading trees (grade_tree.c says what they hold). */
#ifndef PL_GRADE_TREE_H
#define PL_GRADE_TREE_H

#include "grade.h"

/* What the course's build is given: no link-time optimisation (the objects then hold machine code,
 * the allow-list reads the very files linked, and ld --wrap sees every call of the split suites),
 * the course's warnings whatever the caller exported (CI's WERROR=1), and no sanitizer. */
#define GRADE_MAKE_ARGS "-j2", "--no-print-directory", "LTO=0", "WERROR=0", "SAN=0"
/* Where that build puts its objects, in the course's tree and so in every grading tree. */
#define GRADE_OBJECTS "build/release"

/* The folder name of part n in root, e.g. "part2_bvh"; false when there is none. */
bool grade_part_folder(const char *root, int n, char *out, size_t size);

/* Where `bin/grade --prebuild` builds the course's objects ahead of time, under the root. */
#define GRADE_PREBUILD "out/grader-prebuild"

/* Copies the course's tree into env->work/course and builds there, before any student code runs,
 * every object, the renderer, the build recipes (grade_build.h), and for each of `parts` ("1,3") its
 * suite, its split suite's subject and its judge (grade_judge.c); false with why (the course's
 * problem: grading must not start). Objects prebuilt in root/GRADE_PREBUILD are reused. */
bool grade_tree_course_build(const grade_env *env, const char *parts, char *why, size_t size);

/* The name every sandbox folder starts with (grade_main.c makes one per grading under $TMPDIR). */
#define GRADE_SANDBOX_NAME "pathlab-sandbox."
/* Removes a tree (or anything at that path) in a sandbox folder, or that folder; anything else is
 * refused with a line on stderr. */
void grade_tree_remove(const char *tree);

#endif
