/* Grader machinery: not part of any assignment. One part: its tree, its suite, its image cases. */
#include "grade.h"
#include "grade_build.h"
#include "grade_image.h"
#include "grade_guard.h"
#include "grade_inspect.h"
#include "grade_suite.h"
#include "grade_tree.h"
#include "grade_diag.h"
#include "../framework/file.h"
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>


/* A student's own tree (make grade): built by its own make, as they build it, with the course's
 * warnings whatever they exported and no sanitizer, so `make grade` and `make` share every object.
 * Their own code, on their own machine: nothing here is confined (a submission is built by
 * grade_build.c instead). */
static bool build_own_tree(const grade_env *env, int n, grade_part_result *r)
{
    char target[32];
    snprintf(target, sizeof target, "bin/test-part%d", n);
    grade_path(r->build_log, sizeof r->build_log, "%s/part%d/build.log", env->work, n);
    char *argv[] = {"make", "-C", (char *)env->root, "-j2", "--no-print-directory", "WERROR=0", "SAN=0", "bin/pathtracer",
                    target, NULL};
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .log_path = r->build_log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(argv, &o);
    bool ok = rr.exited && rr.status == 0;
    if (!ok) {
        char folder[256] = "";
        grade_part_folder(env->root, n, folder, sizeof folder);
        grade_diagnostics(r->build_log, folder, GRADE_DIAG_LINES, r->build_output, sizeof r->build_output);
        if (!rr.exited) grade_run_describe(&rr, r->suite_reason, sizeof r->suite_reason);
    }
    return ok;
}

/* ---- the suite: verdicts from cmocka's XML files, one per test group ------------------------- */

void grade_suite_results(const char *dir, const grade_test_list *order, int expected, int status, grade_part_result *r)
{
    r->tests_run = r->tests_failed = r->num_tests = 0;
    r->failures[0] = '\0';
    char why[200] = "";
    bool all_read = grade_suite_read(dir, order, r, why, sizeof why);  /* grade_suite.h says what it accepts */
    /* The XML files are written group by group: a suite that stopped early (an _exit in a test, a
     * crash the suite survived) left fewer tests than it has; one with more was not the suite. */
    if (!all_read)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite's results are not what it writes: %s", why);
    else if (r->tests_run == 0)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite wrote no readable test results");
    else if (r->tests_run < expected)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite stopped after %d of %d tests", r->tests_run,
                 expected);
    else if (r->tests_run > expected)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite reported %d tests, but it has %d: its results "
                 "are not the suite's own", r->tests_run, expected);
    else if (status == 1 && r->tests_failed == 0)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite exited with status 1 but reported no failure");
    else if (status != 0 && status != 1)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the suite exited with status %d", status);
}

static void run_suite(const grade_env *env, const char *tree, const grade_part_spec *p, grade_part_result *r)
{
    char dir[4096], pattern[4200], xml_env[4300], log[4096], bin[4096];
    bool contained = env->submission != NULL;
    grade_path(dir, sizeof dir, "%s/part%d-suite", env->sandbox_dir, p->part);
    /* The suite's own folder: it may write its results there, and nothing else beside them. */
    if (!grade_guard_child_dir(dir, &env->sandbox, contained)) {
        grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot create %s", dir);
        return;
    }
    grade_path(pattern, sizeof pattern, "%s/%%g.xml", dir);
    grade_path(xml_env, sizeof xml_env, "CMOCKA_XML_FILE=%s", pattern);
    grade_path(log, sizeof log, "%s/part%d/suite.log", env->work, p->part);
    grade_path(bin, sizeof bin, "%s/bin/test-part%d", tree, p->part);
    char *envv[] = {"CMOCKA_MESSAGE_OUTPUT=xml", xml_env, NULL};
    char *argv[] = {bin, NULL};
    grade_run_opts o = {.wall_seconds = GRADE_SUITE_SECONDS, .deadline = env->deadline, .cwd = tree, .log_path = log, .log_max = GRADE_LOG_MAX,
                        .env = envv, .untrusted = contained, .writes_files = true, .writable = dir};
    grade_run_result rr = grade_run(argv, &o);

    /* A suite that crashed or timed out scores zero, whatever files it left. */
    if (!rr.exited) {
        grade_run_describe(&rr, r->suite_reason, sizeof r->suite_reason);
        return;
    }
    /* The suite's own list of its tests orders the failures as it ran them (nothing is judged by it). */
    static grade_test_list order;
    char list_log[4200];
    grade_path(list_log, sizeof list_log, "%s/part%d/suite.list", env->work, p->part);
    o.log_path = list_log;
    bool listed = grade_suite_list(bin, &o, &order);
    grade_suite_results(dir, listed ? &order : NULL, p->unit_tests, rr.status, r);
}

/* ---- one part -------------------------------------------------------------------------------- */

bool grade_part_dirs(const grade_env *env, int part)
{
    /* The part's folder is the grader's alone (its logs and films); the children get the sandbox's. */
    char dir[4096];
    grade_path(dir, sizeof dir, "%s/part%d", env->work, part);
    return grade_guard_child_dir(dir, &env->sandbox, false) && chmod(dir, 0700) == 0;
}

/* The part's cases, listed in r with their points before anything runs (every case is in the
 * results whatever happens). */
static void list_cases(const grade_env *env, const grade_part_spec *p, grade_part_result *r)
{
    memset(r, 0, sizeof *r);
    r->part = p->part;
    r->spec = p;
    for (int i = 0; i < p->num_cases; i++) {
        if (env->public_only && p->cases[i].hidden) continue;
        grade_case_result *c = &r->cases[r->num_cases++];
        memset(c, 0, sizeof *c);
        c->spec = &p->cases[i];
    }
}

/* Built (a submission's inspected against the allow-list before any of it is linked: grade_build.c);
 * else the reason is in r->suite_reason and every case's. */
static bool ready(const grade_env *env, const char *tree, int part, grade_part_result *r)
{
    char dir[4096];
    grade_path(dir, sizeof dir, "%s/part%d", env->work, part);
    if (!grade_part_dirs(env, part)) grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot create %s", dir);
    r->built = !r->suite_reason[0] &&
               (env->submission ? grade_build_submission(env, part, tree, r) : build_own_tree(env, part, r));
    if (!r->built && !r->suite_reason[0]) grade_msg(r->suite_reason, sizeof r->suite_reason, "the part does not build");
    for (int i = 0; r->suite_reason[0] && i < r->num_cases; i++)
        snprintf(r->cases[i].reason, sizeof r->cases[i].reason, "%s", r->suite_reason);
    return !r->suite_reason[0];
}

void grade_part(const grade_env *env, const grade_spec *spec, const grade_part_spec *p, grade_part_result *r)
{
    list_cases(env, p, r);
    char tree[4096], suite[4200];
    /* A student's own tree is graded where it is; a submission's part is built into a tree of its
     * own in the sandbox's folder, removed below. (Never the other way round: the tree removed is
     * always that one, whatever failed.) */
    if (env->submission) grade_path(tree, sizeof tree, "%s/part%d", env->sandbox_dir, p->part);
    else grade_path(tree, sizeof tree, "%s", env->root);
    if (ready(env, tree, p->part, r)) {
        /* A submission's verdicts come from the course's judge (grade_judge.c), never from a process
         * its code ran in; a student's own tree runs its suite whole, faster and theirs to trust. */
        if (env->submission) grade_judge_suite(env, tree, p, r);
        else run_suite(env, tree, p, r);
        for (int i = 0; i < r->num_cases; i++) grade_image_case(env, spec, tree, p->part, &r->cases[i]);
    }
    /* Nothing of this part stays in reach of the next: its tree and its suite's folder go. */
    grade_path(suite, sizeof suite, "%s/part%d-suite", env->sandbox_dir, p->part);
    grade_tree_remove(suite);
    if (env->submission) grade_tree_remove(tree);
    grade_score_part(p, r);
}
