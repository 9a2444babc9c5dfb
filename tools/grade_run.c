/* Grader machinery: not part of any assignment. Children: own process group, limits, a timeout. */
#include "grade.h"
#include <errno.h>
#include <grp.h>
#include <pwd.h>
#include <sched.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Limits for untrusted children: generous for a render of a grading case, small for a fork bomb,
 * a memory hog or a file flood. */
#define LIMIT_CPU_SECONDS 600
#define LIMIT_ADDRESS_SPACE ((rlim_t)8 << 30)
#define LIMIT_FILE_BYTES ((rlim_t)1 << 30)
#define LIMIT_OPEN_FILES 256
#define LIMIT_PROCESSES 256

static grade_sandbox sandbox;

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
    return sandbox;
}

static void set_limit(int resource, rlim_t value)
{
    struct rlimit l = {value, value};
    setrlimit(resource, &l);
}

/* In the child, before exec: a group of its own (so the timeout kills every descendant), the log
 * as stdout and stderr, no stdin, and a cap on every file it writes so a flood cannot fill the disk. */
static void child_setup(const grade_run_opts *o)
{
    setpgid(0, 0);
    if (o->cwd && chdir(o->cwd) != 0) _exit(126);
    int in = open("/dev/null", O_RDONLY);
    int log = o->log_path ? open(o->log_path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644) : -1;
    if (in < 0 || (o->log_path && log < 0)) _exit(126);
    dup2(in, 0);
    if (log >= 0) {
        dup2(log, 1);
        dup2(log, 2);
    }
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
        set_limit(RLIMIT_NPROC, LIMIT_PROCESSES);  /* counts nobody's processes, not the grader's */
    }
}

grade_run_result grade_run(char *const argv[], const grade_run_opts *o)
{
    grade_run_result r = {false, 0, false, 0.0};
    double t0 = now();
    pid_t pid = fork();
    if (pid < 0) {
        r.status = -1;
        return r;
    }
    if (pid == 0) {
        child_setup(o);
        execvp(argv[0], argv);
        _exit(127);
    }
    setpgid(pid, pid);  /* also from the parent: no race with the first kill */

    /* Wait, polling, until it ends or its time is up; then kill the whole group either way, so no
     * grandchild it left behind keeps running. */
    int status = 0;
    for (;;) {
        pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) break;
        if (now() - t0 > o->wall_seconds) {
            r.timed_out = true;
            kill(-pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        struct timespec nap = {0, 5 * 1000 * 1000};
        nanosleep(&nap, NULL);
    }
    kill(-pid, SIGKILL);
    r.seconds = now() - t0;
    if (!r.timed_out && WIFEXITED(status)) {
        r.exited = true;
        r.status = WEXITSTATUS(status);
    }
    else if (WIFSIGNALED(status))
        r.status = WTERMSIG(status);
    struct stat st;  /* cut a flood to its first log_max bytes (truncate would also grow a short file) */
    if (o->log_path && o->log_max > 0 && stat(o->log_path, &st) == 0 && st.st_size > o->log_max) {
        int cut = truncate(o->log_path, o->log_max);
        (void)cut;  /* a log that stays long is no verdict's business */
    }
    return r;
}

void grade_run_describe(const grade_run_result *r, char *out, size_t size)
{
    if (r->timed_out) snprintf(out, size, "timed out after %.0f s", r->seconds);
    else if (!r->exited) snprintf(out, size, "killed by signal %d (%s)", r->status, strsignal(r->status));
    else snprintf(out, size, "exited with status %d", r->status);
}
