/* Test machinery: not part of any assignment. The file module's reader (framework/file.c): inputs
 * that never end or are not files are refused before a byte is read. */
#include "../common/test.h"
#include "../../framework/file.h"
#include "../../framework/dae.h"
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void expect_refused(const char *path, const char *why)
{
    char *data = (char *)1;
    size_t len = 7;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, file_read_all(path, "scene", 1 << 20, &data, &len, &d));
    assert_null(data);
    assert_int_equal(0, len);
    if (!strstr(d.error, path) || !strstr(d.error, why))
        fail_msg("expected a message naming %s and saying '%s', got: %s", path, why, d.error);
}

static void test_file_read_all__reads_a_small_file_whole(void **state)
{
    (void)state;
    char path[] = "/tmp/pathlab-file-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(5, write(fd, "hello", 5));
    close(fd);
    char *data;
    size_t len;
    assert_int_equal(PL_OK, file_read_all(path, "scene", 5, &data, &len, NULL));
    assert_int_equal(5, len);
    assert_string_equal("hello", data);  /* NUL-terminated */
    free(data);
    expect_refused("/definitely/not/here.dae", "cannot open");
    remove(path);
}

/* /dev/zero never ends; a directory and a FIFO are not files. A FIFO without a writer must not
 * block the reader either. */
static void test_file_read_all__refuses_devices_fifos_and_directories(void **state)
{
    (void)state;
    expect_refused("/dev/zero", "expected a regular file");
    expect_refused("/tmp", "found a directory");
    char dir[] = "/tmp/pathlab-fifo-XXXXXX", fifo[64];
    assert_non_null(mkdtemp(dir));
    snprintf(fifo, sizeof fifo, "%s/scene.dae", dir);
    assert_int_equal(0, mkfifo(fifo, 0600));
    expect_refused(fifo, "found a pipe");
    remove(fifo);
    rmdir(dir);
}

/* The cap applies before reading: a sparse file of the cap + 1 costs no disk and no memory. */
static void test_file_read_all__refuses_a_file_over_its_cap_before_reading(void **state)
{
    (void)state;
    char path[] = "/tmp/pathlab-big-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(0, ftruncate(fd, (off_t)DAE_MAX_FILE_BYTES + 1));
    close(fd);
    char *data = NULL;
    size_t len = 0;
    pl_diag d = pl_diag_default();
    scene s;
    assert_int_equal(PL_ERR_IO, dae_load(path, &s, &d));
    assert_non_null(strstr(d.error, "the limit is"));
    assert_int_equal(PL_ERR_IO, file_read_all(path, "scene", 1000, &data, &len, &d));
    assert_null(data);
    remove(path);
}

int file_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_file_read_all__reads_a_small_file_whole),
        cmocka_unit_test(test_file_read_all__refuses_devices_fifos_and_directories),
        cmocka_unit_test(test_file_read_all__refuses_a_file_over_its_cap_before_reading),
    };
    return cmocka_run_group_tests_name("file", tests, NULL, NULL);
}
