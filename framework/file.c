/* Files: whole-file reads with a type and size check first, atomic writes. */
#include "file.h"
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
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
    /* The checks on the open descriptor, not the name: what is read is what was checked. */
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
    /* NUL-terminated for the text parsers; the length stays exact for binary readers. */
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

/* Case-insensitive, as file managers show extensions (x.PNG is a PNG). */
bool file_has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

/* ---- writing --------------------------------------------------------------------------------- */

/* Temporary files still to be removed if the process is told to stop. The handler may only walk
 * plain memory (async-signal-safe: no malloc, no stdio, no locks), so an entry is a pointer to the
 * file_temp's own name, published before its flag is set; any name the kernel accepts fits. The
 * mutex orders registrations from the output module's encoder threads; a thread holds it only with
 * the stop signals blocked, so the handler never interrupts its holder. */
static const char *volatile temp_paths[FILE_MAX_TEMPS];
static volatile sig_atomic_t temp_used[FILE_MAX_TEMPS];
static bool cleanup_installed;
static pthread_mutex_t temp_lock = PTHREAD_MUTEX_INITIALIZER;

/* The handler: remove every registered temporary, then die of the same signal (the exit status
 * the shell expects of a killed program). */
static void remove_temps_and_die(int sig)
{
    for (int i = 0; i < FILE_MAX_TEMPS; i++)
        if (temp_used[i]) unlink(temp_paths[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void block_stop_signals(sigset_t *old)
{
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &block, old);
}

/* Installs the handler once; called with the stop signals blocked and temp_lock held. */
static void install_cleanup(void)
{
    if (cleanup_installed) return;
    struct sigaction sa, old_action;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = remove_temps_and_die;
    static const int stops[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++) {
        /* A signal the user chose to ignore (nohup, a background job's SIGINT) stays ignored. */
        if (sigaction(stops[i], NULL, &old_action) == 0 && old_action.sa_handler == SIG_IGN) continue;
        sigaction(stops[i], &sa, NULL);
    }
    cleanup_installed = true;
}

/* A free slot, or -1 when the table is full; called with the stop signals blocked and temp_lock held. */
static int temp_free_slot(void)
{
    for (int i = 0; i < FILE_MAX_TEMPS; i++)
        if (!temp_used[i]) return i;
    return -1;
}

static void temp_forget(int slot)
{
    if (slot >= 0) temp_used[slot] = 0;
}

pl_status file_temp_create(const char *path, file_temp *t, pl_diag *diag)
{
    memset(t, 0, sizeof *t);
    t->slot = -1;
    /* In the target's folder (rename cannot cross filesystems), hidden, with a random suffix that
     * mkstemp creates with O_CREAT | O_EXCL: a name planted in advance, even a symlink, makes it
     * pick another name instead of following it. */
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    size_t n = strlen(path) + 16;
    t->tmp = malloc(n);
    t->path = strdup(path);
    if (!t->tmp || !t->path) {
        file_temp_discard(t);
        return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    }
    snprintf(t->tmp, n, "%.*s.%s.XXXXXX", (int)dir_len, path, path + dir_len);
    /* Create and register with the stop signals blocked: a signal in between would find a file
     * the handler does not know. One that arrives meanwhile is delivered at the unblock, and then
     * removes this file too. A full table refuses rather than leave a file untracked. */
    sigset_t old;
    block_stop_signals(&old);
    pthread_mutex_lock(&temp_lock);
    install_cleanup();
    int fd = -1, err = 0, slot = temp_free_slot();
    if (slot >= 0 && (fd = mkstemp(t->tmp)) < 0) err = errno;
    if (fd >= 0) {
        temp_paths[slot] = t->tmp;  /* the name first, then the flag the handler reads */
        temp_used[slot] = 1;
        t->slot = slot;
    }
    pthread_mutex_unlock(&temp_lock);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (fd < 0) {
        pl_status st = err ? pl_fail(diag, PL_ERR_IO, "%s: cannot write into its folder: %s", path, strerror(err))
                           : pl_fail(diag, PL_ERR_IO, "%s: cannot write: already %d temporary files open (the most "
                                     "one process tracks for cleanup)", path, FILE_MAX_TEMPS);
        free(t->tmp);
        t->tmp = NULL;
        file_temp_discard(t);
        return st;
    }
    /* mkstemp makes the file 0600; an output is an ordinary file: 0666 less the umask. */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) { /* keep 0600: still correct, only less shared */ }
    t->f = fdopen(fd, "wb");
    if (!t->f) {
        close(fd);
        pl_status st = pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
        file_temp_discard(t);
        return st;
    }
    return PL_OK;
}

/* Close, reporting the errors a buffered FILE keeps until then (a full disk, a quota). */
pl_status file_temp_close(file_temp *t, pl_diag *diag)
{
    if (!t->f) return PL_OK;
    bool ok = !ferror(t->f);
    ok = fclose(t->f) == 0 && ok;  /* a full disk often shows only here */
    t->f = NULL;
    if (!ok) return pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", t->path, strerror(errno ? errno : EIO));
    return PL_OK;
}

/* rename() within one folder is atomic: a reader sees the old file or the new one, never half. */
pl_status file_temp_commit(file_temp *t, pl_diag *diag)
{
    pl_status st = file_temp_close(t, diag);
    if (st == PL_OK && rename(t->tmp, t->path) != 0)
        st = pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", t->path, strerror(errno));
    if (st == PL_OK) {
        temp_forget(t->slot);
        t->slot = -1;
        free(t->tmp);
        t->tmp = NULL;
    }
    file_temp_discard(t);
    return st;
}

void file_temp_discard(file_temp *t)
{
    if (t->f) fclose(t->f);
    if (t->tmp) unlink(t->tmp);
    temp_forget(t->slot);
    free(t->tmp);
    free(t->path);
    memset(t, 0, sizeof *t);
    t->slot = -1;
}

pl_status file_write_atomic(const char *path, const void *data, size_t len, pl_diag *diag)
{
    file_temp t;
    pl_status st = file_temp_create(path, &t, diag);
    if (st) return st;
    if (fwrite(data, 1, len, t.f) != len) {
        st = pl_fail(diag, PL_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
        file_temp_discard(&t);
        return st;
    }
    return file_temp_commit(&t, diag);
}
