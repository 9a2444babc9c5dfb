/* Grader machinery: not part of any assignment. The build stage of a submission (grade_build.c says
 * what it trusts): the manifest of the submitted files, their confined compile, and the link in a
 * tree the student's code never saw. */
#ifndef PL_GRADE_BUILD_H
#define PL_GRADE_BUILD_H

#include "grade.h"

/* A part's submitted files, checked before anything reads them as code: regular files named
 * [a-z0-9_]+ then .c or .h (at most GRADE_SOURCE_NAME characters), at most GRADE_SOURCE_FILES of
 * them, each at most GRADE_SOURCE_BYTES of UTF-8 text without NUL bytes. An entry that ends in .c
 * or .h any other way (another name, a link, a folder) is refused; the others (a patch's .orig, a
 * notes file, .DS_Store) are no code, and are passed over, never read or named to any tool. */
typedef struct {
    char names[GRADE_SOURCE_FILES][GRADE_SOURCE_NAME + 1];
    int count;
} grade_manifest;

/* The manifest of dir (the submission's parts/<folder>); false with why, in the grader's words and
 * naming the file, when something there that ends like code is not a file the build takes. */
bool grade_manifest_read(const char *dir, const char *folder, grade_manifest *m, char *why, size_t size);

/* The graded build's recipes (grader/grader.mk writes them in the course's tree, before any student
 * code is seen): the compiler, a part file's flags, each program's link line, as argument vectors. */
#define GRADE_RECIPES "build/release/grade-recipes.txt"

/* Builds part n of env->submission into `tree` (the caller's: a new folder in env->sandbox_dir):
 * each submitted .c compiled alone, confined, into an object; the objects taken out, and linked as
 * the grader with the course's own objects of everything else into bin/pathtracer and
 * bin/subject-part<n>. False with r->suite_reason (and the compiler's lines about the student's
 * own files in r->build_output) when the part is refused, does not compile or does not link. */
bool grade_build_submission(const grade_env *env, int n, const char *tree, grade_part_result *r);

#endif
