/* Test machinery: not part of any assignment. The release stripper's rules (course/release/strip.h). */
#include "../../tests/common/test.h"  /* a test suite (make test-course), so it shares the suites' asserts */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "strip.h"

/* Split literals, so this file holds no marker and passes through a release unchanged. */
#define BEGIN "/* BEGIN " "SOLUTION */"
#define END "/* END " "SOLUTION */"
#define STUB(code) "/* STUB" ": " code " */"

/* Strips in and checks the result is exactly want. */
static void assert_strips_to(const char *in, const char *want)
{
    pl_diag diag = pl_diag_default();
    char *out = NULL;
    pl_status s = strip_text(in, strlen(in), "t.c", &out, &diag);
    if (s != PL_OK) fail_msg("strip_text failed: %s", diag.error);
    assert_non_null(out);
    assert_string_equal(want, out);
    free(out);
}

/* Strips in, expects a parse error whose message starts with where ("t.c:3:") and holds what. */
static void assert_rejected(const char *in, const char *where, const char *what)
{
    pl_diag diag = pl_diag_default();
    char *out = (char *)"untouched";
    pl_status s = strip_text(in, strlen(in), "t.c", &out, &diag);
    assert_int_equal(PL_ERR_PARSE, s);
    assert_string_equal("untouched", out);
    if (strncmp(diag.error, where, strlen(where)) != 0 || !strstr(diag.error, what))
        fail_msg("expected an error at %s saying '%s', got '%s'", where, what, diag.error);
    /* Check mode (no output) judges the same way. */
    assert_int_equal(PL_ERR_PARSE, strip_text(in, strlen(in), "t.c", NULL, &diag));
}

static void test_strip__replaces_region_by_stub(void **state)
{
    (void)state;
    assert_strips_to("int f(void)\n"
                     "{\n"
                     "    " BEGIN "\n"
                     "    int x = 2;\n"
                     "    return x;\n"
                     "    " END "\n"
                     "    " STUB("return PL_TODO(\"1.1\", \"f\");") "\n"
                     "}\n",
                     "int f(void)\n"
                     "{\n"
                     "    return PL_TODO(\"1.1\", \"f\");\n"
                     "}\n");
}

static void test_strip__keeps_stub_indentation(void **state)
{
    (void)state;
    assert_strips_to("\t\t" BEGIN "\n\t\tx = 1;\n\t\t" END "\n\t  " STUB("x = 0;") "\n",
                     "\t  x = 0;\n");
}

static void test_strip__removes_file_scope_region_without_stub(void **state)
{
    (void)state;
    assert_strips_to("#include <math.h>\n" BEGIN "\nstatic int helper(void) { return 1; }\n" END "\n\nint g;\n",
                     "#include <math.h>\n\nint g;\n");
}

static void test_strip__removed_region_between_blank_lines_leaves_one(void **state)
{
    (void)state;
    assert_strips_to("int a;\n\n" BEGIN "\nstatic int helper;\n" END "\n\nint b;\n", "int a;\n\nint b;\n");
    assert_strips_to(BEGIN "\nstatic int helper;\n" END "\n\nint b;\n", "int b;\n");
    /* Blank lines elsewhere are the author's: kept as they are. */
    assert_strips_to("int a;\n\n\nint b;\n", "int a;\n\n\nint b;\n");
}

static void test_strip__copies_file_without_markers_unchanged(void **state)
{
    (void)state;
    const char *text = "/* no markers */\nint main(void) { return 0; }\nlast line without newline";
    assert_strips_to(text, text);
}

static void test_strip__empty_file_stays_empty(void **state)
{
    (void)state;
    assert_strips_to("", "");
}

static void test_strip__keeps_crlf_line_endings(void **state)
{
    (void)state;
    assert_strips_to("a\r\n  " BEGIN "\r\n  b;\r\n  " END "\r\n  " STUB("c;") "\r\nd\r\n",
                     "a\r\n  c;\r\nd\r\n");
}

static void test_strip__stub_at_end_of_file_without_newline(void **state)
{
    (void)state;
    assert_strips_to(BEGIN "\nx\n" END "\n" STUB("y();"), "y();");
}

static void test_strip__rejects_unterminated_region_at_its_begin(void **state)
{
    (void)state;
    assert_rejected("a\nb\n" BEGIN "\nc\n", "t.c:3:", "never closed");
}

static void test_strip__rejects_nested_begin(void **state)
{
    (void)state;
    assert_rejected(BEGIN "\n" BEGIN "\n" END "\n" END "\n", "t.c:2:", "opened at line 1");
}

static void test_strip__rejects_end_without_begin(void **state)
{
    (void)state;
    assert_rejected("x\n" END "\n", "t.c:2:", "without a BEGIN");
}

static void test_strip__rejects_stub_not_after_end(void **state)
{
    (void)state;
    assert_rejected("x\n" STUB("y;") "\n", "t.c:2:", "not directly after");
    /* A blank line between the END and its STUB makes the STUB stray too. */
    assert_rejected(BEGIN "\n" END "\n\n" STUB("y;") "\n", "t.c:4:", "not directly after");
}

static void test_strip__rejects_stub_inside_region(void **state)
{
    (void)state;
    assert_rejected(BEGIN "\n" STUB("y;") "\n" END "\n", "t.c:2:", "inside a solution region");
}

static void test_strip__rejects_marker_sharing_its_line(void **state)
{
    (void)state;
    assert_rejected("int x; " BEGIN "\n" END "\n", "t.c:1:", "alone on its line");
    assert_rejected(BEGIN "\n" END "\n    return 0; " STUB("y;") "\n", "t.c:3:", "nothing else");
}

static void test_strip__rejects_empty_stub(void **state)
{
    (void)state;
    assert_rejected(BEGIN "\n" END "\n" STUB("") "\n", "t.c:3:", "empty STUB");
}


/* Each near-miss marker, alone on line 3 of a function body, is refused at t.c:3: as a marker
 * look-alike (a failure names the test's line: PL_AT). */
static void expect_near_misses_refused(const char *const *near, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        char in[256];
        snprintf(in, sizeof in, "int f(void)\n{\n    %s\n    return 42;\n}\n", near[i]);
        pl_diag diag = pl_diag_default();
        char *out = NULL;
        pl_status s = strip_text(in, strlen(in), "t.c", &out, &diag);
        free(out);
        if (s != PL_ERR_PARSE || strncmp(diag.error, "t.c:3:", 6) != 0 || !strstr(diag.error, "looks like a solution marker"))
            PL_FAIL("near miss %zu '%s': expected an error at t.c:3:, got status %d '%s'", i, near[i], s, diag.error);
    }
}
#define expect_near_misses_refused(...) PL_AT(expect_near_misses_refused(__VA_ARGS__))

/* Regression (issue 7, defect 13): a marker spelt almost right used to be copied into the release as
 * plain text, with the solution under it. Every near miss is an error at its line. The literals are
 * split so that this file holds no near miss itself. */
static void test_strip__rejects_near_miss_markers(void **state)
{
    (void)state;
    const char *near[] = {
        "/* BEGIN" " SOLUTION  */", "/*  BEGIN" " SOLUTION */", "// BEGIN" " SOLUTION", "/*BEGIN" " SOLUTION*/",
        "/* begin" " solution */", "/* Begin" " Solution */", "/* BEGIN" "_SOLUTION */", "/* BEGIN" "  SOLUTION */",
        "/* END" " SOLUTION  */", "// END" " SOLUTION", "/*END" " SOLUTION*/", "/* end" " solution */",
        "/* STUB" " : return 0; */", "// STUB" ": return 0;", "/*STUB" ": return 0; */", "/* stub" ": return 0; */",
        "/* STUB" " */", "int x; // END" " SOLUTION",
    };
    expect_near_misses_refused(near, sizeof near / sizeof near[0]);
    /* Prose that names the words is not a marker. */
    assert_strips_to("/* Stub bookkeeping: which tasks ran. */\n/* The end of the solution space. */\n",
                     "/* Stub bookkeeping: which tasks ran. */\n/* The end of the solution space. */\n");
}

/* Regression (issue 7 audit): the words swapped or plural, glued or joined by '_' or '-', in a line
 * comment or on a block comment's inner line, passed the stripper and the solution under them was
 * copied. Each is refused at its line, quoting the words. */
static void test_strip__rejects_swapped_and_plural_markers(void **state)
{
    (void)state;
    const char *near[] = {
        "/* SOLUTION" " BEGIN */", "/* SOLUTION" " END */", "/* BEGIN" " SOLUTIONS */", "/* END" " SOLUTIONS */",
        "// SOLUTION" " BEGIN", "// begin" " solutions", "/* solution" "_begin */", "/* Solutions" "-End */",
        "/* BEGIN" "SOLUTION */", "/*SOLUTION" "END*/", "/* end" "_solution */", "int x; /* TODO: SOLUTION" " END */",
    };
    expect_near_misses_refused(near, sizeof near / sizeof near[0]);
    /* Inside a block comment the words need no opener on their line. */
    assert_rejected("int f(void)\n{\n    /*\n     * SOLUTION" " BEGIN\n     */\n    return 42;\n}\n", "t.c:4:",
                    "`SOLUTION" " BEGIN` looks like a solution marker");
    /* Prose that only mentions the words, and code outside comments, are not markers. */
    assert_strips_to("/* The solution, at the end. */\n/* solutions: begin with the tests */\nint end_" "solution;\n",
                     "/* The solution, at the end. */\n/* solutions: begin with the tests */\nint end_" "solution;\n");
}

/* Regression (issue 7, defect 13): a region in a function body without a STUB used to vanish, leaving
 * the student a function with part of its body silently gone. */
static void test_strip__rejects_region_in_function_body_without_stub(void **state)
{
    (void)state;
    assert_rejected("int f(void)\n{\n    " BEGIN "\n    return 1;\n    " END "\n}\n", "t.c:3:", "no STUB line");
    assert_rejected("int f(void)\n{\n    " BEGIN "\n    return 1;\n    " END "\n", "t.c:3:", "no STUB line");
    assert_rejected("struct s { int a; };\nint f(void) {\n    if (1) {\n" BEGIN "\nx();\n" END "\n    }\n}\n", "t.c:4:",
                    "no STUB line");
    /* At file scope, even after braces in strings, characters and comments, a region may go whole. */
    assert_strips_to("const char *s = \"{\", c = '{';\n/* { */ // {\nint f(void) { return 1; }\n" BEGIN
                     "\nstatic int h(void) { return 2; }\n" END "\nint g;\n",
                     "const char *s = \"{\", c = '{';\n/* { */ // {\nint f(void) { return 1; }\nint g;\n");
}

/* ---- banners ----------------------------------------------------------------------------- */

#define BANNER(part, id, fn) "/* === PART " part " | TASK " id " | " fn " ========\n * Does it.\n * ======== */\n"
#define TASK_BODY(id, fn) "{\n    " BEGIN "\n    return 1;\n    " END "\n    " STUB("return PL_TODO(\"" id "\", \"" fn "\");") "\n}\n"

static pl_status tasks_of(const char *in, strip_task **tasks, int *n, pl_diag *diag)
{
    *tasks = NULL;
    *n = -1;
    return strip_tasks(in, strlen(in), "t.c", tasks, n, diag);
}

static void assert_tasks_rejected(const char *in, const char *where, const char *what)
{
    pl_diag diag = pl_diag_default();
    strip_task *tasks;
    int n;
    assert_int_equal(PL_ERR_PARSE, tasks_of(in, &tasks, &n, &diag));
    if (strncmp(diag.error, where, strlen(where)) != 0 || !strstr(diag.error, what))
        fail_msg("expected an error at %s saying '%s', got '%s'", where, what, diag.error);
}

static void test_strip_tasks__lists_banners_in_order(void **state)
{
    (void)state;
    const char *in = "#include \"x.h\"\n\n"
                     BANNER("2", "2.1", "f") "int f(void)\n" TASK_BODY("2.1", "f") "\n"
                     BANNER("2", "2.2", "g") "pl_status g(int *out)\n" TASK_BODY("2.2", "g");
    pl_diag diag = pl_diag_default();
    strip_task *tasks;
    int n;
    pl_status s = tasks_of(in, &tasks, &n, &diag);
    if (s != PL_OK) fail_msg("strip_tasks failed: %s", diag.error);
    assert_int_equal(2, n);
    assert_int_equal(2, tasks[0].part);
    assert_string_equal("2.1", tasks[0].id);
    assert_string_equal("f", tasks[0].function);
    assert_int_equal(3, tasks[0].line);
    assert_string_equal("2.2", tasks[1].id);
    assert_string_equal("g", tasks[1].function);
    free(tasks);
}

/* A stub macro's name may hold digits (PL_TODO_VEC2, part 9's): it still names its task. */
static void test_strip_tasks__stub_macro_with_digits_names_its_task(void **state)
{
    (void)state;
    const char *in = BANNER("9", "9.1", "f") "vec2 f(void)\n{\n    " BEGIN "\n    return v;\n    " END "\n    "
                     STUB("return PL_TODO_VEC2(\"9.1\", \"f\");") "\n}\n";
    pl_diag diag = pl_diag_default();
    strip_task *tasks;
    int n;
    if (tasks_of(in, &tasks, &n, &diag) != PL_OK) fail_msg("strip_tasks failed: %s", diag.error);
    assert_int_equal(1, n);
    assert_string_equal("9.1", tasks[0].id);
    free(tasks);
}

static void test_strip_tasks__file_without_banners_has_no_tasks(void **state)
{
    (void)state;
    pl_diag diag = pl_diag_default();
    strip_task *tasks;
    int n;
    assert_int_equal(PL_OK, tasks_of("int x;\n", &tasks, &n, &diag));
    assert_int_equal(0, n);
    assert_null(tasks);
}

static void test_strip_tasks__rejects_stub_naming_another_task(void **state)
{
    (void)state;
    assert_tasks_rejected(BANNER("1", "1.2", "f") "int f(void)\n" TASK_BODY("1.3", "f"), "t.c:9:",
                          "PL_TODO*(\"1.2\", \"f\")");
    assert_tasks_rejected(BANNER("1", "1.2", "f") "int f(void)\n" TASK_BODY("1.2", "g"), "t.c:9:",
                          "PL_TODO*(\"1.2\", \"f\")");
}

static void test_strip_tasks__rejects_banner_without_stub(void **state)
{
    (void)state;
    assert_tasks_rejected(BANNER("1", "1.1", "f") "int f(void)\n{\n    " BEGIN "\n    return 1;\n    " END "\n}\n",
                          "t.c:9:", "expected a STUB");
    assert_tasks_rejected(BANNER("1", "1.1", "f") "int f(void)\n{\n    return 1;\n}\n", "t.c:1:",
                          "without a solution region");
}

static void test_strip_tasks__rejects_banner_above_another_function(void **state)
{
    (void)state;
    assert_tasks_rejected(BANNER("1", "1.1", "f") "int g(void)\n" TASK_BODY("1.1", "f"), "t.c:4:",
                          "definition of f()");
}

static void test_strip_tasks__rejects_part_and_task_that_disagree(void **state)
{
    (void)state;
    assert_tasks_rejected(BANNER("2", "1.1", "f") "int f(void)\n" TASK_BODY("1.1", "f"), "t.c:1:", "PART 2");
    assert_tasks_rejected("/* === PART 2 TASK 2.1 f ===\n */\n", "t.c:1:", "expected a banner");
}

static void test_strip_tasks__rejects_todo_stub_without_banner(void **state)
{
    (void)state;
    assert_tasks_rejected("int f(void)\n" TASK_BODY("1.1", "f"), "t.c:6:", "no task banner");
}

int strip_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strip__replaces_region_by_stub),
        cmocka_unit_test(test_strip__keeps_stub_indentation),
        cmocka_unit_test(test_strip__removes_file_scope_region_without_stub),
        cmocka_unit_test(test_strip__removed_region_between_blank_lines_leaves_one),
        cmocka_unit_test(test_strip__copies_file_without_markers_unchanged),
        cmocka_unit_test(test_strip__empty_file_stays_empty),
        cmocka_unit_test(test_strip__keeps_crlf_line_endings),
        cmocka_unit_test(test_strip__stub_at_end_of_file_without_newline),
        cmocka_unit_test(test_strip__rejects_unterminated_region_at_its_begin),
        cmocka_unit_test(test_strip__rejects_nested_begin),
        cmocka_unit_test(test_strip__rejects_end_without_begin),
        cmocka_unit_test(test_strip__rejects_stub_not_after_end),
        cmocka_unit_test(test_strip__rejects_stub_inside_region),
        cmocka_unit_test(test_strip__rejects_marker_sharing_its_line),
        cmocka_unit_test(test_strip__rejects_empty_stub),
        cmocka_unit_test(test_strip__rejects_near_miss_markers),
        cmocka_unit_test(test_strip__rejects_swapped_and_plural_markers),
        cmocka_unit_test(test_strip__rejects_region_in_function_body_without_stub),
        cmocka_unit_test(test_strip_tasks__lists_banners_in_order),
        cmocka_unit_test(test_strip_tasks__stub_macro_with_digits_names_its_task),
        cmocka_unit_test(test_strip_tasks__file_without_banners_has_no_tasks),
        cmocka_unit_test(test_strip_tasks__rejects_stub_naming_another_task),
        cmocka_unit_test(test_strip_tasks__rejects_banner_without_stub),
        cmocka_unit_test(test_strip_tasks__rejects_banner_above_another_function),
        cmocka_unit_test(test_strip_tasks__rejects_part_and_task_that_disagree),
        cmocka_unit_test(test_strip_tasks__rejects_todo_stub_without_banner),
    };
    return cmocka_run_group_tests_name("strip", tests, NULL, NULL);
}
