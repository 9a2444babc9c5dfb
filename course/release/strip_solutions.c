/* Instructor tooling: not part of any assignment.
 * strip_solutions: turns one file of the instructor's tree into the student's (see course/release/strip.h).
 *
 *   strip_solutions SRC DST          strip SRC into DST (written whole or not at all)
 *   strip_solutions --check FILE...  validate the solution markers only
 *   strip_solutions --tasks FILE...  validate markers and task banners; print one line a task:
 *                                    "<part> <id> <function> <file>:<line>"
 * Exit status: 0 when everything is valid, 2 otherwise (each problem printed as file:line: ...). */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "strip.h"
#include "../../framework/file.h"

static void usage(FILE *f)
{
    fprintf(f, "usage: strip_solutions SRC DST\n"
               "       strip_solutions --check FILE...\n"
               "       strip_solutions --tasks FILE...\n");
}

/* No source file of the lab comes near this; a bigger one is not a source file. */
#define SOURCE_MAX_BYTES (16u << 20)

/* One file in one mode; prints its problem or its tasks. */
static bool process(const char *mode, const char *src, const char *dst)
{
    pl_diag diag = pl_diag_default();
    char *in = NULL, *out = NULL;
    size_t len = 0;
    pl_status s = file_read_all(src, "source file", SOURCE_MAX_BYTES, &in, &len, &diag);
    if (s == PL_OK && strcmp(mode, "--tasks") == 0) {
        strip_task *tasks = NULL;
        int num_tasks = 0;
        s = strip_tasks(in, len, src, &tasks, &num_tasks, &diag);
        for (int i = 0; s == PL_OK && i < num_tasks; i++)
            printf("%d %s %s %s:%d\n", tasks[i].part, tasks[i].id, tasks[i].function, src, tasks[i].line);
        free(tasks);
    } else if (s == PL_OK) {
        s = strip_text(in, len, src, dst ? &out : NULL, &diag);
        if (s == PL_OK && dst) s = file_write_atomic(dst, out, strlen(out), &diag);
    }
    if (s != PL_OK) fprintf(stderr, "%s\n", diag.error);
    free(in);
    free(out);
    return s == PL_OK;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)) {
        usage(stdout);
        return 0;
    }
    bool many = argc >= 3 && (strcmp(argv[1], "--check") == 0 || strcmp(argv[1], "--tasks") == 0);
    if (!many && (argc != 3 || argv[1][0] == '-')) {
        usage(stderr);
        return 2;
    }
    if (!many) return process("strip", argv[1], argv[2]) ? 0 : 2;
    bool ok = true;
    for (int i = 2; i < argc; i++) ok = process(argv[1], argv[i], NULL) && ok;
    return ok ? 0 : 2;
}
