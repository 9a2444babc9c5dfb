/* Test machinery: not part of any assignment. Scratch folders (scratch.h). */
#include "scratch.h"
#include "test.h"
#include "../../framework/file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int scratch_make(char *dir, size_t size, const char *name)
{
    if (snprintf(dir, size, "/tmp/pathlab-%s-XXXXXX", name) >= (int)size) return -1;
    return mkdtemp(dir) && chmod(dir, 0755) == 0 ? 0 : -1;
}

int scratch_remove(const char *dir)
{
    /* rm -rf rather than a walk in C: a test may leave read-only folders or files of another user
     * (children run as nobody), which rm handles as root the way a walk would have to again. */
    char cmd[600];
    if (!dir[0] || strchr(dir, '\'') || snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir) >= (int)sizeof cmd) return -1;
    return system(cmd) == 0 ? 0 : -1;
}

void scratch_write(const char *path, const char *text)
{
    pl_diag d = pl_diag_default();
    if (file_write_atomic(path, text, strlen(text), &d) != PL_OK) fail_msg("cannot write %s: %s", path, d.error);
}
