/* Grader machinery: not part of any assignment. Children: own process group, limits, a timeout. */
#include "grade_run.h"
#include "grade_limits.h"
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
#include "sandbox.h"

#define LOG_CUT_NOTE "\n[grader: output cut here]\n"

extern char **environ;

/* Lowers a limit, never above the hard limit already in place (an unprivileged user cannot raise it). */
static void set_limit(int resource, rlim_t value)
{
    struct rlimit l;
    if (getrlimit(resource, &l) == 0 && l.rlim_max != RLIM_INFINITY && l.rlim_max < value) value = l.rlim_max;
    l.rlim_cur = l.rlim_max = value;
    setrlimit(resource, &l);
}

/* CPU time and memory, for every child that runs student code or reads what it made. */
static void stage_limits(const grade_run_opts *o)
{
    set_limit(RLIMIT_CPU, (rlim_t)(o->wall_seconds * GRADE_CPU_PER_WALL) + 5);
#ifndef __SANITIZE_ADDRESS__
    /* (Not in a grader built with AddressSanitizer, make SAN=1: the child is a fork of it until exec,
     * with terabytes of shadow reserved, and could not allocate the filter under any limit.) */
    set_limit(RLIMIT_AS, (rlim_t)(o->compiler ? GRADE_COMPILER_MEMORY : GRADE_CODE_MEMORY));
#endif
}

/* The limits, the namespaces, the private view and the drop to the sandbox's user, for a child
 * that runs or compiles student code. */
static void confine(const grade_run_opts *o)
{
    /* Fails closed: an untrusted child without the grading's settings never runs unconfined. */
    if (!o->sandbox) _exit(126);
    const grade_sandbox *sb = o->sandbox;
    stage_limits(o);
    set_limit(RLIMIT_NOFILE, SANDBOX_EXEC_FD + 1);  /* sandbox_exec lowers it by one more */
#ifdef __linux__
    if (sb->no_network && unshare(CLONE_NEWNET | CLONE_NEWIPC) != 0) _exit(126);
#endif
    /* Still root: from here on the process that continues is inside new PID and mount namespaces,
     * where it sees everything read-only but its output, and /tmp, /var/tmp, /dev/shm of its own. */
    if (sb->isolated) {
        sandbox_isolate();
        /* The sandbox's folder stays in view (else the stage's own folder: a test's scratch). */
        if (!sandbox_private_view(sb->dir ? sb->dir : o->cwd, o->writable, GRADE_TMP_BYTES) ||
            (o->cwd && chdir(o->cwd) != 0))
            _exit(126);
    }
    if (sb->as_other_user) {
        /* Drop every privilege for good: groups, then gid, then uid (the order matters). */
        if (setgroups(0, NULL) != 0 || setgid(sb->gid) != 0 || setuid(sb->uid) != 0) _exit(126);
    }
    /* After the drop, so it counts nobody's processes; as the grader's user, probe set its size. */
    if (sb->process_limit > 0) set_limit(RLIMIT_NPROC, (rlim_t)sb->process_limit);
}

/* In the child, before exec: a group of its own (so the timeout kills every descendant), the pipe
 * to the grader as stdout and stderr (the grader writes the log, never the child), the capture's
 * pipe at its number, in_fd (> 0) as stdin or else none, fd3 (> 0) as its fd 3 (the split suite's
 * record pipe, grade_tests.c), and a cap on every file it writes so a flood cannot fill the disk. */
static void child_setup(const grade_run_opts *o, int out_fd, int capture_fd, int in_fd, int fd3)
{
    setpgid(0, 0);
    if (o->cwd && chdir(o->cwd) != 0) _exit(126);
    int in = open("/dev/null", O_RDONLY);
    if (in < 0 || out_fd < 0) _exit(126);
    dup2(in_fd > 0 ? in_fd : in, 0);
    dup2(out_fd, 1);
    dup2(out_fd, 2);
    if (o->capture && (dup2(capture_fd, o->capture->child_fd) < 0 ||
                       fcntl(o->capture->child_fd, F_SETFD, 0) != 0))  /* dup2 onto itself keeps CLOEXEC */
        _exit(126);
    /* The record pipe as fd 3; dup2 onto itself would keep close-on-exec, so clear it instead. */
    if (fd3 > 0 && (fd3 == 3 ? fcntl(3, F_SETFD, 0) : dup2(fd3, 3)) < 0) _exit(126);
    set_limit(RLIMIT_FSIZE, (rlim_t)GRADE_FILE_BYTES);
    set_limit(RLIMIT_CORE, 0);
    /* Student code gets none of the grader's environment (whatever its caller exported), a PATH only. */
    if (o->untrusted) {
        /* A fresh array (putenv below may write into it): this child's own, never the grader's. */
        char **clean = calloc(3, sizeof *clean);
        if (!clean) _exit(126);
        clean[0] = "PATH=/usr/local/bin:/usr/bin:/bin", clean[1] = "LC_ALL=C";
        environ = clean;
    }
    for (char *const *e = o->env; e && *e; e++) putenv(*e);
    if (o->untrusted) confine(o);
    else if (o->bounded) stage_limits(o);
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

/* Moves what arrived on the capture's pipe into its buffer, keeping the first max bytes; false once
 * the child closed it. */
static bool collect(int fd, grade_capture *c)
{
    char buf[65536];
    for (int rounds = 0; rounds < 64; rounds++) {
        ssize_t n = read(fd, buf, sizeof buf);
        if (n == 0) return false;
        if (n < 0) return errno == EAGAIN || errno == EINTR;
        long keep = c->len + n <= c->max ? n : c->max - c->len;
        c->overflow |= keep < n;
        if (keep > 0) {
            char *grown = realloc(c->data, (size_t)(c->len + keep));
            if (!grown) return c->overflow = true, false;
            memcpy(grown + c->len, buf, (size_t)keep);
            c->data = grown;
            c->len += keep;
        }
    }
    return true;
}

/* Until the child ends or its time is up: its output to the log, its capture to memory. Returns the
 * wait status; r->timed_out when it was killed for time, r->cpu_seconds what the kernel counted. */
static int watch(pid_t pid, const grade_run_opts *o, int out_fd, int log_fd, int cap_fd, grade_run_result *r)
{
    double t0 = clock_seconds();
    int status = 0;
    long written = 0;
    struct rusage usage = {0};
    bool out_open = true, cap_open = cap_fd >= 0;
    for (;;) {
        pid_t w = wait4(pid, &status, WNOHANG, &usage);
        if (w == pid || (w < 0 && errno != EINTR)) break;
        if (clock_seconds() - t0 > o->wall_seconds) {
            r->timed_out = true;
            kill(-pid, SIGKILL);
            wait4(pid, &status, 0, &usage);
            break;
        }
        struct pollfd p[2] = {{out_open ? out_fd : -1, POLLIN, 0}, {cap_open ? cap_fd : -1, POLLIN, 0}};
        if (poll(p, 2, 5) <= 0) continue;  /* also when both closed: it still runs */
        if (p[0].revents) out_open = pump(out_fd, log_fd, o->log_max, &written, 0);
        if (p[1].revents) cap_open = collect(cap_fd, o->capture);
    }
    /* What is left in the pipes, and a descendant that still holds them cannot keep this waiting. */
    kill(-pid, SIGKILL);
    while (out_open && pump(out_fd, log_fd, o->log_max, &written, 0)) {
        struct pollfd p = {out_fd, POLLIN, 0};
        if (poll(&p, 1, 0) <= 0) break;
    }
    while (cap_open && collect(cap_fd, o->capture)) {
        struct pollfd p = {cap_fd, POLLIN, 0};
        if (poll(&p, 1, 0) <= 0) break;
    }
    r->output_cut = o->log_max > 0 && written > o->log_max;
    /* The kernel's count of the child's CPU time, its waited-for descendants' included (a namespace's
     * relay waits for its init, which waits for the confined process): the one measure of a child's
     * work the grader scores, since nothing the child says about itself is trusted. */
    r->cpu_seconds = (double)usage.ru_utime.tv_sec + 1e-6 * (double)usage.ru_utime.tv_usec +
                     (double)usage.ru_stime.tv_sec + 1e-6 * (double)usage.ru_stime.tv_usec;
    return status;
}

bool grade_pipe(int fds[2])
{
    if (pipe(fds) != 0) return false;
    if (fcntl(fds[0], F_SETFD, FD_CLOEXEC) == 0 && fcntl(fds[1], F_SETFD, FD_CLOEXEC) == 0) return true;
    close(fds[0]), close(fds[1]);
    return false;
}

grade_run_result grade_run(char *const argv[], const grade_run_opts *o) { return grade_run_piped(argv, o, 0, 0); }

/* One job in a helper: its result comes back whole through the pipe (a helper that died sends
 * nothing, and its job reads as not exited). */
static pid_t start_job(char *const argv[], const grade_run_opts *o, int *from_helper)
{
    int fds[2];
    if (!grade_pipe(fds)) return -1;
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        sandbox_adopt_orphans();  /* its job's orphans come here, and its grade_run kills them */
        grade_run_result r = grade_run(argv, o);
        _exit(write(fds[1], &r, sizeof r) == (ssize_t)sizeof r ? 0 : 1);
    }
    close(fds[1]);
    if (pid < 0) close(fds[0]);
    *from_helper = fds[0];
    return pid;
}

void grade_run_jobs(int n, char *const *const argv[], const grade_run_opts o[], grade_run_result r[], bool stop_on_failure)
{
    bool failed = false;
    for (int first = 0; first < n; first += GRADE_JOBS) {
        pid_t pid[GRADE_JOBS];
        int from[GRADE_JOBS];
        int batch = n - first < GRADE_JOBS ? n - first : GRADE_JOBS;
        for (int k = 0; k < batch; k++) {
            r[first + k] = (grade_run_result){false, -1, false, false, false, 0.0, 0.0};
            pid[k] = failed ? -1 : start_job(argv[first + k], &o[first + k], &from[k]);  /* after a failure: none */
        }
        for (int k = 0; k < batch; k++) {
            grade_run_result *out = &r[first + k];
            if (pid[k] < 0) continue;
            grade_run_result got;
            ssize_t len;
            while ((len = read(from[k], &got, sizeof got)) < 0 && errno == EINTR) continue;
            if (len == (ssize_t)sizeof got) *out = got;
            close(from[k]);
            waitpid(pid[k], NULL, 0);
            failed = failed || (stop_on_failure && !(out->exited && out->status == 0));
        }
    }
}

/* What a child runs once child_setup has confined it: a program (exec), or a function of the
 * grader's (grade_run_function). */
typedef struct {
    char *const *argv;                 /* a program, or NULL */
    void (*fn)(void *arg, int out_fd); /* else this, with arg, writing to the capture's descriptor */
    void *arg;
} child_work;

static _Noreturn void run_child_work(const grade_run_opts *o, const child_work *w)
{
    if (w->argv) {
        if (o->untrusted && !o->compiler && o->sandbox && o->sandbox->filter) sandbox_exec(w->argv, o->writes_files);
        else execvp(w->argv[0], w->argv);
        _exit(127);
    }
    /* A function never execs: the filter goes on before it reads anything hostile. */
    if (o->untrusted && o->sandbox && o->sandbox->filter && !sandbox_confine_self()) _exit(126);
    w->fn(w->arg, o->capture ? o->capture->child_fd : -1);
    _exit(0);
}

/* Forks a child for w under o's limits and confinement, watches it to its end, and cleans up after
 * it: the one path every child of the grader takes. */
static grade_run_result run_child(const child_work *w, const grade_run_opts *given, int in_fd, int fd3)
{
    grade_run_result r = {false, -1, false, false, false, 0.0, 0.0};
    double t0 = clock_seconds();
    /* The stage's limit, or what is left of the grading's time when that is less. */
    grade_run_opts limited = *given;
    const grade_run_opts *o = &limited;
    bool deadline_first = given->deadline > 0 && given->deadline - t0 < given->wall_seconds;
    if (deadline_first) limited.wall_seconds = given->deadline - t0;
    if (o->wall_seconds <= 0) {
        r.timed_out = r.out_of_time = true;
        return r;
    }
    int log_fd = open_log(o->log_path), fds[2] = {-1, -1}, cap[2] = {-1, -1};
    if (o->capture) o->capture->len = 0, o->capture->overflow = false;
    if (log_fd < 0 || !grade_pipe(fds) || (o->capture && !grade_pipe(cap))) {
        int opened[] = {log_fd, fds[0], fds[1], cap[0]};
        for (int i = 0; i < 4; i++)
            if (opened[i] >= 0) close(opened[i]);
        return r;
    }
    pid_t pid = fork();
    if (pid == 0) {
        child_setup(o, fds[1], cap[1], in_fd, fd3);
        run_child_work(o, w);
    }
    if (pid > 0) setpgid(pid, pid);  /* also from the parent: no race with the first kill */
    close(fds[1]);
    if (cap[1] >= 0) close(cap[1]);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    if (cap[0] >= 0) fcntl(cap[0], F_SETFL, O_NONBLOCK);
    int status = pid > 0 ? watch(pid, o, fds[0], log_fd, cap[0], &r) : 0;
    /* Nothing of student code outlives its stage: its group is killed above, the orphans the grader
     * adopted here (not every process of the sandbox's user: two graders may share a machine, as
     * test-autograder's do). Only after an untrusted child: the course's own children may run side
     * by side (the reference maker's threads, the judge beside its subject), and this would kill them. */
    if (o->untrusted) sandbox_kill_orphans();
    /* Without a mount namespace the stage shared /tmp: what its user left there goes now. */
    if (o->untrusted && o->sandbox && o->sandbox->as_other_user && !o->sandbox->isolated)
        sandbox_clean_shared_tmp(o->sandbox->uid);
    close(fds[0]);
    if (cap[0] >= 0) close(cap[0]);
    close(log_fd);
    r.seconds = clock_seconds() - t0;
    r.out_of_time = r.timed_out && deadline_first;
    if (pid > 0 && !r.timed_out && WIFEXITED(status)) {
        r.exited = true;
        r.status = WEXITSTATUS(status);
    }
    else if (pid > 0 && WIFSIGNALED(status))
        r.status = WTERMSIG(status);
    return r;
}

grade_run_result grade_run_piped(char *const argv[], const grade_run_opts *o, int in_fd, int fd3)
{
    child_work w = {argv, NULL, NULL};
    return run_child(&w, o, in_fd, fd3);
}

grade_run_result grade_run_function(void (*fn)(void *arg, int out_fd), void *arg, const grade_run_opts *o)
{
    child_work w = {NULL, fn, arg};
    return run_child(&w, o, 0, 0);
}
