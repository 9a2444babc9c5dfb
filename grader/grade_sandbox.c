/* Grader machinery: not part of any assignment. The sandbox's settings (grade_sandbox.h): what this
 * machine allows, probed once. */
#include "grade_sandbox.h"
#include "grade_limits.h"
#include "sandbox.h"
#include <dirent.h>
#include <pwd.h>
#include <sched.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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
        snprintf(path, sizeof path, "/proc/%s", e->d_name);  /* a name of /proc's, under 300 bytes */
        n += stat(path, &st) == 0 && st.st_uid == uid;
    }
    if (d) closedir(d);
    return n;
}

grade_sandbox grade_sandbox_probe(void)
{
    grade_sandbox sandbox;
    memset(&sandbox, 0, sizeof sandbox);
    struct passwd *pw = getpwnam("nobody");
    if (geteuid() == 0 && pw) {
        sandbox.as_other_user = true;
        sandbox.uid = pw->pw_uid;
        sandbox.gid = pw->pw_gid;
    }
    /* A network namespace needs privilege; try it in a throwaway child. */
    pid_t pid = fork();
#ifdef __linux__
    if (pid == 0) _exit(unshare(CLONE_NEWNET) == 0 ? 0 : 1);
#else
    if (pid == 0) _exit(1);  /* no network namespaces but Linux's */
#endif
    int status = 1;
    if (pid > 0) waitpid(pid, &status, 0);
    sandbox.no_network = pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    sandbox.isolated = geteuid() == 0 && sandbox_isolation_supported();
    sandbox.process_limit = sandbox.as_other_user ? GRADE_PROCESSES : processes_of(getuid()) + GRADE_PROCESSES;
    sandbox.filter = sandbox_filter_supported(sandbox.filter_why, sizeof sandbox.filter_why);
    sandbox_adopt_orphans();
    return sandbox;
}

void grade_sandbox_keep(grade_sandbox *s, const char *dir)
{
    s->dir = dir;
}
