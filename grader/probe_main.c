/* Grader machinery: not part of any assignment.
 * bin/grade-probe: the sandbox's self-test, run by the grader's tests as student code is run.
 *   grade-probe forbidden      tries what the sandbox forbids (exec, fork, a process not a thread,
 *                              creating a file, a socket, a signal to another process, ptrace,
 *                              setsid, raising the descriptor limit, exec from the exec slot), and
 *                              what it must allow (a thread, reading a file, the clock). One line
 *                              each; exit 0 only when every forbidden thing failed and every allowed
 *                              one worked.
 *   grade-probe sweep ROOT...  reads every regular file it can under each ROOT (no links followed;
 *                              /proc, /sys and /dev left out) and looks for the byte sequences given
 *                              in PL_SWEEP_NEEDLES (hex, comma-separated): prints each needle
 *                              found and where ("FOUND secret K in PATH", K counted from 0) and
 *                              exits 1, else prints how much it read and exits 0. A ROOT may be a file.
 *   grade-probe stage build|run SANDBOX ROOT...
 *                              as root: runs `grade-probe sweep ROOT...` (PL_SWEEP_NEEDLES passed
 *                              on) confined as the grader confines that stage (grade_run.c: the
 *                              build's compiler, or a suite's or a render's code), with SANDBOX as
 *                              the sandbox's folder, and prints what it printed; exits as it did.
 *                              tests/grader/sandbox.sh runs it while a real grading is under way.
 * It is the student's view of the machine: it runs under the same filter, user and limits. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ptrace.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "grade_fmt.h"
#include "grade_limits.h"
#include "grade_run.h"
#include "grade_sandbox.h"
#include "grade_words.h"
#include "sandbox.h"

static int failures;

static void expect(const char *what, bool worked, bool should_work)
{
    printf("%-44s %s%s\n", what, worked ? "worked" : "refused", worked == should_work ? "" : "  <-- WRONG");
    failures += worked != should_work;
}

static void *thread_main(void *arg) { return arg; }

/* A child process, by every route: fork, vfork's clone flags, and exec in place. */
static void try_processes(void)
{
    pid_t pid = fork();
    if (pid == 0) _exit(0);
    if (pid > 0) waitpid(pid, NULL, 0);
    expect("fork()", pid >= 0, false);
    long c = syscall(SYS_clone, (long)SIGCHLD, 0L, 0L, 0L, 0L);
    if (c == 0) _exit(0);
    /* Reaped here: its SIGCHLD arriving after PTRACE_TRACEME (below) would stop the probe, and its
     * runner would see a stopped child, not an exit (a flaky failure of the unconfined check). */
    if (c > 0) waitpid((pid_t)c, NULL, 0);
    expect("clone() without CLONE_THREAD", c > 0, false);
    int fd = open("/bin/false", O_RDONLY);
    int moved = fd >= 0 ? dup2(fd, SANDBOX_EXEC_FD) : -1;
    expect("dup2 into the exec slot", moved == SANDBOX_EXEC_FD, false);
    struct rlimit l = {SANDBOX_EXEC_FD + 10, SANDBOX_EXEC_FD + 10};
    expect("raising the descriptor limit", setrlimit(RLIMIT_NOFILE, &l) == 0, false);
}

/* Last: where exec works, /bin/false replaces the probe and the run fails as it should. */
static void try_exec(void)
{
    char *argv[] = {"/bin/false", NULL}, *envp[] = {NULL};
    syscall(SYS_execveat, SANDBOX_EXEC_FD, "", argv, envp, 0x1000 /* AT_EMPTY_PATH */);
    expect("execveat from the exec slot", false, false);  /* reaching here means it failed */
    execve("/bin/false", argv, envp);
    expect("execve(/bin/false)", false, false);
}

static void try_forbidden(void)
{
    try_processes();
    int fd = open("grade-probe-was-here", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    expect("creating a file", fd >= 0, false);
    fd = open("/etc/passwd", O_RDWR);
    expect("opening a file for writing", fd >= 0, false);
    expect("a socket", socket(AF_INET, SOCK_STREAM, 0) >= 0, false);
    expect("a signal to another process (its parent)", kill(getppid(), 0) == 0, false);
    expect("a signal to every process (kill -1)", kill(-1, 0) == 0, false);
    bool traced = ptrace(PTRACE_TRACEME, 0, NULL, NULL) == 0;  /* then an exec would stop it: skipped below */
    expect("ptrace", traced, false);
    expect("setsid", setsid() >= 0, false);
    pthread_t t;
    bool thread = pthread_create(&t, NULL, thread_main, NULL) == 0;
    if (thread) pthread_join(t, NULL);
    expect("a thread", thread, true);
    fd = open("/etc/hostname", O_RDONLY);
    expect("reading a file", fd >= 0, true);
    struct timespec ts;
    expect("the clock", clock_gettime(CLOCK_MONOTONIC, &ts) == 0, true);
    if (!traced) try_exec();
}

/* ---- the sweep ------------------------------------------------------------------------------- */

typedef struct { unsigned char *bytes; size_t len; } needle;
static needle needles[4096];
static int num_needles;
static long files_read, bytes_read;

static int hex(int c) { return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1; }

static bool parse_needles(const char *text)
{
    for (const char *p = text; *p && num_needles < 4096;) {
        size_t len = strcspn(p, ",");
        needle *n = &needles[num_needles];
        n->bytes = malloc(len / 2 + 1);
        n->len = 0;
        for (size_t i = 0; n->bytes && i + 1 < len; i += 2) n->bytes[n->len++] = (unsigned char)(hex(p[i]) * 16 + hex(p[i + 1]));
        if (n->len >= 8) num_needles++;  /* a short needle would match by chance */
        p += len + (p[len] == ',');
    }
    return num_needles > 0;
}

static void sweep_file(const char *path, int *found)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return;
    static char buf[64 << 20];  /* a file's first 64 MiB: more than any secret of the course */
    ssize_t n = read(fd, buf, sizeof buf), more;
    while (n > 0 && (size_t)n < sizeof buf && (more = read(fd, buf + n, sizeof buf - (size_t)n)) > 0) n += more;
    close(fd);
    if (n <= 0) return;
    files_read++;
    bytes_read += n;
    for (int k = 0; k < num_needles; k++)
        if (memmem(buf, (size_t)n, needles[k].bytes, needles[k].len)) {
            printf("FOUND secret %d in %s\n", k, path);
            ++*found;
        }
}

static void sweep(const char *dir, int depth, int *found)
{
    static const char *const skipped[] = {"/proc", "/sys", "/dev", NULL};
    for (const char *const *s = skipped; *s; s++)
        if (!strcmp(dir, *s)) return;
    DIR *d = depth < 40 ? opendir(dir) : NULL;
    for (struct dirent *e; d && (e = readdir(d));) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", strcmp(dir, "/") ? dir : "", e->d_name);
        if (lstat(path, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) sweep(path, depth + 1, found);
        else if (S_ISREG(st.st_mode)) sweep_file(path, found);
    }
    if (d) closedir(d);
}

/* grade-probe stage build|run SANDBOX ROOT...: the sweep, confined as that stage of a grading is. */
static int as_stage(int argc, char **argv)
{
    static char *args[64], needle_env[1 << 20], self[4096], log_dir[] = "/tmp/pathlab-probe.XXXXXX", log[64];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    const char *given = getenv("PL_SWEEP_NEEDLES");
    if (n <= 0 || !given || argc > 60 || geteuid() != 0 || !mkdtemp(log_dir)) {
        fprintf(stderr, "grade-probe stage: run as root, with PL_SWEEP_NEEDLES, at most 56 roots\n");
        return 2;
    }
    self[n] = '\0';
    /* The probe runs from a copy in the sandbox's folder: the one place sure to be in the stage's
     * view and reachable by its user (a course tree's bin/ is closed once a grading ran in it). */
    char copy[4200], command[3 * 4200 + 64];
    snprintf(copy, sizeof copy, "%s/grade-probe.%d", argv[3], (int)getpid());
    snprintf(command, sizeof command, "cp '%s' '%s' && chmod 755 '%s'", self, copy, copy);
    if (system(command) != 0) {
        fprintf(stderr, "grade-probe stage: cannot copy itself into %s\n", argv[3]);
        return 2;
    }
    snprintf(needle_env, sizeof needle_env, "PL_SWEEP_NEEDLES=%s", given);
    snprintf(log, sizeof log, "%s/sweep.log", log_dir);
    int k = 0;
    args[k++] = copy;
    args[k++] = "sweep";
    for (int i = 4; i < argc; i++) args[k++] = argv[i];
    args[k] = NULL;
    bool build = !strcmp(argv[2], "build");
    grade_sandbox s = grade_sandbox_probe();
    grade_sandbox_keep(&s, argv[3]);
    char *envv[] = {needle_env, NULL};
    grade_run_opts o = {.wall_seconds = 600, .cwd = argv[3], .log_path = log, .log_max = 1 << 20, .env = envv,
                        .untrusted = true, .compiler = build, .writable = build ? argv[3] : NULL, .sandbox = &s};
    grade_run_result r = grade_run(args, &o);
    char in_force[512], line[1024];
    grade_words_protections_in_force(&s, in_force, sizeof in_force);
    printf("stage %s: %s\n", argv[2], in_force);
    FILE *f = fopen(log, "r");
    while (f && fgets(line, sizeof line, f)) fputs(line, stdout);
    if (f) fclose(f);
    remove(log);
    rmdir(log_dir);
    remove(copy);
    return r.exited ? r.status : 3;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (argc == 2 && !strcmp(argv[1], "forbidden")) {
        try_forbidden();
        return failures ? 1 : 0;
    }
    if (argc >= 4 && !strcmp(argv[1], "stage") && (!strcmp(argv[2], "build") || !strcmp(argv[2], "run")))
        return as_stage(argc, argv);
    if (argc < 3 || strcmp(argv[1], "sweep") || !getenv("PL_SWEEP_NEEDLES") || !parse_needles(getenv("PL_SWEEP_NEEDLES"))) {
        fprintf(stderr, "usage: grade-probe forbidden | PL_SWEEP_NEEDLES=hex,... grade-probe sweep ROOT...\n");
        return 2;
    }
    int found = 0;
    for (int i = 2; i < argc; i++) {
        struct stat st;
        if (lstat(argv[i], &st) == 0 && S_ISREG(st.st_mode)) sweep_file(argv[i], &found);
        else sweep(argv[i], 0, &found);
    }
    printf("swept %ld files, %ld bytes, for %d secrets: %d found\n", files_read, bytes_read, num_needles, found);
    return found ? 1 : 0;
}
