/* Grader machinery: not part of any assignment.
 * The run stage of a part's unit tests (grade_tests.h). A submission's suite runs split (grader/seam/
 * seam.h says how the two halves work): for each test, the subject runs the submission's code,
 * contained, and writes its calls' answers to a pipe; the judge, the course's binary with no student
 * code in it, runs the same test on those answers. Only the judge's results count: what the subject
 * prints, exits with or writes to files is never read. One pair of processes per test, so a crash,
 * a hang or a corrupted subject costs that test only. A student's own tree runs its suite whole. */
#include "grade_tests.h"
#include "grade_guard.h"
#include "sandbox.h"
#include "../framework/clock.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define JUDGE_SEAM_STATUS 3  /* replay.c: the record stream failed on a render's worker thread */

/* The tests of program, listed by itself (PL_TEST_LIST=1: a "  name" line per test,
 * tests/common/filter.c), run with o (its env replaced) and read back from o->log_path; false when it
 * lists none. */
static bool list_tests(const char *program, const grade_run_opts *o, grade_test_list *list)
{
    char *envv[] = {"PL_TEST_LIST=1", NULL}, *argv[] = {(char *)program, NULL};
    grade_run_opts listing = *o;
    listing.env = envv;
    grade_run_result rr = grade_run(argv, &listing);
    FILE *f = rr.exited && rr.status == 0 && o->log_path ? fopen(o->log_path, "r") : NULL;
    list->count = 0;
    char line[512];
    while (f && fgets(line, sizeof line, f)) {
        size_t len = strcspn(line, "\n");
        line[len] = '\0';
        if (strncmp(line, "  ", 2) || len - 2 >= sizeof list->names[0] ||
            strspn(line + 2, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != len - 2)
            continue;
        if (list->count < GRADE_MAX_TESTS) memcpy(list->names[list->count++], line + 2, len - 1);  /* and its NUL */
    }
    if (f) fclose(f);
    return list->count > 0;
}

/* ---- a student's own tree: the suite whole ------------------------------------------------------ */

void grade_tests_own(const grade_plan *plan, const grade_part_spec *p, grade_suite_facts *s)
{
    s->run = s->failed = s->num_tests = 0;
    s->judged = false;
    /* The suite's own folder: it may write its results there, and nothing else beside them. */
    if (!grade_guard_child_dir(plan->suite_dir, NULL, false)) {
        s->why = grade_why_of(GRADE_WHY_GRADER);
        snprintf(s->why.detail, sizeof s->why.detail, "cannot create the suite's results folder");
        return;
    }
    char *envv[] = {"CMOCKA_MESSAGE_OUTPUT=xml", (char *)plan->suite_xml_env, NULL};
    char *argv[] = {(char *)plan->test_program, NULL};
    grade_run_opts o = {.wall_seconds = GRADE_SUITE_SECONDS, .deadline = plan->deadline, .cwd = plan->tree,
                        .log_path = plan->suite_log, .log_max = GRADE_LOG_MAX, .env = envv, .writes_files = true,
                        .writable = plan->suite_dir};
    grade_run_result rr = grade_run(argv, &o);
    /* A suite that crashed or timed out scores zero, whatever files it left. */
    if (!rr.exited) {
        s->why = grade_why_of(GRADE_WHY_SUITE_ENDED);
        s->why.run = rr;
        return;
    }
    /* The suite's own list of its tests orders them as it ran them (nothing is judged by it). */
    grade_test_list *order = malloc(sizeof *order);
    o.log_path = plan->suite_list_log;
    bool listed = order && list_tests(plan->test_program, &o, order);
    grade_suite_results(plan->suite_dir, listed ? order : NULL, p->unit_tests, rr.status, p->part, s);
    free(order);
}

/* ---- a submission: subject | judge, one test at a time ---------------------------------------------- */

/* The judge's own message for a test it ended through the record stream ("seam: ..." in its log). */
static void seam_message(const char *log, char *out, size_t size)
{
    snprintf(out, size, "the code under test stopped answering");
    FILE *f = fopen(log, "r");
    char line[1024];
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "seam: ", 6)) snprintf(out, size, "%.*s", (int)strcspn(line + 6, "\n"), line + 6);
    if (f) fclose(f);
}

/* The subject, in a helper process (grade_run waits for its child, and the judge must read at the
 * same time): the submission's code, contained, its records on fd 3, its output in its log only. */
static pid_t start_subject(const grade_plan *plan, const grade_plan_test *t, const grade_sandbox *sandbox,
                           int record_fd, int judge_fd)
{
    pid_t helper = fork();
    if (helper != 0) return helper;
    /* The judge's end of the pipe is the judge's alone: held open here too, a subject that wrote what
     * the judge refused would block on a full pipe until its timeout (120 s a test), where with the
     * judge gone its next write fails at once. */
    close(judge_fd);
    /* The subject's orphans (a setsid grandchild) come to this helper, whose grade_run kills them. */
    sandbox_adopt_orphans();
    char *argv[] = {(char *)plan->subject, NULL};
    grade_run_opts o = {.wall_seconds = GRADE_TEST_SECONDS, .deadline = plan->deadline, .cwd = plan->tree,
                        .log_path = t->subject_log, .log_max = GRADE_LOG_MAX, .env = (char *const *)t->subject_env,
                        .untrusted = true, .sandbox = sandbox};
    grade_run_piped(argv, &o, 0, record_fd);
    _exit(0);
}

/* One test, subject | judge; adds its verdict to s from the judge's results only. */
static void run_test(const grade_plan *plan, const grade_env *env, int k, const char *name, grade_suite_facts *s)
{
    grade_plan_test t;
    int fds[2];
    grade_run_result rr = {.status = -1};
    if (grade_plan_split_test(plan, k, name, &t) && grade_pipe(fds)) {
        unlink(t.judge_xml);  /* cmocka does not overwrite a results file */
        pid_t helper = start_subject(plan, &t, &env->sandbox, fds[1], fds[0]);
        close(fds[1]);
        char *argv[] = {(char *)plan->judge, NULL};
        /* The judge is the course's code, but it parses what the subject sent: bounded like it. */
        grade_run_opts o = {.wall_seconds = GRADE_JUDGE_SECONDS, .deadline = plan->deadline, .cwd = env->root,
                            .log_path = t.judge_log, .log_max = GRADE_LOG_MAX, .env = t.judge_env, .bounded = true};
        if (helper > 0) rr = grade_run_piped(argv, &o, fds[0], 0);
        close(fds[0]);
        if (helper > 0) waitpid(helper, NULL, 0);
    }
    /* Passed or failed by cmocka: its results file holds exactly this test. */
    int run = s->run, failed = s->failed, noted = s->num_tests;
    char why[700];
    bool judged = rr.exited && (rr.status == 0 || rr.status == 1) && grade_suite_read_file(t.judge_xml, NULL, s, why, sizeof why) &&
                  s->run == run + 1 && s->failed - failed == rr.status;
    /* The verdict is recorded under the course's own name of the test (its list), whatever the file said. */
    grade_test_fact kept = judged ? s->tests[noted] : (grade_test_fact){0};
    s->num_tests = noted;
    grade_test_fact *f = grade_suite_note(s, name, judged && rr.status == 0);
    if (!f) return;
    if (judged) {
        snprintf(f->message, sizeof f->message, "%s", kept.message);
        return;
    }
    s->run = run + 1;
    s->failed = failed + 1;
    if (rr.exited && rr.status == JUDGE_SEAM_STATUS) seam_message(t.judge_log, f->message, sizeof f->message);
    else {
        f->why = grade_why_of(rr.out_of_time ? GRADE_WHY_TEST_OUT_OF_TIME : GRADE_WHY_JUDGE_UNFINISHED);
        f->why.run = rr;
    }
}

/* The tests of list from `from` on, failed as not run: the deadline came, or the suite's own limit. */
static void not_run(const grade_test_list *list, int from, grade_why why, grade_suite_facts *s)
{
    for (int i = from; i < list->count; i++) {
        grade_test_fact *f = grade_suite_note(s, list->names[i], false);
        s->run++, s->failed++;
        if (f) f->why = why;
    }
}

void grade_tests_split(const grade_plan *plan, const grade_env *env, const grade_part_spec *p, grade_suite_facts *s)
{
    s->run = s->failed = s->num_tests = 0;
    s->judged = false;
    /* The subjects' logs go here, written by the grader: the folder is the grader's own. */
    if (mkdir(plan->split_dir, 0755) != 0 && errno != EEXIST) {
        s->why = grade_why_of(GRADE_WHY_GRADER);
        snprintf(s->why.detail, sizeof s->why.detail, "cannot create the split suite's folder");
        return;
    }
    /* The course's judge, built with the course's objects before any student code ran
     * (grade_tree_course_build), never in a grading tree. */
    grade_test_list *list = malloc(sizeof *list);
    grade_run_opts o = {.wall_seconds = GRADE_JUDGE_SECONDS, .cwd = env->root, .log_path = plan->tests_list_log,
                        .log_max = GRADE_LOG_MAX, .bounded = true};
    s->why = grade_why_of(GRADE_WHY_COURSE);
    if (!list || !list_tests(plan->judge, &o, list))
        snprintf(s->why.detail, sizeof s->why.detail, "the course's judge of part %d does not run", p->part);
    else if (list->count != p->unit_tests)
        snprintf(s->why.detail, sizeof s->why.detail, "the course's suite of part %d has %d tests, grading/cases.json "
                 "says %d", p->part, list->count, p->unit_tests);
    else {
        s->why = grade_why_of(GRADE_WHY_NONE);
        s->judged = true;
        /* The suite's own limit, or the grading's deadline: the tests left then fail as not run, and
         * the tasks whose tests all finished keep their shares. */
        double t0 = clock_seconds();
        for (int k = 0; k < list->count; k++) {
            bool suite_over = clock_seconds() - t0 > GRADE_SUITE_SECONDS;
            if (suite_over || (plan->deadline > 0 && clock_seconds() >= plan->deadline)) {
                grade_why w = grade_why_of(suite_over ? GRADE_WHY_TEST_NOT_RUN : GRADE_WHY_TEST_OUT_OF_TIME);
                w.limit = GRADE_SUITE_SECONDS;
                not_run(list, k, w, s);
                break;
            }
            run_test(plan, env, k, list->names[k], s);
        }
    }
    free(list);
}
