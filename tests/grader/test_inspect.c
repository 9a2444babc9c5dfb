/* Test machinery: not part of any assignment. The object inspection (grader/grade_inspect.c), attacked
 * one rule at a time: each test compiles a small part file the way a student could write it (C with
 * attributes, or assembly in C) with the graded build's compiler, and checks the verdict the
 * inspection gives its object, and the words the student reads. Plain C written every usual way
 * passes; everything the runtime or the loader could run before main, every kind of symbol plain C
 * does not make, every name that would void the allow-list, and every bound, is refused. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_inspect.h"
#include "../../grader/grade_why.h"
#include "../../grader/grade_words.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

SCRATCH_FOLDER(scratch, "inspect-test")

/* The course's names, loaded once from the renderer (its libraries: libc, libm, libxml2, ...). */
static grade_inspect_course course;
static bool course_loaded;

static const grade_inspect_course *the_course(void)
{
    char why[512] = "";
    if (!course_loaded && !grade_inspect_course_load("bin/pathtracer", NULL, &course, why, sizeof why))
        fail_msg("cannot load the course's names: %s", why);
    course_loaded = true;
    return &course;
}

/* Compiles source (one file's text) into scratch/<name>.o with compiler cc and the graded build's
 * kind of flags (no LTO unless extra says so); fails the test when the compiler refuses it. */
static const char *compile_with(const char *cc, const char *name, const char *source, const char *extra)
{
    static char objects[8][300];
    static int next;
    char src[300], cmd[1024];
    char *obj = objects[next++ % 8];
    snprintf(src, sizeof src, "%s/%s.c", scratch, name);
    snprintf(obj, 300, "%s/%s.o", scratch, name);
    scratch_write(src, source);
    snprintf(cmd, sizeof cmd, "%s -std=c11 -O2 -g -Wno-attributes %s -c %s -o %s 2>%s/%s.log", cc, extra ? extra : "",
             src, obj, scratch, name);
    if (system(cmd) != 0) fail_msg("the compiler refused %s (%s/%s.log)", name, scratch, name);
    return obj;
}

static const char *compile(const char *name, const char *source, const char *extra)
{
    return compile_with("cc", name, source, extra);
}

/* The verdict on the given objects, and its words in *words. */
static grade_inspect_verdict inspect(const char *const *objects, int n, char *words, size_t size)
{
    static const char *const names[] = {"a.c", "b.c", "c.c"};
    grade_inspect_verdict v = grade_inspect_objects(objects, n, the_course());
    /* As the grader words it: the name kept only when the course knows it, the file the manifest's. */
    grade_why w = grade_why_of(GRADE_WHY_INSPECTION);
    w.inspect = v;
    grade_inspect_keep_known(&w.inspect, the_course());
    snprintf(w.file, sizeof w.file, "%s", v.object >= 0 && v.object < n ? names[v.object] : "?");
    words[0] = '\0';
    if (v.code != GRADE_INSPECT_OK) grade_words_why(&w, 1, "p", words, size);
    return v;
}

/* One file's verdict must be `code`, its words holding `says` (NULL: anything). */
static void expect_one(const char *name, const char *source, const char *extra, int code, const char *says)
{
    const char *obj = compile(name, source, extra);
    char words[768];
    grade_inspect_verdict v = inspect(&obj, 1, words, sizeof words);
    if (v.code != code) fail_msg("%s: expected verdict %d, got %d (%s)", name, code, v.code, words);
    if (code != GRADE_INSPECT_OK && says && !strstr(words, says))
        fail_msg("%s: expected the words to say '%s', got '%s'", name, says, words);
}

/* ---- plain C passes ------------------------------------------------------------------------ */

static void test_inspect__plain_c_of_every_usual_kind_passes(void **state)
{
    (void)state;
    expect_one("plain",
               "#include <math.h>\n#include <stdlib.h>\n#include <string.h>\n#include <stdio.h>\n"
               "static const float table[4] = {1, 2, 3, 4};\n"
               "static int counter;\n_Thread_local int per_thread;\n"
               "int shared_helper(int x) { return x * 2; }\n"
               "float f(float x) { per_thread++; counter++; char *p = malloc(16); memset(p, 0, 16); free(p);\n"
               "  printf(\"%g\\n\", (double)x); return sqrtf(x) + tanf(x) + (float)sin(x) + table[counter & 3]; }\n"
               "static double g(double *a, int n) { qsort(a, (size_t)n, sizeof *a, 0); return a[0]; }\n"
               "double (*use_g)(double *, int) = g;\n",
               NULL, GRADE_INSPECT_OK, NULL);
}

/* Clang's objects of plain C pass too: a student's laptop may build with it (macOS's cc is clang),
 * and make test-part<N> inspects what it built. Clang adds an address-significance table
 * (.llvm_addrsig, marked SHF_EXCLUDE) that GCC's objects never hold. Skipped without clang. */
static void test_inspect__plain_c_compiled_by_clang_passes(void **state)
{
    (void)state;
    if (system("command -v clang >/dev/null 2>&1") != 0) skip();
    const char *obj = compile_with("clang", "plain_clang",
                                   "#include <math.h>\n#include <stdlib.h>\n#include <string.h>\n"
                                   "static int counter;\nint helper(int x) { return x * 2; }\n"
                                   "float f(float x) { counter++; char *p = malloc(16); memset(p, 0, 16); free(p);\n"
                                   "  return sqrtf(x) + (float)helper(counter); }\n"
                                   "static int g(int a) { return a + 1; }\nint (*use_g)(int) = g;\n",
                                   "-g");
    char words[768];
    grade_inspect_verdict v = inspect(&obj, 1, words, sizeof words);
    if (v.code != GRADE_INSPECT_OK) fail_msg("clang's object of plain C was refused: %s", words);
}

/* A global of one file is the part's own for the others: a helper shared by two files. */
static void test_inspect__a_global_of_another_file_of_the_part_may_be_called(void **state)
{
    (void)state;
    const char *objs[2] = {compile("user", "int helper(int);\nint f(int x) { return helper(x) + 1; }\n", NULL),
                           compile("helper", "int helper(int x) { return x * 3; }\n", NULL)};
    char words[768];
    assert_int_equal(GRADE_INSPECT_OK, inspect(objs, 2, words, sizeof words).code);
}

/* ---- the allow-list cannot be voided --------------------------------------------------------- */

/* A static function named like a library's in a second file does not make the library's callable
 * from the first (before, any defined name counted, local ones included). */
static void test_inspect__a_local_name_never_defines_an_external_one(void **state)
{
    (void)state;
    const char *objs[2] = {
        compile("calls_open", "int open(const char *, int, ...);\nint f(void) { return open(\"/x\", 0); }\n", NULL),
        compile("static_open", "static int open(const char *p, int m) { return p[0] + m; }\n"
                               "int g(void) { return open(\"y\", 1); }\n", NULL)};
    char words[768];
    grade_inspect_verdict v = inspect(objs, 2, words, sizeof words);
    assert_int_equal(GRADE_INSPECT_CALL, v.code);
    assert_int_equal(0, v.object);
    if (!strstr(words, "parts" "/p/a.c: calls 'open', a C library function"))
        fail_msg("expected the words to name the library's open, got '%s'", words);
}

/* A call to a name no list holds and no file defines as global is described, never quoted: the
 * name is the student's (it could hold markup, or a byte of a secret). */
static void test_inspect__an_unknown_name_is_described_never_quoted(void **state)
{
    (void)state;
    expect_one("unknown", "void pl_secret_name_x9(void);\nvoid f(void) { pl_secret_name_x9(); }\n", NULL,
               GRADE_INSPECT_CALL, "a static function of another file?");
    char words[768];
    const char *obj = compile("unknown2", "void pl_secret_name_x9(void);\nvoid f(void) { pl_secret_name_x9(); }\n", NULL);
    inspect(&obj, 1, words, sizeof words);
    assert_null(strstr(words, "pl_secret_name_x9"));
}

/* A symbol versioned by hand reaches another definition than the list's. */
static void test_inspect__a_versioned_reference_is_not_the_listed_name(void **state)
{
    (void)state;
    expect_one("symver", "__asm__(\".symver memcpy_old, memcpy@GLIBC_2.2.5\");\nvoid *memcpy_old(void *, const void *, "
               "unsigned long);\nvoid f(char *a, char *b) { memcpy_old(a, b, 4); }\n", NULL, GRADE_INSPECT_CALL, NULL);
}

static void test_inspect__a_framework_function_without_the_mark_is_named(void **state)
{
    (void)state;
    expect_one("framework", "struct x; int counters_take(void);\nint f(void) { return counters_take(); }\n", NULL,
               GRADE_INSPECT_CALL, NULL);
}

/* ---- nothing runs before main ---------------------------------------------------------------- */

static void test_inspect__constructors_destructors_and_runtime_sections_are_refused(void **state)
{
    (void)state;
    expect_one("ctor", "volatile int hit;\n__attribute__((constructor)) static void c(void) { hit = 1; }\n", NULL,
               GRADE_INSPECT_BEFORE_MAIN, "has a .init_array section");
    expect_one("dtor", "volatile int hit;\n__attribute__((destructor)) static void d(void) { hit = 2; }\n", NULL,
               GRADE_INSPECT_BEFORE_MAIN, ".fini_array");
    expect_one("init", "__attribute__((section(\".init\"))) void i(void) {}\n", NULL, GRADE_INSPECT_BEFORE_MAIN,
               "has a .init section");
    expect_one("tm_clone", "__attribute__((section(\".tm_clone_table\"), used)) static void *t[2] = {0, 0};\n", NULL,
               GRADE_INSPECT_BEFORE_MAIN, ".tm_clone_table");
    expect_one("ctors", "static void c(void) {}\n__attribute__((section(\".ctors.00001\"), used)) static void (*p)(void) = c;\n",
               NULL, GRADE_INSPECT_BEFORE_MAIN, ".ctors");
    /* An array of constructors under a name of the student's: refused by its type, named by kind. */
    expect_one("init_array_type", "static void c(void) {}\n__asm__(\".section .mine,\\\"aw\\\",@init_array\\n.quad c\\n"
               ".text\");\nvoid (*keep)(void) = c;\n", NULL, GRADE_INSPECT_BEFORE_MAIN, "an array of functions the C runtime calls");
}

static void test_inspect__an_ifunc_is_refused(void **state)
{
    (void)state;
    expect_one("ifunc", "static int real(void) { return 1; }\nstatic int (*resolve(void))(void) { return real; }\n"
               "int f(void) __attribute__((ifunc(\"resolve\")));\n", NULL, GRADE_INSPECT_IFUNC, "IFUNC");
}

/* The names the runtime and the loader call a program by are all reserved ones. */
static void test_inspect__names_the_runtime_calls_are_refused(void **state)
{
    (void)state;
    static const char *const names[] = {"_init", "_fini", "__gmon_start__", "_ITM_registerTMCloneTable", "main", "_start"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char source[160], file[32];
        snprintf(source, sizeof source, "void %s(void);\nvoid %s(void) {}\n", names[i], names[i]);
        snprintf(file, sizeof file, "reserved%zu", i);
        expect_one(file, source, NULL, GRADE_INSPECT_RESERVED, "reserved to the C implementation");
    }
}

static void test_inspect__a_library_function_may_not_be_replaced(void **state)
{
    (void)state;
    expect_one("malloc", "#include <stddef.h>\nvoid *malloc(size_t n) { (void)n; return 0; }\n", NULL,
               GRADE_INSPECT_REDEFINES, "defines 'malloc', which a library of the program already defines");
}

/* ---- only the kinds of section and symbol plain C makes -------------------------------------- */

static void test_inspect__sections_of_other_kinds_are_refused(void **state)
{
    (void)state;
    expect_one("own_section", "__attribute__((section(\".mine\"), used)) static int x = 1;\n", NULL,
               GRADE_INSPECT_SECTION, "a kind plain C does not compile to");
    /* Executable data, by flags spliced into the assembler's directive. */
    expect_one("exec_data", "__attribute__((section(\".data.x,\\\"awx\\\",@progbits#\"), used)) static int x = 1;\n",
               NULL, GRADE_INSPECT_SECTION, NULL);
    /* Clang's table's name on data of another kind, or on data the program would load: the name
     * alone earns nothing (the table is let through by its type and its flag, excluded from links). */
    expect_one("fake_addrsig", "__attribute__((section(\".llvm_addrsig\"), used)) static int x = 1;\n", NULL,
               GRADE_INSPECT_SECTION, NULL);
    expect_one("fake_addrsig_loaded",
               "__asm__(\".section .llvm_addrsig,\\\"ae\\\",@0x6fff4c03\\n.long 1\\n.text\");\n", NULL,
               GRADE_INSPECT_SECTION, NULL);
    expect_one("lto", "int f(int x) { return x + 1; }\n", "-flto", GRADE_INSPECT_BYTECODE, "bytecode");
}

static void test_inspect__symbols_of_other_kinds_are_refused(void **state)
{
    (void)state;
    expect_one("absolute", "__asm__(\".globl answer\\n.set answer, 0x1234\");\n", NULL, GRADE_INSPECT_SYMBOL_KIND, NULL);
    expect_one("unique", "__asm__(\".section .data.u,\\\"aw\\\"\\n.globl u\\n.type u, @gnu_unique_object\\nu: .long 1\\n"
               ".text\");\n", NULL, GRADE_INSPECT_SYMBOL_KIND, NULL);
}

/* ---- bounds ------------------------------------------------------------------------------------ */

/* Tens of thousands of sections (before, they pushed a real .init_array past the cut of a tool's
 * listing): refused whole at the bound, whatever comes after. */
static void test_inspect__too_many_sections_or_symbols_are_refused(void **state)
{
    (void)state;
    size_t size = 8 << 20;
    char *source = malloc(size);
    assert_non_null(source);
    size_t len = 0;
    for (int i = 0; i < GRADE_INSPECT_SECTIONS + 10; i++)
        len += (size_t)snprintf(source + len, size - len, "__attribute__((section(\".data.s%d\"), used)) static int s%d = 1;\n", i, i);
    snprintf(source + len, size - len, "volatile int hit;\n__attribute__((constructor)) static void c(void) { hit = 1; }\n");
    expect_one("sections", source, NULL, GRADE_INSPECT_BOUND, "sections");
    len = 0;
    for (int i = 0; i < GRADE_INSPECT_SYMBOLS + 10; i++)
        len += (size_t)snprintf(source + len, size - len, "int v%d;\n", i);
    expect_one("symbols", source, NULL, GRADE_INSPECT_BOUND, "symbols");
    free(source);
}

int inspect_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inspect__plain_c_of_every_usual_kind_passes),
        cmocka_unit_test(test_inspect__plain_c_compiled_by_clang_passes),
        cmocka_unit_test(test_inspect__a_global_of_another_file_of_the_part_may_be_called),
        cmocka_unit_test(test_inspect__a_local_name_never_defines_an_external_one),
        cmocka_unit_test(test_inspect__an_unknown_name_is_described_never_quoted),
        cmocka_unit_test(test_inspect__a_versioned_reference_is_not_the_listed_name),
        cmocka_unit_test(test_inspect__a_framework_function_without_the_mark_is_named),
        cmocka_unit_test(test_inspect__constructors_destructors_and_runtime_sections_are_refused),
        cmocka_unit_test(test_inspect__an_ifunc_is_refused),
        cmocka_unit_test(test_inspect__names_the_runtime_calls_are_refused),
        cmocka_unit_test(test_inspect__a_library_function_may_not_be_replaced),
        cmocka_unit_test(test_inspect__sections_of_other_kinds_are_refused),
        cmocka_unit_test(test_inspect__symbols_of_other_kinds_are_refused),
        cmocka_unit_test(test_inspect__too_many_sections_or_symbols_are_refused),
    };
    int failed = cmocka_run_group_tests_name("grader: the object inspection", tests, scratch_setup, scratch_teardown);
    grade_inspect_course_free(&course);
    return failed;
}
