/* Test machinery: not part of any assignment.
 * The film fuzzer (libFuzzer, `make fuzz FUZZ_TARGET=film`): every input is one or two range files
 * as a broken copy or an attacker would write them (a second OpenEXR magic number, past the first
 * file's start, begins the second file). Each is read and checked (exr_read_info, exr_read: the
 * strict reader) and as an environment map (envmap_load: exr.h's reader of any RGB image), and then
 * both are merged by `pathtracer --merge` itself (range_merge_main) into a scratch file. Refusals are the expected outcome; only crashes, sanitizer reports, leaks and
 * allocations over the 1 GB limit (-malloc_limit_mb) count. */
#include "../framework/envmap.h"
#include "../framework/exr.h"
#include "../framework/range.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char scratch[64];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    snprintf(scratch, sizeof scratch, "/tmp/pathlab-fuzz-film-XXXXXX");
    return mkdtemp(scratch) ? 0 : 1;
}

static void write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t magic[4] = {0x76, 0x2f, 0x31, 0x01};
    size_t split = size;
    for (size_t i = 4; i + 4 <= size; i++)
        if (!memcmp(data + i, magic, 4)) {
            split = i;
            break;
        }
    char in[2][128], out[128];
    snprintf(in[0], sizeof in[0], "%s/a.exr", scratch);
    snprintf(in[1], sizeof in[1], "%s/b.exr", scratch);
    snprintf(out, sizeof out, "%s/merged.exr", scratch);
    write_file(in[0], data, split);
    write_file(in[1], data + split, size - split);
    for (int k = 0; k < 2; k++) {
        pl_diag quiet = pl_diag_default();
        film f = {0};
        exr_info info;
        int w, h;
        exr_read_info(in[k], &info, &w, &h, &quiet);
        if (exr_read(in[k], &f, &info, &quiet) == PL_OK) film_free(&f);
        envmap e;
        if (envmap_load(in[k], &e, &quiet) == PL_OK) envmap_free(&e);
    }
    char *argv[] = {"pathtracer", "--merge", "-q", "-f", out, in[0], split < size ? in[1] : NULL, NULL};
    range_merge_main(split < size ? 7 : 6, argv, "fuzz");
    unlink(out);
    return 0;
}
