/* Grader machinery: not part of any assignment.
 * The course's side of the grading trees (grade_tree.h): once per grading, before any student code
 * runs, the grader copies the course's tree into its private work folder (work/course, root's alone)
 * and builds there, with the course's make, every object with the graded build's flags, the
 * programs the parts' grading needs and the recipes that build a submission without make
 * (grade_plan.c reads them into each part's commands, grade_build.c runs them). */
#include "grade_tree.h"
#include "grade_run.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static bool run_quiet(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = GRADE_LINK_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

bool grade_tree_course_build(const grade_run_plan *rp, const char *parts, char *why, size_t size)
{
    grade_course_build *b = malloc(sizeof *b);  /* the plan's copies and make: some 40 KiB of paths */
    if (!b) return grade_msg(why, size, "out of memory"), false;
    grade_plan_course_build(rp, parts, b);
    char *rm[] = {"rm", "-rf", (char *)rp->course, NULL}, *mk[] = {"mkdir", "-p", (char *)rp->course, NULL};
    bool ok = run_quiet(rm, NULL) && run_quiet(mk, NULL);
    if (!ok) grade_msg(why, size, "cannot create %s", rp->course);
    for (int k = 0; ok && k < b->count; k++) {
        struct stat st;
        bool prebuilt = k >= b->count - b->prebuilt;
        char *cp[] = {"cp", "-a", b->from[k], (char *)rp->course, NULL};
        if (stat(b->from[k], &st) != 0 || (prebuilt && !S_ISDIR(st.st_mode))) continue;  /* not in this course */
        if (!(ok = run_quiet(cp, rp->course_log))) grade_msg(why, size, "cannot copy %s", b->from[k]);
    }
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .log_path = rp->course_log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = ok ? grade_run(b->make, &o) : (grade_run_result){0};
    if (ok && (!rr.exited || rr.status != 0)) {
        grade_msg(why, size, "the course's own tree does not build with the grader's flags (see %s)", rp->course_log);
        ok = false;
    }
    free(b);
    return ok;
}

void grade_tree_remove(const char *tree)
{
    /* Only what lies in a sandbox folder this grader made: a path gone wrong (a tree never set, the
     * course's own root) is left alone, never removed. */
    if (!strstr(tree, "/" GRADE_SANDBOX_NAME) || strstr(tree, "/..")) {
        fprintf(stderr, "grade: not removing %s: not in a sandbox folder\n", tree);
        return;
    }
    char *rm[] = {"rm", "-rf", (char *)tree, NULL};  /* rm never follows a link it deletes */
    run_quiet(rm, NULL);
}
