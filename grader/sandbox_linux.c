/* Grader machinery: not part of any assignment.
 * The sandbox on Linux (sandbox.h): a seccomp filter, installed with no_new_privs in the child
 * after fork and before exec, so that student code runs under it from its first instruction
 * (before the dynamic loader, IFUNC resolvers, constructors, __gmon_start__).
 *
 * The one exec the filter lets through. A filter cannot be changed after exec and keeps no state,
 * so "only the first exec" must be a property of the arguments. The child opens the program,
 * moves the descriptor to slot SANDBOX_EXEC_FD (close-on-exec) and lowers RLIMIT_NOFILE, soft and
 * hard, to that number: a descriptor already open stays valid, but no open, dup2, fcntl or
 * received descriptor can ever occupy that slot again, and the hard limit cannot be raised
 * (prlimit/setrlimit that set a limit are refused by the filter, and nobody lacks
 * CAP_SYS_RESOURCE). The filter allows execveat(SANDBOX_EXEC_FD, "", ..., AT_EMPTY_PATH) and no
 * other execve or execveat. After the exec the slot is closed, so every later exec fails. (An
 * address check on execve's path would not do: the program can map a page at any address.)
 *
 * Everything not allowed below fails with EPERM (clone3 with ENOSYS, so that glibc falls back to
 * clone, whose flags the filter can read). Allowed: memory, threads (clone with CLONE_THREAD),
 * futexes, reading (open without write, create or truncate flags; stat, getdents, readlink),
 * writing to descriptors already open, the clock, signals to itself, exit. */
#include "grade_fmt.h"
#include "grade_limits.h"
#include "grade_run.h"
#include "grade_sandbox.h"
#include "sandbox.h"
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/sched.h>
#include <seccomp.h>
/* libseccomp's SCMP_A0..SCMP_A5 comparisons leave the second datum out where it is unused, which
 * clang's -Wextra reports in every rule; the macros are the library's documented interface. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

extern char **environ;

/* System calls allowed whatever their arguments. */
static const int always[] = {
    SCMP_SYS(read), SCMP_SYS(pread64), SCMP_SYS(readv), SCMP_SYS(preadv), SCMP_SYS(write), SCMP_SYS(writev),
    SCMP_SYS(pwrite64), SCMP_SYS(lseek), SCMP_SYS(close), SCMP_SYS(dup), SCMP_SYS(dup2), SCMP_SYS(dup3),
    SCMP_SYS(fstat), SCMP_SYS(stat), SCMP_SYS(lstat), SCMP_SYS(newfstatat), SCMP_SYS(statx), SCMP_SYS(statfs),
    SCMP_SYS(fstatfs), SCMP_SYS(access), SCMP_SYS(faccessat), SCMP_SYS(faccessat2), SCMP_SYS(readlink),
    SCMP_SYS(readlinkat), SCMP_SYS(getcwd), SCMP_SYS(getdents64), SCMP_SYS(poll), SCMP_SYS(ppoll),
    SCMP_SYS(brk), SCMP_SYS(mmap), SCMP_SYS(munmap), SCMP_SYS(mprotect), SCMP_SYS(mremap), SCMP_SYS(madvise),
    SCMP_SYS(msync), SCMP_SYS(futex), SCMP_SYS(set_robust_list), SCMP_SYS(get_robust_list), SCMP_SYS(rseq),
    SCMP_SYS(set_tid_address), SCMP_SYS(arch_prctl), SCMP_SYS(membarrier), SCMP_SYS(sched_yield),
    SCMP_SYS(sched_getaffinity), SCMP_SYS(getrandom), SCMP_SYS(uname), SCMP_SYS(sysinfo), SCMP_SYS(getrusage),
    SCMP_SYS(times), SCMP_SYS(getcpu), SCMP_SYS(clock_gettime), SCMP_SYS(clock_getres), SCMP_SYS(clock_nanosleep),
    SCMP_SYS(nanosleep), SCMP_SYS(gettimeofday), SCMP_SYS(time), SCMP_SYS(getpid), SCMP_SYS(gettid),
    SCMP_SYS(getppid), SCMP_SYS(getuid), SCMP_SYS(geteuid), SCMP_SYS(getgid), SCMP_SYS(getegid),
    SCMP_SYS(getresuid), SCMP_SYS(getresgid), SCMP_SYS(getrlimit), SCMP_SYS(rt_sigaction),
    SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigreturn), SCMP_SYS(sigaltstack), SCMP_SYS(restart_syscall),
    SCMP_SYS(exit), SCMP_SYS(exit_group)};

/* fcntl commands that touch only the descriptor (F_SETOWN could aim signals at other processes). */
static const int fcntl_cmds[] = {F_GETFD, F_SETFD, F_GETFL, F_SETFL, F_DUPFD, F_DUPFD_CLOEXEC};

/* The rules that look at arguments: the one exec, threads only, reads only, signals to itself. */
static int add_argument_rules(scmp_filter_ctx ctx, bool may_write_files)
{
    const scmp_datum_t write_flags = O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND;
    pid_t self = getpid();  /* the same process after exec */
    int rc = seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(execveat), 2, SCMP_A0(SCMP_CMP_EQ, SANDBOX_EXEC_FD),
                              SCMP_A4(SCMP_CMP_EQ, AT_EMPTY_PATH));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(clone), 1,
                           SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, CLONE_THREAD));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    if (may_write_files) {
        static const int file_calls[] = {SCMP_SYS(openat), SCMP_SYS(open), SCMP_SYS(rename), SCMP_SYS(renameat),
                                         SCMP_SYS(renameat2), SCMP_SYS(unlink), SCMP_SYS(unlinkat), SCMP_SYS(link),
                                         SCMP_SYS(linkat), SCMP_SYS(fsync), SCMP_SYS(fdatasync), SCMP_SYS(ftruncate),
                                         SCMP_SYS(fchmod), SCMP_SYS(mkdir), SCMP_SYS(mkdirat), SCMP_SYS(umask)};
        for (size_t i = 0; i < sizeof file_calls / sizeof file_calls[0]; i++)
            rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, file_calls[i], 0);
    }
    else {
        rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(openat), 1, SCMP_A2(SCMP_CMP_MASKED_EQ, write_flags, 0));
        rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(open), 1, SCMP_A1(SCMP_CMP_MASKED_EQ, write_flags, 0));
    }
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(prlimit64), 1, SCMP_A2(SCMP_CMP_EQ, 0));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(ioctl), 1, SCMP_A1(SCMP_CMP_EQ, TCGETS));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 1, SCMP_A0(SCMP_CMP_EQ, (scmp_datum_t)self));
    rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(kill), 1, SCMP_A0(SCMP_CMP_EQ, (scmp_datum_t)self));
    for (size_t i = 0; i < sizeof fcntl_cmds / sizeof fcntl_cmds[0]; i++)
        rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(fcntl), 1, SCMP_A1(SCMP_CMP_EQ, (scmp_datum_t)fcntl_cmds[i]));
    return rc;
}

/* Builds and loads the filter in the calling process; false when the kernel or library refused. */
static bool load_filter(bool may_write_files)
{
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ERRNO(EPERM));
    if (!ctx) return false;
    int rc = 0;
    for (size_t i = 0; i < sizeof always / sizeof always[0]; i++)
        if (always[i] >= 0) rc |= seccomp_rule_add(ctx, SCMP_ACT_ALLOW, always[i], 0);
    rc |= add_argument_rules(ctx, may_write_files);
    /* no_new_privs: set by libseccomp's default attribute; set here too, so it never depends on it. */
    rc |= prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
    rc |= seccomp_load(ctx);
    seccomp_release(ctx);
    return rc == 0;
}

/* The program argv[0] names: a path, or the first match in PATH. -1 when not found. */
static int open_program(const char *name)
{
    if (strchr(name, '/')) return open(name, O_PATH | O_CLOEXEC);
    const char *path = getenv("PATH") ? getenv("PATH") : "/usr/bin:/bin";
    for (const char *p = path; *p;) {
        size_t len = strcspn(p, ":");
        char dir[4096], full[4096];
        snprintf(dir, sizeof dir, "%.*s", (int)len, p);
        if (!grade_join(dir, name, full, sizeof full)) full[0] = '\0';
        int fd = access(full, X_OK) == 0 ? open(full, O_PATH | O_CLOEXEC) : -1;
        if (fd >= 0) return fd;
        p += len + (p[len] == ':');
    }
    return -1;
}

void sandbox_exec(char *const argv[], bool may_write_files)
{
    int fd = open_program(argv[0]);
    if (fd < 0 || dup3(fd, SANDBOX_EXEC_FD, O_CLOEXEC) != SANDBOX_EXEC_FD) return;
    close(fd);
    struct rlimit l = {SANDBOX_EXEC_FD, SANDBOX_EXEC_FD};
    if (setrlimit(RLIMIT_NOFILE, &l) != 0 || !load_filter(may_write_files)) return;
    syscall(SYS_execveat, SANDBOX_EXEC_FD, "", argv, environ, AT_EMPTY_PATH);
}

bool sandbox_confine_self(void)
{
    struct rlimit l = {SANDBOX_EXEC_FD, SANDBOX_EXEC_FD};
    return setrlimit(RLIMIT_NOFILE, &l) == 0 && load_filter(false);
}

bool sandbox_filter_supported(char *why, size_t size)
{
    pid_t pid = fork();
    if (pid == 0) _exit(load_filter(false) && fork() < 0 && errno == EPERM ? 0 : 1);
    int status = 1;
    if (pid > 0) waitpid(pid, &status, 0);
    bool ok = pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!ok) grade_msg(why, size, "the kernel refused the seccomp filter (is seccomp enabled? a container "
                                 "profile that forbids seccomp(2)?)");
    return ok;
}

void sandbox_filter_name(char *out, size_t size)
{
    const struct scmp_version *v = seccomp_version();
    snprintf(out, size, "seccomp (libseccomp %u.%u.%u)", v->major, v->minor, v->micro);
}

/* ---- PID and mount namespaces ---------------------------------------------------------------- */

/* The namespaces, and the mounts that make them useful: mounts private (nothing done here reaches
 * the machine's own mount table) and a /proc of the new PID namespace, so the confined process
 * lists only its own namespace. Run by a process already in the new PID namespace (/proc shows the
 * PID namespace of whoever mounts it). */
static bool mount_private_proc(void)
{
    return mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) == 0 &&
           mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, NULL) == 0;
}

bool sandbox_isolation_supported(void)
{
    pid_t pid = fork();
    if (pid == 0) {
        if (unshare(CLONE_NEWPID | CLONE_NEWNS) != 0) _exit(1);
        pid_t init = fork();  /* the first child after unshare is the new namespace's PID 1 */
        if (init == 0) _exit(getpid() == 1 && mount_private_proc() ? 0 : 1);
        int status = 1;
        _exit(init > 0 && waitpid(init, &status, 0) == init && WIFEXITED(status) ? WEXITSTATUS(status) : 1);
    }
    int status = 1;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* The relay, outside the namespace: ends the way the confined process ended, which init sent it as
 * a wait status (a signal is raised again, so the grader still reads "killed by signal 31"). When
 * init is killed before it sends anything (the grader's timeout kills the whole process group),
 * the relay is killed with it. */
static _Noreturn void relay(pid_t init, int from_init)
{
    int status = 0;
    ssize_t got;
    while ((got = read(from_init, &status, sizeof status)) < 0 && errno == EINTR) continue;
    waitpid(init, NULL, 0);
    if (got != (ssize_t)sizeof status) _exit(126);
    if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
    int sig = WIFSIGNALED(status) ? WTERMSIG(status) : SIGKILL;
    signal(sig, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    sigprocmask(SIG_UNBLOCK, &one, NULL);
    raise(sig);
    _exit(128 + sig);  /* a signal whose default is to be ignored: say which, as a shell would */
}

/* The namespace's init: reaps every orphan the namespace makes until the confined process ends,
 * sends its wait status to the relay and ends, which ends the namespace. A PID 1 gets no signal
 * from inside its namespace that it has no handler for, so student code cannot kill it. */
static _Noreturn void init_process(pid_t worker, int to_relay)
{
    for (;;) {
        int status;
        pid_t w = wait(&status);
        if (w == worker) {
            ssize_t put = write(to_relay, &status, sizeof status);
            _exit(put == (ssize_t)sizeof status ? 0 : 126);
        }
        if (w < 0 && errno != EINTR) _exit(126);
    }
}

void sandbox_isolate(void)
{
    int link[2];
    if (unshare(CLONE_NEWPID | CLONE_NEWNS) != 0 || pipe(link) != 0) _exit(126);
    pid_t init = fork();
    if (init < 0) _exit(126);
    if (init > 0) {
        close(link[1]);
        relay(init, link[0]);
    }
    close(link[0]);
    if (!mount_private_proc()) _exit(126);
    pid_t worker = fork();
    if (worker < 0) _exit(126);
    if (worker > 0) init_process(worker, link[1]);
    close(link[1]);
}

/* ---- a stage's private view of the file system ------------------------------------------------ */

/* The folders every user may write: each stage gets its own, empty and bounded. */
static const char *const shared_tmp[] = {"/tmp", "/var/tmp", "/dev/shm"};

/* Whether path is dir or below it. */
static bool inside(const char *path, const char *dir)
{
    size_t n = strlen(dir);
    return !strncmp(path, dir, n) && (path[n] == '/' || path[n] == '\0');
}

/* mkdir -p, as root inside the stage's own tmpfs (the mount point `keep` goes back to). */
static bool make_path(const char *path)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf) return false;
    for (char *p = buf + 1;; p++)
        if (*p == '/' || *p == '\0') {
            char c = *p;
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST) return false;
            if (!c) return true;
            *p = c;
        }
}

/* A /dev of three devices: a tmpfs over the machine's, holding null, zero and urandom as the
 * kernel numbers them (Documentation/admin-guide/devices.txt), and an empty shm for the tmpfs below.
 * So `#include "/dev/stdin"` or a terminal's device cannot block a compile, and no stage reads a
 * device of the machine's. */
static bool minimal_dev(void)
{
    static const struct { const char *path; unsigned minor; } devices[] = {
        {"/dev/null", 3}, {"/dev/zero", 5}, {"/dev/urandom", 9}};
    if (mount("tmpfs", "/dev", "tmpfs", MS_NOSUID | MS_NOEXEC, "size=64k,mode=755") != 0) return false;
    for (size_t i = 0; i < sizeof devices / sizeof devices[0]; i++)
        if (mknod(devices[i].path, S_IFCHR | 0666, makedev(1, devices[i].minor)) != 0 || chmod(devices[i].path, 0666) != 0)
            return false;
    return mkdir("/dev/shm", 01777) == 0 && chmod("/dev/shm", 01777) == 0;
}

bool sandbox_private_view(const char *keep, const char *writable, long tmp_bytes)
{
    /* `keep` is taken first, as a detached copy of its mount: the tmpfs below may cover its path. */
    int kept = keep ? (int)open_tree(AT_FDCWD, keep, OPEN_TREE_CLONE | OPEN_TREE_CLOEXEC | AT_RECURSIVE) : -1;
    if (keep && kept < 0) return false;
    struct mount_attr ro = {.attr_set = MOUNT_ATTR_RDONLY | MOUNT_ATTR_NOSUID};
    bool ok = mount_setattr(AT_FDCWD, "/", AT_RECURSIVE, &ro, sizeof ro) == 0 && minimal_dev();
    char options[64];
    snprintf(options, sizeof options, "size=%ld,mode=1777", tmp_bytes);
    bool covered = false;
    for (size_t i = 0; ok && i < sizeof shared_tmp / sizeof shared_tmp[0]; i++) {
        struct stat st;
        if (stat(shared_tmp[i], &st) != 0 || !S_ISDIR(st.st_mode)) continue;
        ok = mount("tmpfs", shared_tmp[i], "tmpfs", MS_NOSUID | MS_NODEV, options) == 0;
        covered = covered || (keep && inside(keep, shared_tmp[i]));
    }
    /* The sandbox's folder back at its own path, read-only like the rest. */
    if (ok && covered)
        ok = make_path(keep) && mount_setattr(kept, "", AT_EMPTY_PATH | AT_RECURSIVE, &ro, sizeof ro) == 0 &&
             move_mount(kept, "", AT_FDCWD, keep, MOVE_MOUNT_F_EMPTY_PATH) == 0;
    if (kept >= 0) close(kept);
    /* The stage's output: a bind mount of its folder, the one mount made writable again. */
    struct mount_attr rw = {.attr_clr = MOUNT_ATTR_RDONLY};
    if (ok && writable)
        ok = mount(writable, writable, NULL, MS_BIND, NULL) == 0 && mount_setattr(AT_FDCWD, writable, 0, &rw, sizeof rw) == 0;
    return ok;
}

void sandbox_clean_shared_tmp(unsigned uid)
{
    for (size_t i = 0; i < sizeof shared_tmp / sizeof shared_tmp[0]; i++) {
        DIR *d = opendir(shared_tmp[i]);
        for (struct dirent *e; d && (e = readdir(d));) {
            char path[4096];
            struct stat st;
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
            if (!grade_join(shared_tmp[i], e->d_name, path, sizeof path)) continue;
            if (lstat(path, &st) != 0 || st.st_uid != uid) continue;
            pid_t pid = fork();  /* rm never follows a link it deletes */
            if (pid == 0) {
                execlp("rm", "rm", "-rf", "--", path, (char *)NULL);
                _exit(127);
            }
            if (pid > 0) waitpid(pid, NULL, 0);
        }
        if (d) closedir(d);
    }
}

void sandbox_adopt_orphans(void)
{
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
}

/* One pass over /proc: kills every process whose parent is the grader, then waits for each of them
 * (and only them: a process adopted meanwhile may still be alive, and a wait for any child would
 * hang on it; the next pass kills it). How many it found. */
static int kill_children_once(void)
{
    DIR *d = opendir("/proc");
    pid_t killed[256];
    int found = 0;
    for (struct dirent *e; d && (e = readdir(d)) && found < (int)(sizeof killed / sizeof killed[0]);) {
        char path[300], stat[512];
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        snprintf(path, sizeof path, "/proc/%.16s/stat", e->d_name);
        FILE *f = fopen(path, "r");
        size_t n = f ? fread(stat, 1, sizeof stat - 1, f) : 0;
        if (f) fclose(f);
        stat[n] = '\0';
        char *close_paren = strrchr(stat, ')');  /* the name may hold spaces and parentheses */
        int ppid = 0;
        if (close_paren && sscanf(close_paren + 1, " %*c %d", &ppid) == 1 && ppid == getpid()) {
            killed[found] = (pid_t)atoi(e->d_name);
            kill(killed[found++], SIGKILL);
        }
    }
    if (d) closedir(d);
    for (int i = 0; i < found; i++)
        while (waitpid(killed[i], NULL, 0) < 0 && errno == EINTR) continue;
    return found;
}

void sandbox_kill_orphans(void)
{
    /* Each pass kills the adopted; their own children are adopted in turn, and the next pass gets
     * them (a namespace's init among them: its namespace ends with it). */
    for (int pass = 0; pass < 100 && kill_children_once() > 0; pass++) continue;
    while (waitpid(-1, NULL, WNOHANG) > 0) continue;
}
