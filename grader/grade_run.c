/* Grader machinery: not part of any assignment. Children: own process group, limits, a timeout. */
#include "grade.h"
#include "../framework/clock.h"
#include <errno.h>
#include <grp.h>
#include <pwd.h>
#include <sched.h>
#include <fcntl.h>
#include <dirent.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* Limits for untrusted children: generous for a render of a grading case, small for a fork bomb,
 * a memory hog or a file flood. */
#define LIMIT_CPU_SECONDS 600
#define LIMIT_ADDRESS_SPACE ((rlim_t)8 << 30)
#define LIMIT_FILE_BYTES ((rlim_t)1 << 30)
#define LIMIT_OPEN_FILES 256
#define LIMIT_PROCESSES 256
#define LOG_CUT_NOTE "\n[grader: output cut here]\n"

static grade_sandbox sandbox;

/* RLIMIT_NPROC counts every process of the real user. As nobody that is the child's own; as the
 * grader's user it includes the grader's and the user's other processes, so the cap is what the user
 * already runs plus the child's allowance (a fork bomb still stops there). */
static long processes_of(uid_t uid)
{
    DIR *d = opendir("/proc");
    long n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        char path[300];
        struct stat st;
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        snprintf(path, sizeof path, "/proc/%s", e->d_name);
        n += stat(path, &st) == 0 && st.st_uid == uid;
    }
    if (d) closedir(d);
    return n;
}

grade_sandbox grade_sandbox_probe(void)
{
    memset(&sandbox, 0, sizeof sandbox);
    struct passwd *pw = getpwnam("nobody");
    if (geteuid() == 0 && pw) {
        sandbox.as_other_user = true;
        sandbox.uid = pw->pw_uid;
        sandbox.gid = pw->pw_gid;
    }
    /* A network namespace needs privilege; try it in a throwaway child. */
    pid_t pid = fork();
    if (pid == 0) _exit(unshare(CLONE_NEWNET) == 0 ? 0 : 1);
    int status = 1;
    if (pid > 0) waitpid(pid, &status, 0);
    sandbox.no_network = pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    sandbox.process_limit = sandbox.as_other_user ? LIMIT_PROCESSES : processes_of(getuid()) + LIMIT_PROCESSES;
    return sandbox;
}

void grade_sandbox_describe(const grade_sandbox *s, char *out, size_t size)
{
    snprintf(out, size, "%s%s", s->as_other_user ? "" : "not root: student code ran as your own user, "
                                                        "and could read what you can; ",
             s->no_network ? "" : "no network namespace: student code had the network; ");
    size_t n = strlen(out);
    if (n >= 2) out[n - 2] = '\0';  /* the last "; " */
}

/* Lowers a limit, never above the hard limit already in place (an unprivileged user cannot raise it). */
static void set_limit(int resource, rlim_t value)
{
    struct rlimit l;
    if (getrlimit(resource, &l) == 0 && l.rlim_max != RLIM_INFINITY && l.rlim_max < value) value = l.rlim_max;
    l.rlim_cur = l.rlim_max = value;
    setrlimit(resource, &l);
}

/* In the child, before exec: a group of its own (so the timeout kills every descendant), the pipe
 * to the grader as stdout and stderr (the grader writes the log, never the child), no stdin, and a
 * cap on every file it writes so a flood cannot fill the disk. */
static void child_setup(const grade_run_opts *o, int out_fd, int in_fd, int fd3)
{
    setpgid(0, 0);
    if (o->cwd && chdir(o->cwd) != 0) _exit(126);
    int in = open("/dev/null", O_RDONLY);
    if (in < 0 || out_fd < 0) _exit(126);
    dup2(in_fd > 0 ? in_fd : in, 0);
    dup2(out_fd, 1);
    dup2(out_fd, 2);
    /* The record pipe as fd 3; dup2 onto itself would keep close-on-exec, so clear it instead. */
    if (fd3 > 0 && (fd3 == 3 ? fcntl(3, F_SETFD, 0) : dup2(fd3, 3)) < 0) _exit(126);
    set_limit(RLIMIT_FSIZE, LIMIT_FILE_BYTES);
    set_limit(RLIMIT_CORE, 0);
    for (char *const *e = o->env; e && *e; e++) putenv(*e);
    if (!o->untrusted) return;
    set_limit(RLIMIT_CPU, LIMIT_CPU_SECONDS);
    set_limit(RLIMIT_AS, LIMIT_ADDRESS_SPACE);
    set_limit(RLIMIT_NOFILE, LIMIT_OPEN_FILES);
    if (sandbox.no_network && unshare(CLONE_NEWNET) != 0) _exit(126);
    if (sandbox.as_other_user) {
        /* Drop every privilege for good: groups, then gid, then uid (the order matters). */
        if (setgroups(0, NULL) != 0 || setgid(sandbox.gid) != 0 || setuid(sandbox.uid) != 0) _exit(126);
    }
    /* After the drop, so it counts nobody's processes; as the grader's user, probe set its size. */
    if (sandbox.process_limit > 0) set_limit(RLIMIT_NPROC, (rlim_t)sandbox.process_limit);
}

/* The log, created by the grader: a fresh file (O_EXCL), never a name the child planted (a symlink
 * to /etc/passwd stays untouched, O_NOFOLLOW), or /dev/null without a log. */
static int open_log(const char *path)
{
    if (!path) return open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (unlink(path) != 0 && errno != ENOENT) return -1;
    return open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
}

/* Moves what the child printed from the pipe to the log, keeping the first max bytes (max <= 0: all)
 * and dropping the rest, so a flood costs neither disk nor the grader's memory. Waits at most ms for
 * output; false once every writer has closed the pipe. */
static bool pump(int pipe_fd, int log_fd, long max, long *written, int ms)
{
    struct pollfd p = {pipe_fd, POLLIN, 0};
    if (poll(&p, 1, ms) <= 0) return true;
    char buf[16384];
    for (int rounds = 0; rounds < 64; rounds++) {  /* at most 1 MiB a call: the timeout stays checked */
        ssize_t n = read(pipe_fd, buf, sizeof buf);
        if (n == 0) return false;
        if (n < 0) return errno == EAGAIN || errno == EINTR;
        long room = max > 0 ? max - *written : n;
        if (room > 0 && write(log_fd, buf, (size_t)(n < room ? n : room)) < 0) return true;
        if (room >= 0 && n > room && write(log_fd, LOG_CUT_NOTE, sizeof LOG_CUT_NOTE - 1) < 0) return true;
        *written += n;
    }
    return true;
}

grade_run_result grade_run(char *const argv[], const grade_run_opts *o) { return grade_run_piped(argv, o, 0, 0); }

bool grade_pipe(int fds[2])
{
    if (pipe(fds) != 0) return false;
    if (fcntl(fds[0], F_SETFD, FD_CLOEXEC) == 0 && fcntl(fds[1], F_SETFD, FD_CLOEXEC) == 0) return true;
    close(fds[0]), close(fds[1]);
    return false;
}

grade_run_result grade_run_piped(char *const argv[], const grade_run_opts *o, int in_fd, int fd3)
{
    grade_run_result r = {false, -1, false, 0.0};
    double t0 = clock_seconds();
    int log_fd = open_log(o->log_path), fds[2] = {-1, -1};
    if (log_fd < 0 || !grade_pipe(fds)) {
        if (log_fd >= 0) close(log_fd);
        return r;
    }
    pid_t pid = fork();
    if (pid < 0) {
        close(log_fd), close(fds[0]), close(fds[1]);
        return r;
    }
    if (pid == 0) {
        child_setup(o, fds[1], in_fd, fd3);
        execvp(argv[0], argv);
        _exit(127);
    }
    setpgid(pid, pid);  /* also from the parent: no race with the first kill */
    close(fds[1]);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);

    /* Copy its output to the log until it ends or its time is up; then kill the whole group either
     * way, so no grandchild it left behind keeps running. */
    int status = 0;
    long written = 0;
    bool open_pipe = true;
    for (;;) {
        pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) break;
        if (clock_seconds() - t0 > o->wall_seconds) {
            r.timed_out = true;
            kill(-pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        if (open_pipe) open_pipe = pump(fds[0], log_fd, o->log_max, &written, 5);
        else nanosleep(&(struct timespec){0, 5 * 1000 * 1000}, NULL);  /* it closed its output, still runs */
    }
    kill(-pid, SIGKILL);
    while (open_pipe && pump(fds[0], log_fd, o->log_max, &written, 0)) {
        struct pollfd p = {fds[0], POLLIN, 0};  /* what is left in the pipe; stops when it is empty */
        if (poll(&p, 1, 0) <= 0) break;
    }
    close(fds[0]);
    close(log_fd);
    r.seconds = clock_seconds() - t0;
    if (!r.timed_out && WIFEXITED(status)) {
        r.exited = true;
        r.status = WEXITSTATUS(status);
    }
    else if (WIFSIGNALED(status))
        r.status = WTERMSIG(status);
    return r;
}

void grade_run_describe(const grade_run_result *r, char *out, size_t size)
{
    if (r->timed_out) snprintf(out, size, "timed out after %.0f s", r->seconds);
    else if (!r->exited) snprintf(out, size, "killed by signal %d (%s)", r->status, strsignal(r->status));
    else snprintf(out, size, "exited with status %d", r->status);
}
