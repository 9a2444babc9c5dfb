/* Instructor tooling: not part of any assignment.
 * The grade book, OUT/gradebook.csv, in the layout of Canvas's gradebook import: the identity
 * columns Canvas matches students by (Student, ID, SIS User ID, SIS Login ID, Section: the id goes
 * in SIS Login ID, which with Student and Section is what Canvas needs to match a row, the roster's
 * name in Student), a "Points Possible" row under the header, then
 * one column per graded item: the total, each part, each task of each part; and a last column,
 * Notes, that says in words why a row is not a plain score. Gradescope imports no grades for an
 * assignment it did not grade, so Canvas's layout is the one to meet (its import previews each
 * column, and an instructor can leave the task columns out there).
 * A cell is empty where no grade should be imported yet (a duplicate id, a student missing from
 * the roster, a part not graded yet); 0 where the autograder gives 0 (a submission without parts,
 * a zip refused as unsafe or too large, a part whose grading ran out of time). Every cell is
 * quoted, and text a spreadsheet would run as a formula is neutralised (class_text_csv). */
#include "class.h"
#include "class_text.h"
#include "../../framework/file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A refusal for which the autograder gives 0: the submission is there and is the student's. */
static bool zero_refusal(const char *status)
{
    static const char *const zero[] = {"empty", "no_parts", "unsafe_path", "too_large", "bad_zip"};
    for (size_t i = 0; i < sizeof zero / sizeof *zero; i++)
        if (!strcmp(status, zero[i])) return true;
    return false;
}

static void cell(FILE *f, const char *text) { fputc(',', f), class_text_csv(f, text); }

static void number_cell(FILE *f, double x)
{
    char n[32];
    cell(f, class_text_number(x, n, sizeof n));
}

/* The parts graded, as numbers, in order. */
static int graded_parts(const class_run *r, int parts[GRADE_MAX_PART])
{
    int n = 0;
    for (const char *c = r->o->parts; *c; c++)
        if (*c >= '1' && *c <= '9') parts[n++] = *c - '0';
    return n;
}

static void header(FILE *f, const class_run *r, const int *parts, int n)
{
    class_text_csv(f, "Student");
    cell(f, "ID"), cell(f, "SIS User ID"), cell(f, "SIS Login ID"), cell(f, "Section"), cell(f, "pathlab total");
    char name[64];
    for (int i = 0; i < n; i++) snprintf(name, sizeof name, "pathlab part %d", parts[i]), cell(f, name);
    for (int i = 0; i < n; i++)
        for (int t = 0; t < r->num_tasks[parts[i] - 1]; t++)
            snprintf(name, sizeof name, "pathlab task %s", r->tasks[parts[i] - 1][t].task), cell(f, name);
    cell(f, "Notes");
    fputs("\r\n", f);
    /* Canvas's second row: each column's points. */
    double total = 0.0;
    for (int i = 0; i < n; i++) total += r->part_max[parts[i] - 1];
    class_text_csv(f, "Points Possible");
    for (int k = 0; k < 4; k++) cell(f, "");
    number_cell(f, total);
    for (int i = 0; i < n; i++) number_cell(f, r->part_max[parts[i] - 1]);
    for (int i = 0; i < n; i++)
        for (int t = 0; t < r->num_tasks[parts[i] - 1]; t++) number_cell(f, r->tasks[parts[i] - 1][t].points);
    cell(f, "");
    fputs("\r\n", f);
}

/* The unit of part p, or NULL. */
static const class_unit *unit_of(const class_student *s, int p)
{
    for (int u = 0; u < s->num_units; u++)
        if (s->units[u].part == p) return &s->units[u];
    return NULL;
}

/* Task t's score in the unit: its facts when graded, 0 when it timed out, else empty. */
static void task_cell(FILE *f, const class_run *r, const class_student *s, const class_unit *u, int p, int t)
{
    if (u && !strcmp(u->status, "timed_out")) {
        number_cell(f, 0.0);
        return;
    }
    json_t *facts = u ? class_unit_facts(r, s, u) : NULL, *task;
    size_t i;
    bool found = false;
    json_array_foreach(json_object_get(facts, "tasks"), i, task)
    {
        const char *name = json_string_value(json_object_get(task, "task"));
        if (!found && name && !strcmp(name, r->tasks[p - 1][t].task))
            found = true, number_cell(f, json_number_value(json_object_get(task, "score")));
    }
    if (!found) cell(f, "");
    json_decref(facts);
}

/* The Notes cell: the refusal, or each part that is not a plain score. */
static void notes(FILE *f, const class_student *s)
{
    char text[1600] = "";
    size_t n = 0;
    if (strcmp(s->status, "ok")) n += (size_t)snprintf(text, sizeof text, "not graded (%s): %s", s->status, s->why);
    for (int u = 0; u < s->num_units && n < sizeof text; u++) {
        const class_unit *x = &s->units[u];
        if (!strcmp(x->status, "graded")) continue;
        n += (size_t)snprintf(text + n, sizeof text - n, "%spart %d: %s", n ? "; " : "", x->part,
                              x->status[0] ? x->why : "not graded yet");
    }
    if (s->left_out[0] && n < sizeof text) snprintf(text + n, sizeof text - n, "%s%s", n ? "; " : "", s->left_out);
    cell(f, text);
}

static void row(FILE *f, const class_run *r, const class_student *s, const int *parts, int n)
{
    /* Identity: the roster's name (else the id) as Student, the id as SIS Login ID. */
    class_text_csv(f, s->name[0] ? s->name : s->shown);
    cell(f, ""), cell(f, ""), cell(f, s->shown), cell(f, "");
    bool ok = !strcmp(s->status, "ok"), zero = zero_refusal(s->status), whole = ok;
    /* The total only when every part has a score: a part still to grade leaves it empty. */
    double total = 0.0;
    for (int i = 0; i < n; i++) {
        const class_unit *u = unit_of(s, parts[i]);
        whole = whole && u && u->status[0] && strcmp(u->status, "grader_failed");
        total += whole ? u->score : 0.0;
    }
    if (whole || zero) number_cell(f, total);
    else cell(f, "");
    /* Each part, then each task: a number, 0 for the autograder's 0s, or empty. */
    for (int i = 0; i < n; i++) {
        const class_unit *u = ok ? unit_of(s, parts[i]) : NULL;
        if (zero || (u && (!strcmp(u->status, "graded") || !strcmp(u->status, "timed_out")))) number_cell(f, u ? u->score : 0.0);
        else cell(f, "");
    }
    for (int i = 0; i < n; i++)
        for (int t = 0; t < r->num_tasks[parts[i] - 1]; t++)
            if (zero) number_cell(f, 0.0);
            else task_cell(f, r, s, ok ? unit_of(s, parts[i]) : NULL, parts[i], t);
    notes(f, s);
    fputs("\r\n", f);
}

bool class_book_write(const class_run *r)
{
    /* The whole file in memory, then one atomic write: an import never reads half a book. CRLF line
     * ends, as RFC 4180 says and spreadsheets expect. */
    char path[1200], *text = NULL;
    size_t len = 0;
    int parts[GRADE_MAX_PART], n = graded_parts(r, parts);
    FILE *f = open_memstream(&text, &len);
    if (!f) return false;
    header(f, r, parts, n);
    for (int i = 0; i < r->num_students; i++) row(f, r, &r->students[i], parts, n);
    fclose(f);
    snprintf(path, sizeof path, "%s/gradebook.csv", r->o->out);
    pl_diag diag = pl_diag_default();
    bool ok = file_write_atomic(path, text, len, &diag) == PL_OK;
    if (!ok) fprintf(stderr, "grade-class: %s\n", diag.error);
    free(text);
    return ok;
}
