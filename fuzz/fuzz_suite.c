/* Test machinery: not part of any assignment.
 * The test-results fuzzer (libFuzzer, `make fuzz FUZZ_TARGET=suite`): every input is a cmocka XML
 * file as code under test could leave it, read by the grader's suite reader (grade_suite_read) as
 * part 1's group "g". Refusals are expected; only crashes, sanitizer reports and leaks count. */
#include "../grader/grade_suite.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char dir[64], path[128];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    snprintf(dir, sizeof dir, "/tmp/pathlab-fuzz-suite-XXXXXX");
    if (!mkdtemp(dir)) return 1;
    snprintf(path, sizeof path, "%s/part1: g.xml", dir);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    static grade_test_fact tests[GRADE_MAX_TESTS];
    grade_suite_facts s = {.tests = tests};
    char why[200];
    grade_suite_read(dir, NULL, 1, &s, why, sizeof why);
    return 0;
}
