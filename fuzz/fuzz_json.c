/* Test machinery: not part of any assignment.
 * The grader's JSON fuzzer (libFuzzer, `make fuzz FUZZ_TARGET=json`): every input is read as the
 * course's cases file (grade_spec_load: grading/cases.json) and as a reference's JSON
 * (grade_refs_figures, for a plain case and an adaptive one, whose rate map it reads). Refusals are expected;
 * only crashes, sanitizer reports and leaks count. */
#include "../grader/grade_spec.h"
#include "../grader/grade_refs.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char json[96], exr[96];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char dir[64];
    snprintf(dir, sizeof dir, "/tmp/pathlab-fuzz-json-XXXXXX");
    if (!mkdtemp(dir)) return 1;
    snprintf(json, sizeof json, "%s/ref.json", dir);
    snprintf(exr, sizeof exr, "%s/ref.exr", dir);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fopen(json, "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    pl_diag quiet = pl_diag_default();
    grade_spec spec;
    if (grade_spec_load(json, NULL, &spec, &quiet) == PL_OK) grade_spec_free(&spec);
    static char flag[] = "-a";
    grade_case k;
    memset(&k, 0, sizeof k);
    static grade_course_figures figures;
    k.width = 120, k.height = 90;
    for (int kind = 0; kind < 2; kind++) {
        k.flags[0] = flag;
        k.num_flags = kind == 1;
        grade_refs_figures(exr, &k, &figures, &quiet);
    }
    return 0;
}
