/* Test machinery: not part of any assignment. A scratch folder per test group, made fresh under
 * /tmp (readable by everyone: the grader's tests run children as nobody in it) and removed whole at
 * the end, and small files written into it. */
#ifndef PL_TEST_SCRATCH_H
#define PL_TEST_SCRATCH_H

#include <stddef.h>

/* Makes /tmp/pathlab-<name>-XXXXXX into dir (mode 0755); 0, or -1 as a cmocka group setup returns. */
int scratch_make(char *dir, size_t size, const char *name);
/* Removes dir and everything in it; 0 or -1, as a cmocka group teardown returns. */
int scratch_remove(const char *dir);
/* Writes text to path (created or replaced), failing the test when it cannot. */
void scratch_write(const char *path, const char *text);

/* A file's scratch folder and its cmocka fixtures: SCRATCH_FOLDER(dir, "output") declares
 * char dir[64] and dir_setup / dir_teardown, which make and remove it. */
#define SCRATCH_FOLDER(var, name)                                                               \
    static char var[64];                                                                        \
    static int var##_setup(void **state) { (void)state; return scratch_make(var, sizeof var, name); } \
    static int var##_teardown(void **state) { (void)state; return scratch_remove(var); }

#endif
