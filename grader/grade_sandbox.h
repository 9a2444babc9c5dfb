/* Grader machinery: not part of any assignment.
 * The sandbox's settings: one value (grade_sandbox), probed once per grading before any child runs,
 * kept in the grading's settings (grade_env.h) and handed to every stage that runs untrusted code
 * through its run options (grade_run.h). The operating system's part, what confines a process, is
 * sandbox.h (sandbox_linux.c, sandbox_posix.c). */
#ifndef PL_GRADE_SANDBOX_H
#define PL_GRADE_SANDBOX_H

#include <stdbool.h>
#include <stddef.h>

/* What grade_run can do to contain untrusted code on this machine: limits always; a network
 * namespace, PID and mount namespaces and another user only as root (and not in a container whose
 * profile refuses namespaces: then limits, the user and the filter remain); the filter where libseccomp and the kernel allow. The
 * report names what was unavailable, the staff log what was in force. */
typedef struct {
    bool as_other_user;        /* runs as `nobody` (the grader is root) */
    bool no_network;           /* a new network namespace */
    bool isolated;             /* new PID and mount namespaces with their own /proc (sandbox_isolate) */
    unsigned uid, gid;         /* nobody's */
    long process_limit;        /* RLIMIT_NPROC for untrusted children (counts the whole user's) */
    bool filter;               /* the seccomp filter is installed before student code runs */
    const char *dir;           /* the sandbox's folder: the one a stage sees of its /tmp (grade_sandbox_keep) */
    char filter_why[160];      /* why not, when it is not */
} grade_sandbox;

/* Finds what this machine allows (call once, before any child runs). */
grade_sandbox grade_sandbox_probe(void);
/* The sandbox's folder, where every stage's files are: it stays in view when a stage gets a private
 * /tmp (call before any child runs, with a path that outlives the grading). */
void grade_sandbox_keep(grade_sandbox *s, const char *dir);
/* Its words (what is missing, what is in force) are the words stage's: grade_words_protections_*. */

#endif
