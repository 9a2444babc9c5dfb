/* Grader machinery: not part of any assignment.
 * What keeps the answers from student code, beside the child's own limits
 * (grade_run.c). Student code runs as `nobody` when the grader is root; then:
 * - the references, the hidden cases, the course's solutions (parts/) and the grader's own outputs
 *   (results.json, report/) sit in folders only root may enter (grade_guard_secrets);
 * - the child writes only into folders made for it (grade_guard_child_dir), never into one that
 *   holds a log or a result, so it cannot plant a name the grader would later follow;
 * - a file the child wrote is opened by the grader without following a symlink and only when it is
 *   a regular file (grade_guard_open_child_file): a render "written" as a link to a reference
 *   would otherwise be read, as root, and compared with itself. */
#include "grade_guard.h"
#include "grade_fmt.h"
#include "grade_run.h"
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A folder only its owner may enter, and its owner root, not nobody. */
static bool make_private(const char *path, const grade_sandbox *s)
{
    struct stat st;
    if (lstat(path, &st) != 0) return errno == ENOENT;  /* nothing to hide */
    if (S_ISREG(st.st_mode)) return chmod(path, 0600) == 0;  /* a worktree's .git: a pointer only */
    if (!S_ISDIR(st.st_mode)) return false;
    if (st.st_uid == s->uid && chown(path, 0, 0) != 0) return false;
    return chmod(path, 0700) == 0;
}

bool grade_guard_secrets(const grade_secrets *secrets, const grade_sandbox *s, char *why, size_t size)
{
    if (!s->as_other_user) return true;  /* the child is the grader's own user: nothing a mode can hide */
    /* What they are, and why each, is the plan's (grade_plan_secrets): the folders become root's
     * alone; a file (results.json), readable by root alone. */
    for (int k = 0; k < secrets->count; k++) {
        const char *path = secrets->path[k];
        if (secrets->file[k] ? chmod(path, 0600) != 0 && errno != ENOENT : !make_private(path, s))
            return grade_msg(why, size, "cannot make %s private to root", path), false;
    }
    return true;
}

bool grade_guard_child_dir(const char *path, const grade_sandbox *s, bool contained)
{
    char *rm[] = {"rm", "-rf", (char *)path, NULL};  /* rm never follows a link it deletes */
    grade_run_opts o = {.wall_seconds = 60};
    grade_run_result r = grade_run(rm, &o);
    if (!r.exited || r.status != 0 || mkdir(path, 0755) != 0) return false;
    return !(contained && s->as_other_user) || chown(path, s->uid, s->gid) == 0;
}

bool grade_guard_own_dir(const char *path)
{
    return grade_guard_child_dir(path, NULL, false) && chmod(path, 0700) == 0;
}

int grade_guard_open_child_file(const char *path, long max_bytes)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    if (fd < 0) return -1;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > max_bytes) {
        close(fd);
        errno = EINVAL;
        return -1;
    }
    return fd;
}
