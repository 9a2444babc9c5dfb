/* Grader machinery: not part of any assignment.
 * bin/inspect-part: the autograder's object inspection (grade_inspect.c), on a student's own tree,
 * so that `make test-part<N>` refuses what the grader refuses, with the grader's words, before the
 * suite runs. make compiles the part's files once more as the grader does (no link-time
 * optimisation, so the objects hold machine code) and runs
 *
 *   bin/inspect-part PROGRAM NAMES FOLDER OBJECT...
 *
 * PROGRAM: the part's test program (its libraries are the ones a part may not redefine); NAMES: the
 * framework's global names, one a line (make lists them from the framework's objects); FOLDER:
 * parts/<folder>; each OBJECT has its dependency file beside it (<name>.d). Exit status 0 when every
 * object keeps to the allow-list, 1 with the grader's message otherwise, 2 on a usage error. Where
 * the machine has no libelf (macOS: its objects are Mach-O), it says the inspection is the
 * autograder's and exits 0. */
#include "grade_fmt.h"
#include "grade_inspect.h"
#include "grade_why.h"
#include "grade_words.h"
#include <stdio.h>
#include <string.h>

#define MAX_FILES 32

/* "<name>.c" for object ".../<name>.o": the file the student wrote, as the grader's words name it. */
static void source_name(const char *object, char *out, size_t size)
{
    const char *base = strrchr(object, '/');
    base = base ? base + 1 : object;
    size_t n = strlen(base);
    grade_msg(out, size, "%.*s.c", n > 2 ? (int)n - 2 : (int)n, base);
}

/* The grader's words for a why about file `file` of parts/<folder>. */
static void say(grade_why *w, const char *file, const char *folder)
{
    char words[1024];
    snprintf(w->file, sizeof w->file, "%s", file);
    grade_words_why(w, 0, folder, words, sizeof words);
    printf("%s\nThe autograder refuses this part for it (0 points: it checks the compiled objects before anything "
           "runs), so its tests were not run.\n", words);
}

int main(int argc, char **argv)
{
    if (argc < 5 || argc - 4 > MAX_FILES || strncmp(argv[3], "parts/", 6)) {
        fprintf(stderr, "usage: bin/inspect-part PROGRAM NAMES parts/<folder> OBJECT... (at most %d objects)\n", MAX_FILES);
        return 2;
    }
    const char *folder = argv[3] + 6;
    int n = argc - 4;
    const char *objects[MAX_FILES + 1];
    char names[MAX_FILES][GRADE_SOURCE_NAME + 1], deps[MAX_FILES][4096];
    char why[1024];
    for (int i = 0; i < n; i++) {
        objects[i] = argv[4 + i];
        source_name(objects[i], names[i], sizeof names[i]);
        size_t len = strlen(objects[i]);
        grade_msg(deps[i], sizeof deps[i], "%.*s.d", len > 2 ? (int)len - 2 : (int)len, objects[i]);
        if (!grade_inspect_dependencies(folder, deps[i])) {
            grade_why w = grade_why_of(GRADE_WHY_INCLUDES);
            say(&w, names[i], folder);
            return 1;
        }
    }
    objects[n] = NULL;
    grade_inspect_course course;
    if (!grade_inspect_course_load(argv[1], objects, &course, why, sizeof why)) {
        printf("inspect-part: the object inspection is not run here: %s\n", why);
        return 0;
    }
    if (!grade_inspect_course_add_names(&course, argv[2])) {
        printf("inspect-part: cannot read %s (make lists the framework's names there)\n", argv[2]);
        grade_inspect_course_free(&course);
        return 2;
    }
    grade_inspect_verdict v = grade_inspect_objects(objects, n, &course);
    if (v.code != GRADE_INSPECT_OK) {
        grade_inspect_keep_known(&v, &course);
        grade_why w = grade_why_of(GRADE_WHY_INSPECTION);
        w.inspect = v;
        say(&w, v.object >= 0 && v.object < n ? names[v.object] : "(an object)", folder);
    }
    grade_inspect_course_free(&course);
    return v.code != GRADE_INSPECT_OK;
}
