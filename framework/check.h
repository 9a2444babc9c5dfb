/* Framework invariants: PL_CHECK(cond) states what must hold at a point of the framework's code (an
 * index in range, a sample range in order), so that a broken invariant stops at the line that broke
 * it, naming it, instead of corrupting an image or a verdict further on. Bad input is never a
 * check: it gets a located message and a status (status.h). A check is for bugs, the framework's
 * or a part's (a traversal asking for node -1).
 *
 * Always compiled in, in the renderer, the tests and the grader alike: each check is one branch the
 * processor predicts, on values already in registers, so renders take no measurable time more (and
 * they stay byte-identical: a check never changes a value).
 *
 * On failure pl_check_failed calls the handler: by default it prints "file:line: check failed:
 * cond" and aborts (a render or a grading stage stops at the bug); the test suites install one that
 * fails the running test with the same text (tests/common/filter.c), so the tests use PL_CHECK for
 * their own assertions too. Part code does not call PL_CHECK: the grader refuses pl_check_failed. */
#ifndef PL_FRAMEWORK_CHECK_H
#define PL_FRAMEWORK_CHECK_H

#define PL_CHECK(cond) ((cond) ? (void)0 : pl_check_failed(#cond, __FILE__, __LINE__))

void pl_check_failed(const char *what, const char *file, int line);

/* What a failed check does. Set once before any thread runs (a test suite's start); NULL restores
 * the default (print, abort). */
typedef void (*pl_check_handler)(const char *what, const char *file, int line);
void pl_check_set_handler(pl_check_handler handler);

#endif
