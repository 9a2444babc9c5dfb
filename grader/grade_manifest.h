/* Grader machinery: not part of any assignment.
 * The spec stage's submission side: a submitted part's folder read as data (grade_manifest.c), before
 * anything reads its files as code. No submitted name ever reaches make, a shell, or the student's
 * report: a refused entry is described, never quoted. */
#ifndef PL_GRADE_MANIFEST_H
#define PL_GRADE_MANIFEST_H

#include <stdbool.h>
#include "grade_limits.h"
#include "grade_why.h"

/* A part's submitted files, checked before anything reads them as code: regular files named
 * [a-z0-9_]+ then .c or .h (at most GRADE_SOURCE_NAME characters), at most GRADE_SOURCE_FILES of
 * them, each at most GRADE_SOURCE_BYTES of UTF-8 text without NUL bytes. An entry that ends in .c
 * or .h any other way (another name, a link, a folder) is refused; the others (a patch's .orig, a
 * notes file, .DS_Store) are no code, and are passed over, never read or named to any tool. */
typedef struct {
    char names[GRADE_SOURCE_FILES][GRADE_SOURCE_NAME + 1];
    int count;
} grade_manifest;

/* The manifest of dir (the submission's parts/<folder>); false with why (what was refused, and the
 * file when its name is one the build takes) when something there that ends like code is not a file
 * the build takes. */
bool grade_manifest_read(const char *dir, const char *folder, grade_manifest *m, grade_why *why);


#endif
