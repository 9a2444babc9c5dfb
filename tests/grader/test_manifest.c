/* Test machinery: not part of any assignment.
 * The spec stage's manifest (grader/grade_manifest.h): a submitted part's folder is read as data
 * before anything reads it as code. A name is refused when it ends like code but is not a plain
 * [a-z0-9_]+.c/.h file (a name like a make function once ran a shell in the build), and passed
 * over when it is no code at all (a patch's .orig, notes): never read, never named to a tool. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_manifest.h"
#include "../../grader/grade_words.h"
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

SCRATCH_FOLDER(scratch, "manifest-test")

/* A fresh part folder under the scratch folder, holding direct.c and part3.h. */
static void fresh_part(char *dir, size_t size, const char *name)
{
    char path[512];
    snprintf(dir, size, "%s/%s", scratch, name);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(path, sizeof path, "%s/direct.c", dir);
    scratch_write(path, "int pl_direct;\n");
    snprintf(path, sizeof path, "%s/part3.h", dir);
    scratch_write(path, "/* the student's copy */\n");
}

/* The manifest of dir; why is "" when it is taken. */
static int read_manifest(const char *dir, grade_manifest *m, char *why, size_t size)
{
    why[0] = '\0';
    grade_why w = grade_why_of(GRADE_WHY_NONE);
    if (grade_manifest_read(dir, "part3_direct", m, &w)) return m->count;
    grade_words_why(&w, 3, "part3_direct", why, size);  /* the words the student reads */
    return -1;
}

static void test_manifest__sources_taken_no_code_passed_over(void **state)
{
    (void)state;
    char dir[256], path[512], why[256];
    grade_manifest m;
    fresh_part(dir, sizeof dir, "plain");
    static const char *const no_code[] = {"direct.c.orig", "notes.txt", ".DS_Store", "Makefile", NULL};
    for (const char *const *n = no_code; *n; n++) {
        snprintf(path, sizeof path, "%s/%s", dir, *n);
        scratch_write(path, "\xff\xfe not code, not even UTF-8\n");
    }
    snprintf(path, sizeof path, "%s/old", dir);
    assert_int_equal(mkdir(path, 0755), 0);
    assert_int_equal(read_manifest(dir, &m, why, sizeof why), 2);
    assert_string_equal(why, "");
    bool direct = !strcmp(m.names[0], "direct.c") || !strcmp(m.names[1], "direct.c");
    bool header = !strcmp(m.names[0], "part3.h") || !strcmp(m.names[1], "part3.h");
    assert_true(direct && header);
}

/* Each entry here ends like code and is refused, the message describing it in the grader's words:
 * a refused name is never quoted (it could hold markup, and results.json is Markdown). */
static void test_manifest__code_that_cannot_be_built_is_refused(void **state)
{
    (void)state;
    static const struct { const char *name, *content, *expected; } cases[] = {
        {"x$(shell id>pwned).c", "", "characters other than a-z, 0-9 and _"},
        {"Direct.c", "int x;\n", "characters other than a-z, 0-9 and _"},
        {"my helpers.h", "", "characters other than a-z, 0-9 and _"},
        {"<img src=x onerror=alert(1)>.c", "", "characters other than a-z, 0-9 and _"},
        {"nul.c", NULL, "not UTF-8 text"},
        {"latin1.c", "int caf\xe9;\n", "not UTF-8 text"},
        {"linked.c", "", "a symbolic link"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char dir[256], path[512], why[256], name[32];
        grade_manifest m;
        snprintf(name, sizeof name, "refused%zu", i);
        fresh_part(dir, sizeof dir, name);
        snprintf(path, sizeof path, "%s/%s", dir, cases[i].name);
        if (!strcmp(cases[i].name, "linked.c")) assert_int_equal(symlink("/etc/passwd", path), 0);
        else if (!cases[i].content) {
            FILE *f = fopen(path, "wb");
            assert_non_null(f);
            assert_int_equal(fwrite("int a;\0int b;\n", 1, 14, f), 14);
            assert_int_equal(fclose(f), 0);
        }
        else scratch_write(path, cases[i].content);
        assert_int_equal(read_manifest(dir, &m, why, sizeof why), -1);
        if (!strstr(why, cases[i].expected) || !strstr(why, "parts/part3_direct"))
            fail_msg("%s: \"%s\", expected it to say \"%s\"", cases[i].name, why, cases[i].expected);
        if (strchr(cases[i].name, '$') || strchr(cases[i].name, '<') || strchr(cases[i].name, ' '))
            if (strstr(why, cases[i].name) || strchr(why, '<') || strchr(why, '$'))
                fail_msg("%s: the refusal quotes the name: \"%s\"", cases[i].name, why);
    }
}

/* No code at all, or too many files: refused, never an empty build. */
static void test_manifest__bounds(void **state)
{
    (void)state;
    char dir[256], path[512], why[256];
    grade_manifest m;
    snprintf(dir, sizeof dir, "%s/empty", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    assert_int_equal(read_manifest(dir, &m, why, sizeof why), -1);
    assert_non_null(strstr(why, "holds no .c file"));
    fresh_part(dir, sizeof dir, "many");
    for (int i = 0; i < GRADE_SOURCE_FILES; i++) {
        snprintf(path, sizeof path, "%s/extra%d.h", dir, i);
        scratch_write(path, "\n");
    }
    assert_int_equal(read_manifest(dir, &m, why, sizeof why), -1);
    assert_non_null(strstr(why, "holds over"));
}

int manifest_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_manifest__sources_taken_no_code_passed_over),
        cmocka_unit_test(test_manifest__code_that_cannot_be_built_is_refused),
        cmocka_unit_test(test_manifest__bounds),
    };
    return cmocka_run_group_tests_name("grader: the build's manifest", tests, scratch_setup, scratch_teardown);
}
