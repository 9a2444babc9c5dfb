/* Grader machinery: not part of any assignment. The grading trees (grade_tree.c says what they hold). */
#ifndef PL_GRADE_TREE_H
#define PL_GRADE_TREE_H

#include "grade.h"

/* What every build of a graded tree is given: no link-time optimisation (the objects then hold
 * machine code, and the allow-list reads the very files linked), the course's warnings whatever the
 * caller exported (CI's WERROR=1 made a student's unused variable a part that does not build), and
 * one version string, so that a tree's build never recompiles the objects it was given. */
#define GRADE_MAKE_ARGS "-j2", "--no-print-directory", "LTO=0", "WERROR=0", "SAN=0", "VERSION=graded"

/* The folder name of part n in root, e.g. "part2_bvh"; false when there is none. */
bool grade_part_folder(const char *root, int n, char *out, size_t size);

/* Where `bin/grade --prebuild` builds the course's objects ahead of time, under the root. */
#define GRADE_PREBUILD "out/grader-prebuild"

/* Copies the course's tree into env->work/course and builds there, before any student code runs,
 * every object and the renderer, and the suites of `parts` ("1,3"); false with why (the course's
 * problem: grading must not start). Objects prebuilt in root/GRADE_PREBUILD are reused. */
bool grade_tree_course_build(const grade_env *env, const char *parts, char *why, size_t size);

/* Part n's tree at env->sandbox_dir/part<n> (tree receives its path): the course's pieces and the
 * submission's part n, owned by the sandbox's user. False with r->suite_reason when the submission's
 * part cannot be taken. */
bool grade_tree_make(const grade_env *env, int n, char *tree, size_t size, grade_part_result *r);

/* "PARTS_SRC=..." for part n's build: the course's sources of the other parts (their objects are in
 * the tree) and the tree's own sources of part n. */
bool grade_tree_sources(const grade_env *env, const char *tree, int n, char *list, size_t size);

/* After the build: bin/ and build/ become root's, so what was built and inspected is what runs. */
bool grade_tree_seal(const grade_env *env, const char *tree);

/* Removes a tree (or anything at that path). */
void grade_tree_remove(const char *tree);

#endif
