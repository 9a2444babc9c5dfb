/* Test machinery: not part of any assignment.
 * Shared cmocka asserts that print both values, and the "not implemented" check that turns a
 * stub call into a clear message instead of a wrong-value failure. Include after <cmocka.h>'s
 * prerequisites: use tests/common/test.h, which includes everything in the right order. */
#ifndef PL_CHECK_H
#define PL_CHECK_H

#include "../../framework/vec.h"
#include "../../framework/todo.h"
#include "../../framework/check.h"

void check_vec3_near(vec3 expected, vec3 got, float eps, const char *what, const char *file, int line);
void check_rgb_near(rgb expected, rgb got, float eps, const char *what, const char *file, int line);
void check_float_near(double expected, double got, double eps, const char *what, const char *file, int line);
void check_implemented(const char *file, int line);

/* Fails with both vectors printed when any component differs by more than eps. */
#define assert_vec3_near(expected, got, eps) check_vec3_near((expected), (got), (eps), #got, __FILE__, __LINE__)
#define assert_rgb_near(expected, got, eps) check_rgb_near((expected), (got), (eps), #got, __FILE__, __LINE__)
#define assert_float_near(expected, got, eps) check_float_near((expected), (got), (eps), #got, __FILE__, __LINE__)
/* Fails with "not implemented: Part N, task N.M: fn()" if a stub ran since the last reset.
 * Call pl_todo_reset() in setup (test_setup does), then this after calling student code. */
#define assert_implemented() check_implemented(__FILE__, __LINE__)

/* A hit/miss query on student code: "not implemented" for a stub, else "wrong" naming the call. */
#define assert_hit(call) check_hit((call), true, #call, __FILE__, __LINE__)
#define assert_miss(call) check_hit((call), false, #call, __FILE__, __LINE__)
void check_hit(bool found, bool expected, const char *what, const char *file, int line);

/* A helper that several tests call reports a failure at the calling test's line, not its own: wrap
 * its calls with PL_AT, e.g. right after the helper's definition
 *     #define check_direct(...) PL_AT(check_direct(__VA_ARGS__))
 * (a macro does not expand inside itself, so the inner name is the function). The checks here and
 * in mc_assert.h then fail at the outermost PL_AT call site and name the helper's line as well.
 * The helper must return void. */
#define PL_AT(call) (pl_at_push(__FILE__, __LINE__), (call), pl_at_pop())
void pl_at_push(const char *file, int line);
void pl_at_pop(void);
/* cmocka's _fail at the outermost PL_AT call site if there is one, else at file:line. */
void check_fail(const char *file, int line);
/* fail_msg that a PL_AT helper may call: prints "ERROR: <message>" and fails at the outermost PL_AT
 * call site (cmocka's fail_msg always names its own line, which in a helper is the helper's). */
#define PL_FAIL(...) check_fail_msg(__FILE__, __LINE__, __VA_ARGS__)
void check_fail_msg(const char *file, int line, const char *format, ...) CMOCKA_PRINTF_ATTRIBUTE(3, 4);

/* PL_CHECK(cond) is the framework's (framework/check.h): in a suite a failed one, in a test or in
 * framework code the test called, prints the expression and fails the test at the calling test's
 * line (through PL_AT helpers too). PL_CHECK_NEAR(expected, got, eps) prints both values. */
#define PL_CHECK_NEAR(expected, got, eps) check_float_near((expected), (got), (eps), #got, __FILE__, __LINE__)
void check_true(bool cond, const char *what, const char *file, int line);
/* The suites' handler of a failed PL_CHECK (pl_run_group installs it): fails the running test. */
void check_failed_invariant(const char *what, const char *file, int line);

/* cmocka setup/teardown that reset and silence the stub counter; use for every student-code test. */
int test_setup(void **state);

/* The grader's split suites (grader/seam/seam.h) run the part's functions in one process and the test
 * in another, which replays their answers in the order they were given: there a test calls part code
 * from one thread at a time. pl_test_split is set before main in those binaries only. */
extern bool pl_test_split;
/* The threads a test may use to call part code: `wanted`, or 1 in a split suite. */
int pl_test_threads(int wanted);

#endif
