/* Stubs for student tasks.
 * The release replaces each solution with a line such as `return PL_TODO_RGB("3.4", "direct_hemisphere");`.
 * A stub prints "Part 3, task 3.4: direct_hemisphere() is not implemented yet" once per function,
 * counts the call (tests read the count to say "not implemented" instead of "wrong"), and returns
 * a neutral value: magenta for radiance, so a missing part shows in the picture, never as black.
 * Parts may not call: pl_todo_count, pl_todo_reset, pl_todo_handled, pl_todo_last, pl_todo_set_quiet (the
 * grader refuses them; the functions marked PL_PART_API are theirs). */
#ifndef PL_TODO_H
#define PL_TODO_H

#include "part_api.h"

#include <stdbool.h>
#include "status.h"
#include "vec.h"
#include "ray.h"

/* Reports the missing task (once per function name) and counts the call. */
PL_PART_API void pl_todo_report(const char *task, const char *function);

/* How many stub calls have happened since the last reset (all threads). */
int pl_todo_count(void);
void pl_todo_reset(void);
/* The framework has a fallback for the stub call just reported (part 2's bvh_build: the linear
 * scan), so it is no missing work: takes it back out of the count and of pl_todo_last. The line
 * printed for it stays, so the student still learns the task is open. */
void pl_todo_handled(void);
/* The function name of the most recent stub call, or NULL. */
const char *pl_todo_last(void);
/* Silences the printed line (tests keep stdout clean); counting continues. */
void pl_todo_set_quiet(bool quiet);

static inline pl_status pl_todo_status(const char *task, const char *fn) { pl_todo_report(task, fn); return PL_ERR_TODO; }
static inline rgb pl_todo_rgb(const char *task, const char *fn) { pl_todo_report(task, fn); return rgb_magenta(); }
static inline bool pl_todo_false(const char *task, const char *fn) { pl_todo_report(task, fn); return false; }
static inline ray pl_todo_ray(const char *task, const char *fn)
{
    pl_todo_report(task, fn);
    return ray_make(vec3_make(0, 0, 0), vec3_make(0, 0, -1), 0.0f, 0.0f);
}

static inline vec2 pl_todo_vec2(const char *task, const char *fn) { pl_todo_report(task, fn); return vec2_make(0.0f, 0.0f); }
static inline vec3 pl_todo_vec3(const char *task, const char *fn) { pl_todo_report(task, fn); return vec3_make(0.0f, 0.0f, 1.0f); }

#define PL_TODO(task, fn) pl_todo_status(task, fn)
#define PL_TODO_RGB(task, fn) pl_todo_rgb(task, fn)
#define PL_TODO_FALSE(task, fn) pl_todo_false(task, fn)
#define PL_TODO_RAY(task, fn) pl_todo_ray(task, fn)
#define PL_TODO_VEC2(task, fn) pl_todo_vec2(task, fn)
#define PL_TODO_VEC3(task, fn) pl_todo_vec3(task, fn)

#endif
