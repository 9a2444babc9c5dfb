/* Grader machinery: not part of any assignment.
 * The handout's grading tables, generated from grading/cases.json (grade_handout.h): what a part's
 * unit tasks and public image cases are worth is written once, in the cases file, and the handout
 * shows that file's figures, so the two cannot drift apart. `bin/grade --handout write` rewrites the
 * tables in handout/part<N>.md; `--handout check` (and make test-grader) fails on any difference. */
#include "grade_handout.h"
#include "grade_fmt.h"
#include "grade_plan.h"
#include "../framework/file.h"
#include <dirent.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BEGIN_MARK "<!-- BEGIN GENERATED: the grading table, from grading/cases.json (bin/grade --handout write) -->\n"
#define END_MARK "<!-- END GENERATED -->\n"

/* Appends printf-style text to out (size bytes), keeping *len; false once it no longer fits. */
static bool put(char *out, size_t size, size_t *len, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static bool put(char *out, size_t size, size_t *len, const char *fmt, ...)
{
    if (*len >= size) return false;
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(out + *len, size - *len, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= size - *len) return *len = size, false;
    *len += (size_t)n;
    return true;
}

static int compare_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The test functions of part p's suite, "static void test_<name>(" in the .c files of tests/part<N>, in file
 * name order and, within a file, in order of definition; into names (each up to 96 bytes). */
static int suite_tests(int part, char names[][96], int max)
{
    char dir[64];
    grade_plan_suite_sources(part, dir, sizeof dir);
    DIR *d = opendir(dir);
    char *files[64];
    int nfiles = 0, n = 0;
    for (struct dirent *e; d && (e = readdir(d)) && nfiles < 64;) {
        size_t len = strlen(e->d_name);
        if (len > 2 && !strcmp(e->d_name + len - 2, ".c") && (files[nfiles] = strdup(e->d_name))) nfiles++;
    }
    if (d) closedir(d);
    qsort(files, (size_t)nfiles, sizeof *files, compare_names);
    for (int f = 0; f < nfiles; f++) {
        char path[128], *text = NULL;
        size_t len = 0;
        pl_diag diag = pl_diag_default();
        bool named = grade_join(dir, files[f], path, sizeof path);
        free(files[f]);
        if (!named || file_read_all(path, "test source", (size_t)1 << 22, &text, &len, &diag) != PL_OK) continue;
        for (char *at = text; (at = strstr(at, "\nstatic void test_")) && n < max;) {
            at += strlen("\nstatic void ");
            size_t name = strspn(at, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_");
            if (at[name] == '(' && name < 96) snprintf(names[n++], 96, "%.*s", (int)name, at);
        }
        free(text);
    }
    return n;
}

bool grade_handout_table(const grade_part_spec *p, char *out, size_t size)
{
    size_t len = 0;
    bool ok = put(out, size, &len, "The unit tests are shared out by task: a task's points are earned when every one of "
                  "its tests passes (`%s test-part%d` names them), and none otherwise.\n\n"
                  "| task | functions | tests | points |\n| --- | --- | --- | --- |\n", "make", p->part);
    for (int t = 0; ok && t < p->num_tasks; t++) {
        /* "bsdf_pdf, bsdf_sample_f" reads as code; words ("the whole part: ...") stay prose. */
        const char *fn = p->tasks[t].functions;
        bool code = strspn(fn, "abcdefghijklmnopqrstuvwxyz0123456789_, ") == strlen(fn) && !strstr(fn, " and ");
        ok = put(out, size, &len, "| %s | ", p->tasks[t].task);
        for (const char *w = fn; ok && code && *w;) {
            size_t n = strcspn(w, ", ");
            ok = put(out, size, &len, "%s`%.*s`", w == fn ? "" : ", ", (int)n, w);
            w += n;
            w += strspn(w, ", ");
        }
        ok = ok && (code || put(out, size, &len, "%s", fn)) &&
             put(out, size, &len, " | %d | %g |\n", p->tasks[t].tests, p->tasks[t].points);
    }
    /* Each task's tests by name, as its suite defines them: the handout's prose never lists them all. */
    char (*names)[96] = malloc(GRADE_MAX_TESTS * sizeof *names);
    if (!names) return false;
    int count = suite_tests(p->part, names, GRADE_MAX_TESTS);
    for (int t = 0; ok && t < p->num_tasks; t++) {
        ok = put(out, size, &len, "%s- task %s's tests:", t ? "" : "\n", p->tasks[t].task);
        for (int i = 0, first = 1; ok && i < count; i++)
            if (grade_spec_task_of(p, names[i]) == t) {
                ok = put(out, size, &len, "%s `%s`", first ? "" : ",", names[i] + strlen("test_"));
                first = 0;
            }
        ok = ok && put(out, size, &len, ".\n");
    }
    free(names);
    ok = ok && put(out, size, &len, "\n| case | what it shows | render | points | reference |\n"
                   "| --- | --- | --- | --- | --- |\n");
    for (int i = 0; ok && i < p->num_cases; i++) {
        const grade_case *k = &p->cases[i];
        if (k->hidden) continue;
        ok = put(out, size, &len, "| `%s` | %s | `", k->name, k->shows);
        for (int f = 0; ok && f < k->num_flags; f++) ok = put(out, size, &len, "%s ", k->flags[f]);
        ok = ok && put(out, size, &len, "-r %d %d -s %d` | %g | ![%s](../reference_images/part%d/%s.png) |\n", k->width,
                       k->height, k->samples, k->points, k->name, p->part, k->name);
    }
    return ok;
}

pl_status grade_handout_update(const char *path, const grade_part_spec *p, bool write, pl_diag *diag)
{
    char *text = NULL, table[16384];
    size_t len = 0;
    pl_status st = file_read_all(path, "handout", (size_t)1 << 22, &text, &len, diag);
    if (st != PL_OK) return st;
    char *begin = strstr(text, BEGIN_MARK), *end = begin ? strstr(begin, END_MARK) : NULL;
    if (!end) st = pl_fail(diag, PL_ERR_PARSE, "%s: expected the generated grading table between the lines %.*s and %.*s",
                           path, (int)strlen(BEGIN_MARK) - 1, BEGIN_MARK, (int)strlen(END_MARK) - 1, END_MARK);
    else if (!grade_handout_table(p, table, sizeof table))
        st = pl_fail(diag, PL_ERR_PARSE, "%s: part %d's grading table is over %zu bytes", path, p->part, sizeof table);
    else {
        char *body = begin + strlen(BEGIN_MARK);
        bool same = (size_t)(end - body) == strlen(table) && !memcmp(body, table, strlen(table));
        if (!same && !write)
            st = pl_fail(diag, PL_ERR_PARSE, "%s: its grading table differs from grading/cases.json's part %d: run "
                         "bin/grade --handout write", path, p->part);
        else if (!same) {
            size_t head = (size_t)(body - text), tail = strlen(end), n = head + strlen(table) + tail;
            char *out = malloc(n);
            if (!out) st = pl_fail(diag, PL_ERR_NOMEM, "out of memory");
            else {
                memcpy(out, text, head);
                memcpy(out + head, table, strlen(table));
                memcpy(out + head + strlen(table), end, tail);
                st = file_write_atomic(path, out, n, diag);
                free(out);
            }
        }
    }
    free(text);
    return st;
}
