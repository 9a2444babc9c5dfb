/* Grader machinery: not part of any assignment.
 * The grading's settings: one value, made by main from the command line and the machine before any
 * part is graded, read by every stage and changed by none (a part's share of the deadline is its
 * plan's, grade_plan.h). */
#ifndef PL_GRADE_ENV_H
#define PL_GRADE_ENV_H

#include <stdbool.h>
#include <stdint.h>
#include "grade_sandbox.h"

typedef struct {
    const char *root;          /* the tree holding the other parts (the course's), or the student's tree */
    const char *submission;    /* a folder holding the submission's parts/, or NULL (a student's own tree) */
    const char *work;          /* the grader's scratch, root's alone: the course's build, logs, films */
    const char *sandbox_dir;   /* the only folder the sandbox's user may reach: the parts' trees */
    const char *report;        /* the report folder (images and index.html) */
    bool public_only;
    uint64_t seed;
    int threads;
    double deadline;           /* clock_seconds() by which the whole grading must end (bin/grade
                                  --deadline), 0 for none: each part's plan takes its share */
    grade_sandbox sandbox;     /* what containment this machine allows: the one value every stage
                                  hands its untrusted children (grade_run_opts.sandbox) */
} grade_env;

#endif
