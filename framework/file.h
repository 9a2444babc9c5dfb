/* Files: the one place that reads a whole input file and writes an output file.
 *
 * Inputs are untrusted: a scene or camera file may be a FIFO, /dev/zero, or gigabytes long. So a
 * reader refuses anything that is not a regular file, and anything over its caller's size cap,
 * before reading a byte. Outputs go through a temporary file in the target folder and a rename, so
 * a killed render never leaves a half-written file where the output should be.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_FILE_H
#define PL_FILE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "status.h"

/* ---- reading --------------------------------------------------------------------------------- */

/* Reads the regular file at path, at most max_bytes long, into a new NUL-terminated buffer
 * (*data, free with free(); *len excludes the NUL). `what` names the file's role in messages
 * ("scene", "camera settings"). Refuses directories, FIFOs, devices and files over the cap with
 * PL_ERR_IO and a message naming the path and the limit. */
pl_status file_read_all(const char *path, const char *what, size_t max_bytes, char **data, size_t *len,
                        pl_diag *diag);

/* True when path ends in ext (".png"), in any letter case. */
bool file_has_extension(const char *path, const char *ext);

/* ---- writing --------------------------------------------------------------------------------- */

/* A temporary file beside its final path, open for writing. It is created exclusively (a name an
 * attacker planted, even a symlink, is never opened), removed if the process gets SIGINT, SIGTERM
 * or SIGHUP, and becomes path only at file_temp_commit. At most FILE_MAX_TEMPS exist at once (more
 * than every file one render writes): one more is refused, never left untracked. */
#define FILE_MAX_TEMPS 16
typedef struct {
    FILE *f;     /* write here */
    char *tmp;   /* its name, ".<name>.XXXXXX" in path's folder */
    char *path;  /* the final name */
    int slot;    /* its entry in the cleanup table */
} file_temp;

pl_status file_temp_create(const char *path, file_temp *t, pl_diag *diag);
/* Closes the file, reporting any write error (a full disk); the temporary stays until commit. */
pl_status file_temp_close(file_temp *t, pl_diag *diag);
/* Closes and renames into place; on failure the temporary is removed. Either way t is released. */
pl_status file_temp_commit(file_temp *t, pl_diag *diag);
/* Removes the temporary and releases t (safe on a released or zeroed t with slot -1). */
void file_temp_discard(file_temp *t);

/* Writes len bytes to path through a temporary file and rename: all or nothing. */
pl_status file_write_atomic(const char *path, const void *data, size_t len, pl_diag *diag);

#endif
