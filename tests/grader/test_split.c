/* Test machinery: not part of any assignment. The grader's pipes for the split suites
 * (grader/grade_tests.c): grade_run_piped gives a child its stdin and its fd 3. */
#include "../common/test.h"
#include "../../grader/grade_run.h"
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

/* Runs `sh -c script` with in_fd as stdin and the write end of a fresh pipe as fd 3 (numbered
 * `number` in the grader, 3 included, whose close-on-exec must then be cleared); returns what the
 * child wrote to fd 3. */
static void run_with_pipes(const char *script, int in_fd, int number, char *out, size_t size)
{
    int fds[2];
    assert_true(grade_pipe(fds));
    int reader = fcntl(fds[0], F_DUPFD_CLOEXEC, 40);  /* out of the way of `number` */
    assert_true(reader >= 40);
    close(fds[0]);
    fds[0] = reader;
    int record = dup2(fds[1], number);
    assert_int_equal(record, number);
    assert_int_equal(fcntl(record, F_SETFD, FD_CLOEXEC), 0);
    close(fds[1]);
    char *argv[] = {"sh", "-c", (char *)script, NULL};
    grade_run_opts o = {.wall_seconds = 10};
    grade_run_result r = grade_run_piped(argv, &o, in_fd, record);
    close(record);
    assert_true(r.exited);
    assert_int_equal(r.status, 0);
    ssize_t n = read(fds[0], out, size - 1);
    out[n > 0 ? n : 0] = '\0';
    close(fds[0]);
}

static void test_run_piped__stdin_and_fd_3_reach_the_child(void **state)
{
    (void)state;
    int in[2];
    assert_true(grade_pipe(in));
    assert_int_equal(write(in[1], "record\n", 7), 7);
    close(in[1]);
    char got[64];
    run_with_pipes("cat >&3", in[0], 30, got, sizeof got);
    close(in[0]);
    assert_string_equal(got, "record\n");
}

static void test_run_piped__fd_3_itself_is_handed_over(void **state)
{
    (void)state;
    /* The grader's own fd 3, if free, is the pipe itself: dup2 onto itself would keep it closed on exec. */
    if (fcntl(3, F_GETFD) != -1) skip();
    char got[64];
    run_with_pipes("echo three >&3", 0, 3, got, sizeof got);
    assert_string_equal(got, "three\n");
}

int split_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_run_piped__stdin_and_fd_3_reach_the_child),
        cmocka_unit_test(test_run_piped__fd_3_itself_is_handed_over),
    };
    return cmocka_run_group_tests_name("grader: the split suites' pipes", tests, NULL, NULL);
}
