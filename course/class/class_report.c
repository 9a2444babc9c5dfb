/* Instructor tooling: not part of any assignment.
 * The class report, OUT/report/index.html: what the class got wrong, for the instructor.
 *   - the submissions: how many graded, refused (each with its line), not graded yet;
 *   - per part: the score distribution, then the share of the class that lost each task, failed
 *     each test and each image case (with the case's causes), and the most frequent first causes;
 *   - every student: their scores, each part linked to their own report, and its first cause.
 * A part's first cause is the first thing that went wrong, in the report's own categories, read
 * from bin/grade's facts.json (never from the words of results.json): the part did not build, its
 * unit tests stopped, the first failed test's name, or the first failed image case's cause
 * ("too dark by 1/pi", "noisier than the course's"); a part whose grading ran out of time is that.
 * Every text is escaped (class_text_html); each figure is also an attribute (data-*) so that a test
 * reads the page's numbers without parsing its words. Nothing in it depends on when or where it
 * was made, so a Slurm run and a local run write the same bytes. */
#include "class.h"
#include "class_text.h"
#include "class_tally.h"
#include "../../framework/file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define REPORT_BINS 11   /* score shares: 0-10%, ..., 90-100%, and full marks alone */

static const char *const report_style =
    "body{font:14px/1.45 system-ui,sans-serif;margin:2em auto;max-width:72em;color:#222;padding:0 1em}"
    "h1{font-size:1.6em}h2{margin-top:2em;border-bottom:2px solid #ccc}h3{margin-top:1.4em}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ddd;padding:.2em .6em;text-align:left;"
    "vertical-align:top}th{background:#f3f3f3}.bar{background:#4a7bd0;height:1em;display:inline-block}"
    ".num{text-align:right;font-variant-numeric:tabular-nums}.bad{color:#b00}.muted{color:#777}"
    ".who a{margin-right:.5em}";

/* ---- what the report reads: each student's facts of one part ------------------------------ */

typedef struct {
    int part;
    json_t **facts;      /* per student: the graded unit's facts, or NULL */
    int graded;          /* students with a score for the part (graded or timed out) */
} part_view;

static const class_unit *unit_of(const class_student *s, int p)
{
    for (int u = 0; u < s->num_units; u++)
        if (s->units[u].part == p) return &s->units[u];
    return NULL;
}

/* Whether the student has a score for part p: graded, or 0 for a grading out of time. */
static bool scored(const class_student *s, int p)
{
    const class_unit *u = unit_of(s, p);
    return !strcmp(s->status, "ok") && u && (!strcmp(u->status, "graded") || !strcmp(u->status, "timed_out"));
}

/* The student's id, linked to their own report of part p when it was graded (a part out of time
 * has no report: the id alone). The path is made of this tool's names only. */
static void link_to(FILE *f, const class_student *s, int p)
{
    const class_unit *u = unit_of(s, p);
    if (u && !strcmp(u->status, "graded")) {
        fprintf(f, "<a href=\"../students/");
        class_text_html(f, s->folder);
        fprintf(f, "/part%d-%s/report/index.html\">", p, u->key);
        class_text_html(f, s->shown);
        fputs("</a>", f);
    }
    else class_text_html(f, s->shown);
}

/* The students of a tally item, each linked to their own report of part p. */
static void who(FILE *f, const class_run *r, const tally_item *it, int p)
{
    fputs("<td class=\"who\">", f);
    for (int i = 0; i < it->count; i++) link_to(f, &r->students[it->students[i]], p), fputc(' ', f);
    fputs("</td>", f);
}

/* ---- first causes ------------------------------------------------------------------------------ */

/* The first failed image case's cause words, or NULL. */
static const char *first_case_cause(json_t *facts)
{
    json_t *c;
    size_t i;
    json_array_foreach(json_object_get(facts, "cases"), i, c)
    {
        const char *words = json_string_value(json_object_get(c, "cause_words"));
        if (!json_is_true(json_object_get(c, "passed")) && words) return words;
    }
    return NULL;
}

/* The first cause of a part that lost points, in the report's categories; "" when none was lost. */
static void first_cause(const class_unit *u, json_t *facts, char *out, size_t size)
{
    const char *unit = json_string_value(json_object_get(facts, "unit_cause"));
    const char *test = json_string_value(json_object_get(facts, "first_failed_test"));
    const char *image = first_case_cause(facts);
    bool lost = json_number_value(json_object_get(facts, "score")) < json_number_value(json_object_get(facts, "max_score"));
    out[0] = '\0';
    if (!strcmp(u->status, "timed_out")) snprintf(out, size, "its grading ran out of time");
    else if (!facts || !lost) return;
    else if (unit && !strcmp(unit, "not_built")) snprintf(out, size, "the part did not build");
    else if (unit && !strcmp(unit, "suite_stopped")) snprintf(out, size, "its unit tests stopped early");
    else if (test) snprintf(out, size, "%s", test);  /* a test's name: test_<function>__<what it checks> */
    else if (image) snprintf(out, size, "%s", image);
    else snprintf(out, size, "points lost (no failed test or case named)");
}

/* ---- one part ------------------------------------------------------------------------------------ */

/* The part's scores in REPORT_BINS bins of its maximum, with the mean, full marks and zeros. */
static void distribution(FILE *f, const class_run *r, const part_view *v)
{
    /* Each score as a share of its maximum (a part out of time: 0 of the part's points). */
    int bins[REPORT_BINS] = {0}, full = 0, zero = 0;
    double sum = 0.0, max = r->part_max[v->part - 1];
    for (int i = 0; i < r->num_students; i++) {
        const class_unit *u = unit_of(&r->students[i], v->part);
        if (!scored(&r->students[i], v->part)) continue;
        double share = u->max_score > 0 ? u->score / u->max_score : 0.0;
        int b = share >= 1.0 ? REPORT_BINS - 1 : (int)(share * 10.0);
        bins[b < 0 ? 0 : b]++;
        full += share >= 1.0, zero += u->score <= 0.0, sum += u->score;
    }
    /* The counts in words and as attributes, then one bar a bin, 300 pixels for the whole class. */
    char n1[32], n2[32];
    fprintf(f, "<p data-part=\"%d\" data-graded=\"%d\" data-full=\"%d\" data-zero=\"%d\">%d graded; mean %s of %s; "
               "full marks %d, zero %d.</p>\n<table class=\"dist\"><tr><th>score</th><th>students</th><th></th></tr>\n",
            v->part, v->graded, full, zero, v->graded, class_text_number(v->graded ? sum / v->graded : 0.0, n1, sizeof n1),
            class_text_number(max, n2, sizeof n2), full, zero);
    for (int b = 0; b < REPORT_BINS; b++) {
        char label[32];
        if (b == REPORT_BINS - 1) snprintf(label, sizeof label, "full marks");
        else snprintf(label, sizeof label, "%d-%d%%", 10 * b, 10 * b + 10);
        fprintf(f, "<tr data-bin=\"%d\" data-count=\"%d\"><td>%s</td><td class=\"num\">%d</td><td><span class=\"bar\" "
                   "style=\"width:%dpx\"></span></td></tr>\n", b, bins[b], label, bins[b], v->graded ? 300 * bins[b] / v->graded : 0);
    }
    fputs("</table>\n", f);
}

/* A share as "2 of 6 (33%)", with its figures as attributes. */
static void share_cells(FILE *f, int count, int of)
{
    fprintf(f, "<td class=\"num\" data-count=\"%d\" data-of=\"%d\">%d of %d (%d%%)</td>", count, of, count, of,
            of ? (100 * count + of / 2) / of : 0);
}

/* Every task of the part (cases.json's), with how many lost it: a task's share is earned whole
 * or not at all, so "lost" is any score below its points. */
static void tasks(FILE *f, const class_run *r, const part_view *v)
{
    fputs("<h3>Tasks</h3>\n<table><tr><th>task</th><th>writes</th><th>points</th><th>lost by</th><th>students</th></tr>\n", f);
    for (int t = 0; t < r->num_tasks[v->part - 1]; t++) {
        /* Lost: a task scored below its points (facts.json's task score), or a grading out of time. */
        const grade_task *k = &r->tasks[v->part - 1][t];
        tally lost = {0};
        tally_add(&lost, k->task, -1);  /* the row is there even when no one lost it */
        for (int i = 0; i < r->num_students; i++) {
            json_t *task;
            size_t j;
            const class_unit *u = unit_of(&r->students[i], v->part);
            if (scored(&r->students[i], v->part) && !strcmp(u->status, "timed_out")) tally_add(&lost, k->task, i);
            json_array_foreach(json_object_get(v->facts[i], "tasks"), j, task)
            {
                const char *name = json_string_value(json_object_get(task, "task"));
                if (name && !strcmp(name, k->task) && json_number_value(json_object_get(task, "score")) < k->points)
                    tally_add(&lost, k->task, i);
            }
        }
        /* The row: the task, what it writes, its points, who lost it. */
        char pts[32];
        fprintf(f, "<tr data-task=\"");
        class_text_html(f, k->task);
        fputs("\"><td>", f), class_text_html(f, k->task), fputs("</td><td>", f), class_text_html(f, k->functions);
        fprintf(f, "</td><td class=\"num\">%s</td>", class_text_number(k->points, pts, sizeof pts));
        share_cells(f, lost.items[0].count, v->graded);
        who(f, r, &lost.items[0], v->part);
        fputs("</tr>\n", f);
        tally_free(&lost);
    }
    fputs("</table>\n", f);
}

/* A tally's rows: label, share of the graded, students; an empty table says so. */
static void tally_rows(FILE *f, const class_run *r, const part_view *v, tally *t, const char *kind)
{
    tally_sort(t);
    if (!t->num) fprintf(f, "<tr><td colspan=\"3\" class=\"muted\">no %s</td></tr>\n", kind);
    for (int i = 0; i < t->num; i++) {
        fputs("<tr data-label=\"", f), class_text_html(f, t->items[i].label), fputs("\"><td>", f);
        class_text_html(f, t->items[i].label);
        fputs("</td>", f);
        share_cells(f, t->items[i].count, v->graded);
        who(f, r, &t->items[i], v->part);
        fputs("</tr>\n", f);
    }
    fputs("</table>\n", f);
}

/* Every failed test, by how many students failed it. */
static void tests(FILE *f, const class_run *r, const part_view *v)
{
    tally failed = {0};
    for (int i = 0; i < r->num_students; i++) {
        json_t *test;
        size_t j;
        json_array_foreach(json_object_get(v->facts[i], "tests"), j, test)
        {
            const char *name = json_string_value(json_object_get(test, "name"));
            if (name && !json_is_true(json_object_get(test, "passed"))) tally_add(&failed, name, i);
        }
    }
    fputs("<h3>Unit tests failed</h3>\n<table class=\"tests\"><tr><th>test</th><th>failed by</th><th>students</th></tr>\n", f);
    tally_rows(f, r, v, &failed, "test failed");
    tally_free(&failed);
}

/* Every image case: how many failed it, and why (its causes, most frequent first). */
static void cases(FILE *f, const class_run *r, const part_view *v)
{
    tally failed = {0}, causes = {0};
    for (int i = 0; i < r->num_students; i++) {
        json_t *c;
        size_t j;
        json_array_foreach(json_object_get(v->facts[i], "cases"), j, c)
        {
            const char *name = json_string_value(json_object_get(c, "name"));
            const char *words = json_string_value(json_object_get(c, "cause_words"));
            char label[200];
            if (!name) continue;
            /* Every case gets a row (a case no one failed shows 0); a hidden one says so: staff only. */
            snprintf(label, sizeof label, "%s%s", name, json_is_true(json_object_get(c, "hidden")) ? " (hidden)" : "");
            tally_add(&failed, label, json_is_true(json_object_get(c, "passed")) ? -1 : i);
            snprintf(label, sizeof label, "%s: %s", name, words ? words : "");
            if (!json_is_true(json_object_get(c, "passed"))) tally_add(&causes, label, i);
        }
    }
    fputs("<h3>Image cases</h3>\n<table class=\"cases\"><tr><th>case</th><th>failed by</th><th>students</th></tr>\n", f);
    tally_rows(f, r, v, &failed, "image case");
    fputs("<h3>Why image cases failed</h3>\n<table class=\"case-causes\"><tr><th>case: cause</th><th>failed by</th>"
          "<th>students</th></tr>\n", f);
    tally_rows(f, r, v, &causes, "failed case");
    tally_free(&failed), tally_free(&causes);
}

/* Each scored student's first cause of the part, into t (most frequent first). */
static void count_firsts(const class_run *r, const part_view *v, tally *t)
{
    for (int i = 0; i < r->num_students; i++) {
        char cause[200];
        if (!scored(&r->students[i], v->part)) continue;
        first_cause(unit_of(&r->students[i], v->part), v->facts[i], cause, sizeof cause);
        if (cause[0]) tally_add(t, cause, i);
    }
    tally_sort(t);
}

/* The part's first causes: what to teach again, most frequent first. */
static void first_causes(FILE *f, const class_run *r, const part_view *v)
{
    tally firsts = {0};
    count_firsts(r, v, &firsts);
    fputs("<h3>First causes, most frequent first</h3>\n<table class=\"firsts\"><tr><th>first cause</th><th>students</th>"
          "<th></th></tr>\n", f);
    tally_rows(f, r, v, &firsts, "points lost");
    tally_free(&firsts);
}

/* Each student's facts of part p, read once for every table; false when out of memory. */
static bool view_load(const class_run *r, int p, part_view *v)
{
    *v = (part_view){.part = p, .facts = calloc((size_t)r->num_students, sizeof *v->facts)};
    for (int i = 0; v->facts && i < r->num_students; i++) {
        const class_unit *u = unit_of(&r->students[i], p);
        v->graded += scored(&r->students[i], p);
        if (scored(&r->students[i], p)) v->facts[i] = class_unit_facts(r, &r->students[i], u);
    }
    return v->facts != NULL;
}

static void view_free(const class_run *r, part_view *v)
{
    for (int i = 0; v->facts && i < r->num_students; i++) json_decref(v->facts[i]);
    free(v->facts);
}

static void part_section(FILE *f, const class_run *r, int p)
{
    part_view v;
    if (!view_load(r, p, &v)) return;
    fprintf(f, "<section id=\"part%d\" data-part=\"%d\"><h2>Part %d</h2>\n", p, p, p);
    distribution(f, r, &v);
    tasks(f, r, &v);
    tests(f, r, &v);
    cases(f, r, &v);
    first_causes(f, r, &v);
    fputs("</section>\n", f);
    view_free(r, &v);
}

/* The page's first table: per part, how many lost points and the three most frequent first causes,
 * each linking to the part's section. */
static void overview(FILE *f, const class_run *r, const int *parts, int n)
{
    fputs("<table class=\"overview\"><tr><th>part</th><th>lost points</th><th>most frequent first causes</th></tr>\n", f);
    for (int k = 0; k < n; k++) {
        part_view v;
        tally firsts = {0};
        if (!view_load(r, parts[k], &v)) continue;
        count_firsts(r, &v, &firsts);
        int lost = 0;
        for (int i = 0; i < firsts.num; i++) lost += firsts.items[i].count;
        fprintf(f, "<tr data-part=\"%d\"><td><a href=\"#part%d\">part %d</a></td>", parts[k], parts[k], parts[k]);
        share_cells(f, lost, v.graded);
        fputs("<td>", f);
        for (int i = 0; i < firsts.num && i < 3; i++) {
            fputs(i ? "; " : "", f), class_text_html(f, firsts.items[i].label);
            fprintf(f, " (%d)", firsts.items[i].count);
        }
        fputs("</td></tr>\n", f);
        tally_free(&firsts);
        view_free(r, &v);
    }
    fputs("</table>\n", f);
}

/* ---- the class -------------------------------------------------------------------------------- */

/* Counts of students graded whole, refused, and not graded yet (some part missing). */
static void summary(FILE *f, const class_run *r)
{
    /* Graded: every part there (class_record_complete); waiting: a part still to grade. */
    int whole = 0, refused = 0, waiting = 0;
    for (int i = 0; i < r->num_students; i++) {
        const class_student *s = &r->students[i];
        if (strcmp(s->status, "ok")) refused++;
        else if (class_record_complete(s)) whole++;
        else waiting++;
    }
    fprintf(f, "<p id=\"summary\" data-students=\"%d\" data-graded=\"%d\" data-refused=\"%d\" data-waiting=\"%d\">"
               "%d submissions: %d graded, %d not graded (below, each with why), %d not graded yet (run the class "
               "grader again). Parts graded: %s.</p>\n", r->num_students, whole, refused, waiting, r->num_students, whole,
            refused, waiting, r->o->parts);
    if (r->ignored[0]) fputs("<p class=\"muted\">Ignored (neither a folder nor a .zip): ", f), class_text_html(f, r->ignored), fputs("</p>\n", f);
}

/* One line per submission not graded: its name and id as shown, and why, in this tool's words. */
static void refused(FILE *f, const class_run *r)
{
    fputs("<h2 id=\"refused\">Submissions not graded</h2>\n<table class=\"refused\"><tr><th>submission</th><th>id</th>"
          "<th>why</th></tr>\n", f);
    int n = 0;
    for (int i = 0; i < r->num_students; i++) {
        const class_student *s = &r->students[i];
        if (!strcmp(s->status, "ok")) continue;
        n++;
        fputs("<tr data-status=\"", f), class_text_html(f, s->status), fputs("\" data-id=\"", f), class_text_html(f, s->shown);
        fputs("\"><td>", f), class_text_html(f, s->entry_shown), fputs("</td><td>", f), class_text_html(f, s->shown);
        fputs("</td><td>", f), class_text_html(f, s->why), fputs("</td></tr>\n", f);
    }
    if (!n) fputs("<tr><td colspan=\"3\" class=\"muted\">none: every submission was graded</td></tr>\n", f);
    fputs("</table>\n", f);
}

/* One student's row: id, name, total, and per part its score linked to the report, and why. */
static void student_row(FILE *f, const class_run *r, const class_student *s, const int *parts, int n)
{
    fputs("<tr data-id=\"", f), class_text_html(f, s->shown), fputs("\" data-status=\"", f), class_text_html(f, s->status);
    fputs("\"><td>", f), class_text_html(f, s->shown), fputs("</td><td>", f), class_text_html(f, s->name), fputs("</td>", f);
    for (int i = 0; i < n; i++) {
        /* A part without a score says why in a word; the refusal itself is in the table above. */
        const class_unit *u = unit_of(s, parts[i]);
        char score[32], max[32], cause[200] = "";
        if (!scored(s, parts[i])) {
            fprintf(f, "<td data-part=\"%d\" class=\"muted\">%s</td>", parts[i],
                    strcmp(s->status, "ok") ? "not graded" : u && u->status[0] ? "grader failed" : "not graded yet");
            continue;
        }
        json_t *facts = class_unit_facts(r, s, u);
        first_cause(u, facts, cause, sizeof cause);
        json_decref(facts);
        fprintf(f, "<td data-part=\"%d\" data-score=\"%s\" data-max=\"%s\">", parts[i],
                class_text_number(u->score, score, sizeof score), class_text_number(u->max_score, max, sizeof max));
        link_to(f, s, parts[i]);
        fprintf(f, ": %s / %s", score, max);
        if (cause[0]) fputs(" <span class=\"bad\">", f), class_text_html(f, cause), fputs("</span>", f);
        fputs("</td>", f);
    }
    fputs("</tr>\n", f);
}

/* Every student in the folder's order, refused ones included (their parts say "not graded"). */
static void students(FILE *f, const class_run *r, const int *parts, int n)
{
    fputs("<h2 id=\"students\">Students</h2>\n<table class=\"students\"><tr><th>id</th><th>name</th>", f);
    for (int i = 0; i < n; i++) fprintf(f, "<th>part %d: report, score, first cause</th>", parts[i]);
    fputs("</tr>\n", f);
    for (int i = 0; i < r->num_students; i++) student_row(f, r, &r->students[i], parts, n);
    fputs("</table>\n", f);
}

bool class_report_write(const class_run *r)
{
    /* The graded parts in order, from --parts ("1,3"). */
    int parts[GRADE_MAX_PART], n = 0;
    for (const char *c = r->o->parts; *c; c++)
        if (*c >= '1' && *c <= '9') parts[n++] = *c - '0';
    /* The page in memory, then one atomic write: a reader never sees half a report. */
    char *text = NULL, path[1300];
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) return false;
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>pathlab: class report</title>"
               "<style>%s</style></head><body>\n<h1>Class report</h1>\n", report_style);
    summary(f, r);
    overview(f, r, parts, n);
    refused(f, r);
    for (int i = 0; i < n; i++) part_section(f, r, parts[i]);
    students(f, r, parts, n);
    fputs("</body></html>\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/report", r->o->out);
    mkdir(path, 0755);
    strcat(path, "/index.html");
    pl_diag diag = pl_diag_default();
    bool ok = file_write_atomic(path, text, len, &diag) == PL_OK;
    if (!ok) fprintf(stderr, "grade-class: %s\n", diag.error);
    free(text);
    return ok;
}
