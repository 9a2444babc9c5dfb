/* PL_PART_API marks, in the framework's headers, each function with external linkage that part code
 * may call (as Lua marks its API with LUA_API). It expands to nothing: it is a promise, read by
 * people and checked by a test (tests/grader/test_allow.c) against the grader's allow-list
 * (grader/grade_allow.c) and against handout/README.md's "What your part may call". A framework
 * function without the mark is the framework's own: the grader refuses a part that calls it.
 * Every static inline helper of the framework's headers (vectors, colours, frames, rays, boxes) may
 * be called too; it needs no mark, since it leaves no symbol to check.
 * Parts may not call: none of these (it declares no function). */
#ifndef PL_PART_API_H
#define PL_PART_API_H

#define PL_PART_API

#endif
