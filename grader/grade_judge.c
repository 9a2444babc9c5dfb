/* Grader machinery: not part of any assignment. The split suite of one part (grader/seam/seam.h says
 * how the two halves work): for each test, the subject runs the submission's code, contained, and
 * writes its calls' answers to a pipe; the judge, the course's binary with no student code in it,
 * runs the same test on those answers. Only the judge's results count: what the subject prints,
 * exits with or writes to files is never read. One pair of processes per test, so a crash, a hang
 * or a corrupted subject costs that test only. */
#include "../framework/clock.h"
#include "grade.h"
#include "grade_suite.h"
#include "sandbox.h"
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define JUDGE_SEAM_STATUS 3  /* replay.c: the record stream failed on a render's worker thread */

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
static pid_t start_subject(const char *tree, int n, const char *name, const char *dir, int k, int record_fd,
                           int judge_fd, double deadline)
{
    pid_t helper = fork();
    if (helper != 0) return helper;
    /* The judge's end of the pipe is the judge's alone: held open here too, a subject that wrote what
     * the judge refused would block on a full pipe until its timeout (120 s a test), where with the
     * judge gone its next write fails at once. */
    close(judge_fd);
    /* The subject's orphans (a setsid grandchild) come to this helper, whose grade_run kills them. */
    sandbox_adopt_orphans();
    char bin[4200], log[4200], filter[200];
    grade_path(bin, sizeof bin, "%s/bin/subject-part%d", tree, n);
    grade_path(log, sizeof log, "%s/subject-%d.log", dir, k);
    grade_path(filter, sizeof filter, "PL_TEST_FILTER=%s", name);
    char *envv[] = {filter, "PL_SEAM_FD=3", NULL}, *argv[] = {bin, NULL};
    grade_run_opts o = {.wall_seconds = GRADE_TEST_SECONDS, .deadline = deadline, .cwd = tree, .log_path = log, .log_max = GRADE_LOG_MAX,
                        .env = envv, .untrusted = true};
    grade_run_piped(argv, &o, 0, record_fd);
    _exit(0);
}

/* One test, subject | judge; adds its verdict to r from the judge's results only. */
static void run_test(const grade_env *env, const char *tree, const char *judge, int n, const char *name,
                     const char *dir, int k, grade_part_result *r)
{
    char xml[4200], xml_env[4300], log[4200], filter[200], line[1024], why[700];
    grade_path(xml, sizeof xml, "%s/judge-%d.xml", dir, k);
    grade_path(xml_env, sizeof xml_env, "CMOCKA_XML_FILE=%s", xml);
    grade_path(log, sizeof log, "%s/judge-%d.log", dir, k);
    grade_path(filter, sizeof filter, "PL_TEST_FILTER=%s", name);
    unlink(xml);  /* cmocka does not overwrite a results file */
    int fds[2];
    grade_run_result rr = {.status = -1};
    if (grade_pipe(fds)) {
        pid_t helper = start_subject(tree, n, name, dir, k, fds[1], fds[0], env->deadline);
        close(fds[1]);
        char *envv[] = {filter, "PL_SEAM_FD=0", "CMOCKA_MESSAGE_OUTPUT=xml", xml_env, NULL}, *argv[] = {(char *)judge, NULL};
        /* The judge is the course's code, but it parses what the subject sent: bounded like it. */
        grade_run_opts o = {.wall_seconds = GRADE_JUDGE_SECONDS, .deadline = env->deadline, .cwd = env->root,
                            .log_path = log, .log_max = GRADE_LOG_MAX, .env = envv, .bounded = true};
        if (helper > 0) rr = grade_run_piped(argv, &o, fds[0], 0);
        close(fds[0]);
        if (helper > 0) waitpid(helper, NULL, 0);
    }
    /* Passed or failed by cmocka: its results file holds exactly this test. */
    int run = r->tests_run, failed = r->tests_failed, noted = r->num_tests;
    bool judged = rr.exited && (rr.status == 0 || rr.status == 1) && grade_suite_read_file(xml, NULL, r, why, sizeof why) &&
                  r->tests_run == run + 1 && r->tests_failed - failed == rr.status;
    /* The verdict is recorded under the course's own name of the test (its list), whatever the file says. */
    r->num_tests = noted;
    grade_score_note_test(r, name, judged && rr.status == 0);
    if (judged) return;
    r->tests_run = run + 1;
    r->tests_failed = failed + 1;
    if (rr.exited && rr.status == JUDGE_SEAM_STATUS) seam_message(log, why, sizeof why);
    else if (rr.out_of_time) grade_msg(why, sizeof why, "did not finish: %s", GRADE_OUT_OF_TIME);
    else {
        char how[128];
        grade_run_describe(&rr, how, sizeof how);
        grade_msg(why, sizeof why, "the course's judge of this test did not finish (%s): please tell the course staff", how);
    }
    snprintf(line, sizeof line, "- `%s`: %s\n", name, why);
    size_t len = strlen(r->failures);
    if (len + 1 < sizeof r->failures) snprintf(r->failures + len, sizeof r->failures - len, "%s", line);
}

/* The tests of list from `from` on, failed as not run, with why (the grader's words). */
static void not_run(const grade_test_list *list, int from, const char *why, grade_part_result *r)
{
    for (int i = from; i < list->count; i++) {
        grade_score_note_test(r, list->names[i], false);
        r->tests_run++, r->tests_failed++;
        size_t len = strlen(r->failures);
        if (len + 1 < sizeof r->failures)
            snprintf(r->failures + len, sizeof r->failures - len, "- `%s`: did not run: %s\n", list->names[i], why);
    }
}

void grade_judge_suite(const grade_env *env, const char *tree, const grade_part_spec *p, grade_part_result *r)
{
    char dir[4096], judge[4200];
    r->tests_run = r->tests_failed = r->num_tests = 0;
    r->failures[0] = '\0';
    grade_path(dir, sizeof dir, "%s/part%d/split", env->work, p->part);
    /* The subjects' logs go here, written by the grader: the folder is the grader's own. */
    if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
        grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot create %s", dir);
        return;
    }
    /* The course's judge, built with the course's objects before any student code ran
     * (grade_tree_course_build), never in a grading tree. */
    static grade_test_list list;
    char log[4200];
    grade_path(judge, sizeof judge, "%s/course/bin/judge-part%d", env->work, p->part);
    grade_path(log, sizeof log, "%s/tests.list", dir);
    grade_run_opts o = {.wall_seconds = GRADE_JUDGE_SECONDS, .cwd = env->root, .log_path = log, .log_max = GRADE_LOG_MAX,
                        .bounded = true};
    if (!grade_suite_list(judge, &o, &list)) {
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the course's judge of part %d does not run (see "
                 "%s/tests.list): the course's problem, please tell the staff", p->part, dir);
        return;
    }
    if (list.count != p->unit_tests) {
        grade_msg(r->suite_reason, sizeof r->suite_reason, "the course's suite has %d tests, grading/cases.json says "
                 "%d: the course's problem, please tell the staff", list.count, p->unit_tests);
        return;
    }
    /* The suite's own limit, or the grading's deadline: the tests left then fail as not run, and the
     * tasks whose tests all finished keep their shares. */
    double t0 = clock_seconds();
    for (int k = 0; k < list.count; k++) {
        bool suite_over = clock_seconds() - t0 > GRADE_SUITE_SECONDS;
        bool no_time = env->deadline > 0 && clock_seconds() >= env->deadline;
        if (suite_over || no_time) {
            not_run(&list, k, suite_over ? "the part's tests ran past their time together"
                                                               : GRADE_OUT_OF_TIME, r);
            break;
        }
        run_test(env, tree, judge, p->part, list.names[k], dir, k, r);
    }
}
