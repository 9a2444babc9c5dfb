/* Test machinery: not part of any assignment. The student release's devcontainer
 * (.devcontainer/devcontainer.json): it parses as JSON, runs on Debian 12 and sets pathlab up with
 * tools/setup, so a laptop with Docker (or GitHub Codespaces) gets the environment CI tests. */
#include "../../tests/common/test.h"
#include <jansson.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define DEVCONTAINER ".devcontainer/devcontainer.json"
#define SETUP_COMMAND "sh tools/setup --no-render"

/* Why the file at path is not a devcontainer for pathlab, or NULL when it is. Debian 12 is named
 * by its number or its code name (bookworm), as Docker images name it. */
static const char *devcontainer_problem(const char *path, char *why, size_t size)
{
    json_error_t err;
    json_t *root = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    if (!root) {
        snprintf(why, size, "%s:%d: not JSON: %s", path, err.line, err.text);
        return why;
    }
    const char *image = json_string_value(json_object_get(root, "image"));
    const char *command = json_string_value(json_object_get(root, "postCreateCommand"));
    if (!image) snprintf(why, size, "%s: no \"image\" string", path);
    else if (!strstr(image, "bookworm") && !strstr(image, "debian:12") && !strstr(image, "debian-12"))
        snprintf(why, size, "%s: image \"%s\" is not Debian 12 (bookworm)", path, image);
    else if (!command || strcmp(command, SETUP_COMMAND) != 0)
        snprintf(why, size, "%s: postCreateCommand is not \"%s\"", path, SETUP_COMMAND);
    else why = NULL;
    json_decref(root);
    return why;
}

static void test_devcontainer__debian12_runs_setup(void **state)
{
    (void)state;
    char why[512];
    const char *problem = devcontainer_problem(DEVCONTAINER, why, sizeof why);
    if (problem) fail_msg("%s", problem);
    assert_int_equal(0, access("tools/setup", R_OK));
}

/* The check itself: each way a devcontainer can be wrong is caught. */
static void test_devcontainer__check_rejects_wrong_files(void **state)
{
    (void)state;
    static const struct { const char *text, *expected; } cases[] = {
        {"{\"image\": \"debian:12\", \"postCreateCommand\": \"" SETUP_COMMAND "\",}", "not JSON"},
        {"{\"postCreateCommand\": \"" SETUP_COMMAND "\"}", "no \"image\""},
        {"{\"image\": \"ubuntu:22.04\", \"postCreateCommand\": \"" SETUP_COMMAND "\"}", "not Debian 12"},
        {"{\"image\": \"debian:12\", \"postCreateCommand\": \"make\"}", "postCreateCommand"},
        {"{\"image\": \"debian:12\", \"image\": \"debian:12\"}", "not JSON"},
    };
    char path[] = "/tmp/pathlab-devcontainer-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(cases[i].text, f);
        fclose(f);
        char why[512];
        const char *problem = devcontainer_problem(path, why, sizeof why);
        if (!problem || !strstr(problem, cases[i].expected))
            fail_msg("%s: expected a problem saying '%s', got '%s'", cases[i].text, cases[i].expected,
                     problem ? problem : "none");
    }
    unlink(path);
}

int devcontainer_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_devcontainer__debian12_runs_setup),
        cmocka_unit_test(test_devcontainer__check_rejects_wrong_files),
    };
    return cmocka_run_group_tests_name("devcontainer", tests, NULL, NULL);
}
