/* Grader machinery: not part of any assignment.
 * The sandbox where the build found no libseccomp (macOS, or Linux without libseccomp-dev):
 * no filter. A student's own `make grade` runs their own code on their own machine and needs none;
 * the autograder (bin/grade --submission as root) refuses to grade without it and says what to
 * install (grade_main.c). Orphans cannot be adopted here: a child's process group is killed, and as
 * root every process of the sandbox's user (grade_run.c). */
#include "grade_fmt.h"
#include "grade_run.h"
#include "sandbox.h"
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

bool sandbox_filter_supported(char *why, size_t size)
{
    grade_msg(why, size, "this grader was built without libseccomp (install libseccomp-dev: tools/setup, then "
                        "rebuild bin/grade)");
    return false;
}

void sandbox_filter_name(char *out, size_t size)
{
    snprintf(out, size, "none");
}

void sandbox_exec(char *const argv[], bool may_write_files)
{
    (void)may_write_files;
    execvp(argv[0], argv);
}

bool sandbox_confine_self(void) { return false; }

bool sandbox_isolation_supported(void) { return false; }

void sandbox_isolate(void) {}

bool sandbox_private_view(const char *keep, const char *writable, long tmp_bytes)
{
    (void)keep, (void)writable, (void)tmp_bytes;
    return false;
}

void sandbox_clean_shared_tmp(unsigned uid) { (void)uid; }

void sandbox_adopt_orphans(void) {}

void sandbox_kill_orphans(void)
{
    while (waitpid(-1, NULL, WNOHANG) > 0) continue;
}
