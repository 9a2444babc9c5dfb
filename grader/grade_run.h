/* Grader machinery: not part of any assignment.
 * The run stage's machinery: every child the grader starts goes through grade_run (grade_run.c),
 * in a process group of its own, with a wall-clock limit cut to the grading's deadline, its output
 * pumped into a log the grader writes, and, for untrusted code, the sandbox's confinement from its
 * first instruction. It returns what happened (grade_run_result) and what the kernel measured,
 * never what the child said about itself. */
#ifndef PL_GRADE_RUN_H
#define PL_GRADE_RUN_H

#include <stdbool.h>
#include "grade_sandbox.h"

/* What a child sends the grader on a descriptor of its own besides its log (a render's film): the
 * grader reads it while the child runs, into memory, never through a file the child could name. */
typedef struct {
    int child_fd;              /* the descriptor number the child writes to (3 and up) */
    long max;                  /* keep at most this many bytes */
    char *data;                /* filled by grade_run: what arrived (malloc'd; the caller frees) */
    long len;
    bool overflow;             /* it sent more than max (data holds the first max bytes) */
} grade_capture;

typedef struct {
    double wall_seconds;       /* kill the whole process group after this */
    double deadline;           /* and at the latest at this clock_seconds() (the grading's deadline:
                                  grade_env), 0 for none; a child never starts past it */
    const char *cwd;           /* run in this folder */
    const char *log_path;      /* stdout and stderr go here (a fresh file the grader writes, in a folder
                                  the child cannot write), cut at log_max bytes; NULL: discarded */
    long log_max;
    char *const *env;          /* extra "NAME=value" entries, NULL-terminated, or NULL */
    bool untrusted;            /* runs student code: the sandbox's user, limits, namespaces, a private
                                  read-only view with its own /tmp, and the seccomp filter from its
                                  first instruction (grader/sandbox.h) */
    bool compiler;             /* with untrusted: the compiler or a tool reading student files, running
                                  none of them: all of the above but the filter (cc forks cc1 and as) */
    bool writes_files;         /* with untrusted: the filter lets it create files (the XML suite) */
    const char *writable;      /* with untrusted: the one folder it may write (its output), or NULL */
    bool bounded;              /* trusted, but reading what student code made (the linker on its
                                  objects, the judge on its records): the limits, as the grader's user */
    grade_capture *capture;    /* a second channel to the grader, or NULL */
    const grade_sandbox *sandbox;  /* with untrusted: the grading's sandbox settings (grade_env.sandbox),
                                      what confines the child; required (NULL: the child exits 126
                                      before it runs anything: it never runs unconfined) */
} grade_run_opts;

typedef struct {
    bool exited;               /* ended by exit(), not by a signal or the timeout */
    int status;                /* exit status when exited, else the signal */
    bool timed_out;
    bool out_of_time;          /* timed out at the grading's deadline, not at the stage's own limit (or
                                  not started: the deadline had passed) */
    bool output_cut;           /* it printed more than log_max */
    double seconds;            /* wall clock */
    double cpu_seconds;        /* user + system CPU time, the kernel's count (wait4), threads and
                                  waited-for descendants included */
} grade_run_result;

/* Runs argv as a child in its own process group; never reads what it prints except into the log. */
grade_run_result grade_run(char *const argv[], const grade_run_opts *o);
/* Runs the n jobs (argv[i] with o[i]) two at a time, the machine's cores, each in a helper process
 * of its own that adopts its job's orphans (so a job's clean-up never touches the other), and fills
 * r[i]. With stop_on_failure, no job starts after one failed (those read as not exited, status -1):
 * a part's compile stops at its first file that fails, so a file that stalls its compile costs one
 * compile's time, not one per file. Only jobs without a capture: a build's compiles and links. */
#define GRADE_JOBS 2
void grade_run_jobs(int n, char *const *const argv[], const grade_run_opts o[], grade_run_result r[], bool stop_on_failure);
/* Runs fn(arg, fd) in a forked child under o's limits and, with o->untrusted, the whole confinement
 * of an untrusted stage and the filter, installed before fn runs; the child never execs. For the
 * grader's own code reading hostile files (the object inspection): what fn writes to fd (the
 * capture's descriptor, o->capture required) arrives in o->capture. */
grade_run_result grade_run_function(void (*fn)(void *arg, int out_fd), void *arg, const grade_run_opts *o);
/* grade_run with pipe ends for the split suite (grade_judge.c): in_fd > 0 becomes the child's stdin
 * (else /dev/null), fd3 > 0 its fd 3. */
grade_run_result grade_run_piped(char *const argv[], const grade_run_opts *o, int in_fd, int fd3);
/* pipe(2) with both ends close-on-exec (POSIX has no pipe2): a child gets only the ends it is given. */
bool grade_pipe(int fds[2]);


#endif
