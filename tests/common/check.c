/* Test machinery: not part of any assignment. */
#include "test.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <math.h>

/* ---- failure messages, kept for the XML results (test.h) --------------------------------------- */

static char failure_text[4096];
static size_t failure_len;

void pl_vprint_error(const char *format, va_list args)
{
    va_list copy;
    va_copy(copy, args);
    vfprintf(stderr, format, args);
    if (failure_len < sizeof failure_text - 1) {
        int n = vsnprintf(failure_text + failure_len, sizeof failure_text - failure_len, format, copy);
        if (n > 0) failure_len += (size_t)n < sizeof failure_text - failure_len ? (size_t)n : sizeof failure_text - 1 - failure_len;
    }
    va_end(copy);
}

void pl_print_error(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    pl_vprint_error(format, args);
    va_end(args);
}

/* cmocka's own failure, with the kept messages as its text when the results are XML (on the
 * console they were printed already). */
static void fail_with_messages(const char *file, int line)
{
    const char *mode = getenv("CMOCKA_MESSAGE_OUTPUT");
    char text[sizeof failure_text];
    snprintf(text, sizeof text, "%s", failure_text);
    failure_len = 0;
    failure_text[0] = '\0';
    size_t n = strlen(text);
    while (n > 0 && text[n - 1] == '\n') text[--n] = '\0';  /* cmocka adds its own newline */
    if (mode && !strcasecmp(mode, "xml") && n > 0) _assert_true(0, text, file, line);
    _fail(file, line);
}

static bool far(float a, float b, float eps) { return !(fabsf(a - b) <= eps); }  /* NaN is far */

void check_vec3_near(vec3 e, vec3 g, float eps, const char *what, const char *file, int line)
{
    if (far(e.x, g.x, eps) || far(e.y, g.y, eps) || far(e.z, g.z, eps)) {
        print_error("%s: wrong: expected (%.6g, %.6g, %.6g), got (%.6g, %.6g, %.6g) (tolerance %g)\n",
                    what, e.x, e.y, e.z, g.x, g.y, g.z, eps);
        check_fail(file, line);
    }
}

void check_rgb_near(rgb e, rgb g, float eps, const char *what, const char *file, int line)
{
    if (far(e.r, g.r, eps) || far(e.g, g.g, eps) || far(e.b, g.b, eps)) {
        print_error("%s: wrong: expected rgb(%.6g, %.6g, %.6g), got rgb(%.6g, %.6g, %.6g) (tolerance %g)\n",
                    what, e.r, e.g, e.b, g.r, g.g, g.b, eps);
        check_fail(file, line);
    }
}

void check_float_near(double e, double g, double eps, const char *what, const char *file, int line)
{
    if (!(fabs(e - g) <= eps)) {
        print_error("%s: wrong: expected %.12g, got %.12g (tolerance %g)\n", what, e, g, eps);
        check_fail(file, line);
    }
}

/* ---- call sites: the failing test's own line ---------------------------------------------------- */
/* The outermost PL_AT call site of the running test; only the outermost one is kept, which is the
 * test's own line however deep the helpers nest. */
static const char *at_file;
static int at_line, at_depth;

void pl_at_push(const char *file, int line)
{
    if (at_depth++ == 0) {
        at_file = file;
        at_line = line;
    }
}

void pl_at_pop(void)
{
    if (at_depth > 0) at_depth--;
}

void check_fail(const char *file, int line)
{
    /* A failure ends the test (cmocka longjmps out), so the next test starts with no call site. */
    bool nested = at_depth > 0;
    at_depth = 0;
    if (nested) {
        print_error("(failed in a helper at %s:%d)\n", file, line);
        fail_with_messages(at_file, at_line);
    }
    fail_with_messages(file, line);
}

void check_fail_msg(const char *file, int line, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    print_error("ERROR: ");
    vprint_error(format, args);
    print_error("\n");
    va_end(args);
    check_fail(file, line);
}

void check_true(bool cond, const char *what, const char *file, int line)
{
    if (!cond) {
        print_error("wrong: expected %s\n", what);
        check_fail(file, line);
    }
}

void check_failed_invariant(const char *what, const char *file, int line) { check_true(false, what, file, line); }

void check_implemented(const char *file, int line)
{
    if (pl_todo_count() > 0) {
        print_error("not implemented: %s is still a stub\n", pl_todo_last() ? pl_todo_last() : "a task");
        check_fail(file, line);
    }
}

bool pl_test_split;

int pl_test_threads(int wanted) { return pl_test_split ? 1 : wanted; }

int test_setup(void **state)
{
    (void)state;
    pl_todo_set_quiet(true);
    pl_todo_reset();
    at_depth = 0;
    failure_len = 0;  /* a message printed by an earlier, passing test is not this test's */
    failure_text[0] = '\0';
    return 0;
}

void check_hit(bool found, bool expected, const char *what, const char *file, int line)
{
    check_implemented(file, line);
    if (found != expected) {
        print_error("%s: wrong: expected a %s, got a %s\n", what, expected ? "hit" : "miss", found ? "hit" : "miss");
        check_fail(file, line);
    }
}
