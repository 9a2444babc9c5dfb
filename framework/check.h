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
 * their own assertions too. Part code does not call PL_CHECK: the grader refuses pl_check_failed.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_FRAMEWORK_CHECK_H
#define PL_FRAMEWORK_CHECK_H

#if defined(__GNUC__)
#define PL_CHECK(cond) (__builtin_expect(!!(cond), 1) ? (void)0 : pl_check_failed(#cond, __FILE__, __LINE__))
/* PL_HOT on a framework function's definition: the few that part code calls once per node, primitive
 * or random number (bvh_visit, scene_prim_intersect's counting, rng_uniform) are inlined into the
 * part's loop when the build links with LTO (the release build does), so the framework's
 * bookkeeping costs no call. They stay ordinary functions to the linker, the seam and the grader. */
#if defined(__clang__)  /* C's inline on an external definition may not touch a static (clang says so) */
#define PL_HOT __attribute__((always_inline))
#else                    /* gcc wants the inline beside always_inline */
#define PL_HOT __attribute__((always_inline)) inline
#endif
#define PL_UNLIKELY(cond) __builtin_expect(!!(cond), 0)
#else
#define PL_CHECK(cond) ((cond) ? (void)0 : pl_check_failed(#cond, __FILE__, __LINE__))
#define PL_HOT
#define PL_UNLIKELY(cond) (cond)
#endif

#if defined(__GNUC__)
__attribute__((cold))
#endif
void pl_check_failed(const char *what, const char *file, int line);

/* What a failed check does. Set once before any thread runs (a test suite's start); NULL restores
 * the default (print, abort). */
typedef void (*pl_check_handler)(const char *what, const char *file, int line);
void pl_check_set_handler(pl_check_handler handler);

#endif
