/* Files: whole-file reads with a type and size check first, atomic writes. */
#include "file.h"
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- reading --------------------------------------------------------------------------------- */

pl_status file_read_all(const char *path, const char *what, size_t max_bytes, char **data, size_t *len,
                        pl_diag *diag)
{
    *data = NULL;
    *len = 0;
    /* O_NONBLOCK: opening a FIFO must not wait for a writer; the type check below refuses it. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return pl_fail(diag, PL_ERR_IO, "%s: cannot open %s: %s", path, what, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        pl_status s = pl_fail(diag, PL_ERR_IO, "%s: cannot read %s: %s", path, what, strerror(errno));
        close(fd);
        return s;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return pl_fail(diag, PL_ERR_IO, "%s: expected a regular file for the %s, found %s", path, what,
                       S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ? "a pipe" : "a device or socket");
    }
    if ((unsigned long long)st.st_size > max_bytes) {
        close(fd);
        return pl_fail(diag, PL_ERR_IO, "%s: the %s is %lld bytes; the limit is %zu", path, what,
                       (long long)st.st_size, max_bytes);
    }
    /* Read one byte more than fstat promised: a file that grows while we read is caught at the cap. */
    size_t want = (size_t)st.st_size;
    char *buf = malloc(want + 2);
    if (!buf) {
        close(fd);
        return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory for a %zu-byte %s", path, want, what);
    }
    size_t got = 0;
    while (got < want + 1) {
        ssize_t n = read(fd, buf + got, want + 1 - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            pl_status s = pl_fail(diag, PL_ERR_IO, "%s: cannot read %s: %s", path, what, strerror(errno));
            free(buf);
            close(fd);
            return s;
        }
        if (n == 0) break;
        got += (size_t)n;
    }
    close(fd);
    if (got > max_bytes) {
        free(buf);
        return pl_fail(diag, PL_ERR_IO, "%s: the %s grew past the limit of %zu bytes while being read", path, what,
                       max_bytes);
    }
    buf[got] = '\0';
    *data = buf;
    *len = got;
    return PL_OK;
}

/* ---- writing --------------------------------------------------------------------------------- */

pl_status file_write_atomic(const char *path, const void *data, size_t len, pl_diag *diag)
{
    size_t n = strlen(path) + 32;
    char *tmp = malloc(n);
    if (!tmp) return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    snprintf(tmp, n, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        pl_status s = pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
        free(tmp);
        return s;
    }
    bool ok = fwrite(data, 1, len, f) == len;
    ok = (fclose(f) == 0) && ok;
    if (!ok || rename(tmp, path) != 0) {
        pl_status s = pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
        remove(tmp);
        free(tmp);
        return s;
    }
    free(tmp);
    return PL_OK;
}
