/* Grader machinery: not part of any assignment.
 * The report stage (grade_report.h): the three outputs of one grading run for people and platforms,
 * a terminal table, results.json in Gradescope's format, and a static HTML report with its pictures.
 *
 * The words are grade_words.c's, one sentence per fact, so a student reads the same sentence wherever
 * they look. Every string that reaches a student goes through report_text (valid UTF-8) and, in the
 * HTML, html_escape: messages hold whatever bytes a test or a compiler printed, and neither jansson
 * nor a browser may be handed them raw. */
#include "grade_report.h"
#include "grade_fmt.h"
#include "grade_score.h"
#include "grade_words.h"
#include "../framework/file.h"
#include "../framework/image.h"
#include "../framework/utf8.h"
#include <jansson.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define Z_SCALE 5.0f  /* the z-map saturates at |t| = 5 */

static void md_fence(const char *text, char *fence, size_t size)
{
    size_t longest = 0, run = 0;
    for (const char *s = text; *s; s++) {
        run = *s == '`' ? run + 1 : 0;
        if (run > longest) longest = run;
    }
    size_t n = longest + 1 < 3 ? 3 : longest + 1;
    if (n >= size) n = size - 1;
    memset(fence, '`', n);
    fence[n] = '\0';
}

/* Plain text (a reason: the grader's words, with a file's name or a figure in them) as Markdown:
 * every character that could make markup escaped (grade_md_escape), into out. */
static const char *md(const char *plain, char *out, size_t size)
{
    grade_md_escape(plain, strlen(plain), out, size);
    return out;
}

/* The protections this grading could not give student code ("" when none is missing, and for a
 * student's own tree, which is not confined by design). */
static void unprotected(const grade_result *r, char *out, size_t size)
{
    out[0] = '\0';
    if (r->submission) grade_words_protections_missing(&r->sandbox, out, size);
}

/* A part's unit tests as shown: passed of run (0 of 0 when they were not judged). */
static int tests_passed(const grade_part_result *p)
{
    return p->suite.judged ? p->suite.run - p->suite.failed : 0;
}

/* ---- the terminal table (make grade) ------------------------------------------------------------- */

/* make grade: under the table, what each part lost and why: its failed tasks with their failed
 * tests, and for each failing public case its cause, its hint, the seed its trace commands replay
 * and why, and the pixels to trace. */
static void print_causes(const grade_result *r, FILE *out)
{
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        char zero[1024];
        bool judged = !grade_words_unit_zero(p, zero, sizeof zero);
        for (int t = 0; judged && p->spec && t < p->spec->num_tasks; t++) {
            const grade_task *k = &p->spec->tasks[t];
            if (p->task_score[t] >= k->points) continue;
            fprintf(out, "part %d, task %s (%s): %g / %g points; failed:", p->part, k->task, k->functions, p->task_score[t],
                    k->points);
            int shown = 0;
            for (int j = 0; j < p->suite.num_tests; j++)
                if (!p->suite.tests[j].passed && grade_spec_task_of(p->spec, p->suite.tests[j].name) == t)
                    fprintf(out, "%s %s", shown++ ? "," : "", p->suite.tests[j].name);
            fprintf(out, "%s\n", shown ? "" : " (tests that did not run)");
        }
        if (judged && grade_words_tasks_failed(p) > 1) {
            char cascade[1024];
            grade_words_cascade(p, cascade, sizeof cascade);
            fprintf(out, "part %d: %s\n", p->part, cascade);
        }
        if (!judged) fprintf(out, "part %d, unit tests: 0 points: %s\n", p->part, zero);
        for (int k = 0; k < p->num_cases; k++) {
            const grade_case_result *c = &p->cases[k];
            if (c->pass || c->spec->hidden) continue;
            char cause[2048], trace[1536];
            grade_words_case_cause(c, p->part, p->folder, cause, sizeof cause);
            fprintf(out, "part %d, %s: %s\n", p->part, c->spec->name, cause);
            if (c->ran && c->v.hint[0]) fprintf(out, "part %d, %s: %s\n", p->part, c->spec->name, c->v.hint);
            grade_words_trace(c, trace, sizeof trace);
            if (!trace[0]) continue;
            if (c->rendered_twice)
                fprintf(out, "part %d, %s: rendered twice (the first render, seed %llu, failed, and so did the second: the "
                        "difference is your code's), so its commands replay the second, seed %llu:\n", p->part,
                        c->spec->name, c->first_seed, c->seed);
            else fprintf(out, "part %d, %s: the pixels that differ most:\n", p->part, c->spec->name);
            fprintf(out, "%s", trace);
        }
    }
}

void grade_report_table(const grade_result *r, FILE *out)
{
    double max, total = grade_score_total(r, &max);
    fprintf(out, "%-5s  %-12s  %-24s  %s\n", "part", "unit tests", "image cases", "score");
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        int passed = 0;
        for (int k = 0; k < p->num_cases; k++) passed += p->cases[k].pass;
        char unit[32], zero[8];
        if (grade_words_unit_zero(p, zero, sizeof zero)) snprintf(unit, sizeof unit, "0 (see below)");
        else snprintf(unit, sizeof unit, "%d/%d passed", tests_passed(p), p->suite.run);
        fprintf(out, "%-5d  %-12s  %2d/%-2d matched            %5.1f / %.1f\n", p->part, unit, passed, p->num_cases,
                p->score, p->max_score);
    }
    fprintf(out, "total%52.1f / %.1f   (seed %llu, %.0f s)\n", total, max, (unsigned long long)r->seed,
            grade_words_seconds(r));
    char missing[512];
    unprotected(r, missing, sizeof missing);
    if (missing[0]) fprintf(out, "unavailable protections: %s\n", missing);
    print_causes(r, out);
}

/* ---- one function for every string shown -------------------------------------------------------- */

/* Every string results.json and the HTML report show goes through here: test messages, reasons and
 * paths hold whatever bytes a test or a file held, and jansson refuses a string that is not UTF-8
 * (its entry would vanish from results.json). A valid copy (utf8_sanitize: bad bytes as \xNN, no
 * character cut), malloc'd; NULL when out of memory. */
static char *report_text(const char *s)
{
    size_t size = 4 * strlen(s) + 1;
    char *out = malloc(size);
    return out ? utf8_sanitize(s, out, size) : NULL;
}

/* ---- results.json: Gradescope's format ------------------------------------------------------- */

/* One "tests" entry. A hidden case's entry is "after_published": Gradescope shows it to the student
 * only once the grades are published, so hidden cases stay hidden while the work is open. */
static json_t *test_entry(const char *name, double score, double max, bool passed, const char *output, bool hidden)
{
    char *n = report_text(name), *o = report_text(output);
    json_t *e = n && o ? json_pack("{s:s, s:f, s:f, s:s, s:s, s:s, s:s}", "name", n, "score", score, "max_score", max,
                                   "status", passed ? "passed" : "failed", "output", o, "output_format", "md",
                                   "visibility", hidden ? "after_published" : "visible")
                       : NULL;
    free(n);
    free(o);
    return e;
}

/* Appends an entry; false when it could not be made (never a silently missing test). */
static bool append_entry(json_t *tests, json_t *entry)
{
    return entry && json_array_append_new(tests, entry) == 0;
}

/* A part's unit tests in Markdown: why nothing was earned (with the compiler's last lines, the
 * student's own files only: grade_diag.c), or how many passed, task by task, and the failures. */
static void unit_text(const grade_part_result *p, char *text, size_t size)
{
    char zero[1024], escaped[2100], fence[64];
    if (grade_words_unit_zero(p, zero, sizeof zero)) {
        md_fence(p->build.diagnostics, fence, sizeof fence);
        if (p->build.diagnostics[0])
            snprintf(text, size, "**0 points**: %s. The end of the compiler's output:\n\n%s\n%s\n%s\n",
                     md(zero, escaped, sizeof escaped), fence, p->build.diagnostics, fence);
        else snprintf(text, size, "**0 points**: %s.", md(zero, escaped, sizeof escaped));
        return;
    }
    int len = snprintf(text, size, "%d of %d tests passed.\n\n", tests_passed(p), p->suite.run);
    if (len >= 0 && (size_t)len < size) len += grade_words_tasks(p, text + len, size - (size_t)len);
    if (len >= 0 && (size_t)len + 1 < size) {
        text[len++] = '\n';
        grade_words_failures(p, text + len, size - (size_t)len);
    }
}

/* A case's Markdown: its verdict, then the pixels to trace. */
static void case_markdown(const grade_part_result *p, const grade_case_result *c, char *text, size_t size)
{
    grade_words_case(c, p->part, p->folder, text, size);
    char trace[1536], fence[64];
    grade_words_trace(c, trace, sizeof trace);
    md_fence(trace, fence, sizeof fence);
    size_t len = strlen(text);
    if (trace[0] && len < size)
        snprintf(text + len, size - len, "\n\nThe pixels that differ most, and the command that shows every path of "
                 "each as your render computed it (handout: \"Debugging with a trace\"):\n\n%s\n%s%s\n", fence, trace,
                 fence);
}

/* results.json: every part's unit-test entry and every case's, each always present (an entry that
 * cannot be made fails the whole file rather than vanishing), written atomically (file.h): a
 * platform never reads half a file. */
pl_status grade_report_results_json(const grade_result *r, const char *path, pl_diag *diag)
{
    json_t *tests = json_array();
    double max, total = grade_score_total(r, &max);
    bool complete = tests != NULL;
    char *text = malloc(GRADE_REPORT_TEXT);
    for (int i = 0; text && i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        char name[128];
        snprintf(name, sizeof name, "Part %d: unit tests", p->part);
        unit_text(p, text, GRADE_REPORT_TEXT);
        bool all = p->build.built && p->suite.judged && p->suite.failed == 0;
        complete = complete && append_entry(tests, test_entry(name, p->unit_score, p->unit_max, all, text, false));
        for (int k = 0; k < p->num_cases; k++) {
            const grade_case_result *c = &p->cases[k];
            snprintf(name, sizeof name, "Part %d: image %s%s", p->part, c->spec->name, c->spec->hidden ? " (hidden)" : "");
            case_markdown(p, c, text, GRADE_REPORT_TEXT);
            complete = complete && append_entry(tests, test_entry(name, c->score, c->spec->points, c->pass, text,
                                                                  c->spec->hidden));
        }
    }
    free(text);
    /* The run's line: its seed (to grade again the same way) and any protection it lacked. */
    char summary[1024], missing[512];
    unprotected(r, missing, sizeof missing);
    snprintf(summary, sizeof summary, "pathlab grader, seed %llu.%s%s", (unsigned long long)r->seed,
             missing[0] ? " Unavailable protections: " : "", missing);
    char *shown = report_text(summary);
    json_t *root = complete && text && shown
                       ? json_pack("{s:f, s:f, s:s, s:O}", "score", total, "execution_time", grade_words_seconds(r),
                                   "output", shown, "tests", tests)
                       : NULL;
    char *dumped = root ? json_dumps(root, JSON_INDENT(2)) : NULL;
    free(shown);
    json_decref(root);
    json_decref(tests);
    if (!dumped) return pl_fail(diag, PL_ERR_NOMEM, "%s: an entry could not be written (out of memory)", path);
    pl_status st = file_write_atomic(path, dumped, strlen(dumped), diag);
    free(dumped);
    return st;
}

/* ---- the pictures ---------------------------------------------------------------------------------- */

/* The signed t of every block, blue below the reference, red above, white at 0, at image size. */
static pl_status write_z_map(const verdict *v, int width, int height, const char *path, pl_diag *diag)
{
    uint8_t *px = malloc((size_t)width * height * 3);
    if (!px) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            int bx = (int)((long)x * v->blocks_x / width), by = (int)((long)y * v->blocks_y / height);
            float t = 0.0f;  /* the channel with the largest |t| */
            for (int ch = 0; ch < 3; ch++) {
                float tc = v->t[((long)by * v->blocks_x + bx) * 3 + ch];
                if (fabsf(tc) > fabsf(t)) t = tc;
            }
            float a = fminf(fabsf(t) / Z_SCALE, 1.0f);
            uint8_t fade = (uint8_t)(255.0f * (1.0f - a) + 0.5f);
            uint8_t *p = px + 3 * ((long)y * width + x);
            p[0] = t > 0 ? 255 : fade;
            p[1] = fade;
            p[2] = t < 0 ? 255 : fade;
        }
    pl_status st = image_write_png_rgb8(px, width, height, path, diag);
    free(px);
    return st;
}

/* A public case's three pictures in folder, under the names the plan gave them (c->images): the
 * candidate's render, the reference and the z-map; which of them were written, in shown[]. A hidden
 * case's render is never shown. */
static void write_pictures(const grade_case_result *c, const char *folder, bool shown[3])
{
    for (int i = 0; i < 3; i++) {
        shown[i] = false;
        char path[GRADE_PATH];
        if (!c->ran || c->spec->hidden || !c->images[i][0] || !c->candidate.pixels ||
            !grade_join(folder, c->images[i], path, sizeof path))
            continue;
        pl_diag diag = pl_diag_default();
        pl_status st = i == 0 ? image_write_png(&c->candidate, path, &diag)
                     : i == 1 ? (c->reference.pixels ? image_write_png(&c->reference, path, &diag) : PL_ERR_IO)
                              : (c->v.t ? write_z_map(&c->v, c->candidate.width, c->candidate.height, path, &diag)
                                        : PL_ERR_IO);
        shown[i] = st == PL_OK;
    }
}

/* ---- the HTML report: one page, a row per case with its three pictures ----------------------- */

/* Escapes text for HTML (valid UTF-8 first: report_text). With markdown (the verdicts' shared text,
 * results.json's): its bold (**...**) becomes <b>, a fence line is dropped (the text shows in <pre>),
 * and a character escaped for Markdown (a backslash before it: grade_md_escape) shows as itself.
 * Plain text (a compiler's lines, a command) is shown exactly as it is. */
static void html_escape(FILE *f, const char *text, bool markdown)
{
    bool bold = false;
    char *valid = report_text(text);
    const char *s = valid ? valid : "(out of memory)";
    for (; *s; s++) {
        if (markdown && s[0] == '*' && s[1] == '*') {
            fputs(bold ? "</b>" : "<b>", f);
            bold = !bold;
            s++;
            continue;
        }
        if (markdown && s[0] == '\\' && s[1] && strchr("\\`*_[]<>&|~!#-+=.)", s[1])) s++;
        if (*s == '<') fputs("&lt;", f);
        else if (*s == '>') fputs("&gt;", f);
        else if (*s == '&') fputs("&amp;", f);
        else if (*s == '"') fputs("&quot;", f);
        else fputc(*s, f);
    }
    if (bold) fputs("</b>", f);
    free(valid);
}

/* Text between an opening and a closing tag: the one way any grader or student text enters the page,
 * plain (html_wrapped) or the verdicts' Markdown (html_markdown). */
static void html_wrapped(FILE *f, const char *open, const char *text, const char *close)
{
    fputs(open, f);
    html_escape(f, text, false);
    fputs(close, f);
}

static void html_markdown(FILE *f, const char *open, const char *text, const char *close)
{
    fputs(open, f);
    html_escape(f, text, true);
    fputs(close, f);
}

/* The page's head, its style sheet and the paragraph on how cases are judged. */
static void html_head(FILE *f, const grade_result *r)
{
    fprintf(f, "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>pathlab grade</title>\n<style>\n"
               "body{font:15px/1.45 system-ui,sans-serif;margin:24px;color:#222;max-width:1200px}\n"
               "table.sum td,table.sum th{padding:4px 12px;border-bottom:1px solid #ddd;text-align:left}\n"
               ".pass{color:#17702b;font-weight:600}.fail{color:#b3261e;font-weight:600}\n"
               ".case{border:1px solid #ddd;border-radius:6px;padding:12px;margin:12px 0}\n"
               ".imgs{display:flex;gap:12px}.imgs figure{margin:0}.imgs img{width:320px;image-rendering:pixelated;"
               "border:1px solid #ccc}\nfigcaption{font-size:13px;color:#555}\n"
               ".scale{display:inline-block;width:160px;height:10px;background:linear-gradient(90deg,#00f,#fff,#f00);"
               "vertical-align:middle}\npre{background:#f6f6f6;padding:8px;white-space:pre-wrap}\n"
               "</style></head><body>\n<h1>pathlab grade</h1>\n");
    fprintf(f, "<p>Seed %llu, %.0f s. Each image case renders a scene with your part and compares it with the "
               "reference, block by block; a case fails only when the difference is too large to be noise (a "
               "correct part's render differs that much about once in a thousand gradings at most, so a case whose "
               "render does is rendered again at another seed, and fails only if that render differs too).</p>\n",
            (unsigned long long)r->seed, grade_words_seconds(r));
    char missing[512];
    unprotected(r, missing, sizeof missing);
    if (missing[0]) html_wrapped(f, "<p class=\"fail\">Unavailable protections: ", missing, "</p>\n");
}

/* The summary table: a row per part, linked to its section. */
static void html_summary(FILE *f, const grade_result *r)
{
    fprintf(f, "<table class=\"sum\"><tr><th>part</th><th>unit tests</th><th>image cases</th><th>score</th></tr>\n");
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        int passed = 0;
        for (int k = 0; k < p->num_cases; k++) passed += p->cases[k].pass;
        fprintf(f, "<tr><td><a href=\"#part%d\">Part %d</a></td><td>%d/%d</td><td>%d/%d</td><td>%.1f / %.1f</td></tr>\n",
                p->part, p->part, tests_passed(p), p->suite.run, passed, p->num_cases, p->score, p->max_score);
    }
    fprintf(f, "</table>\n");
}

/* A part's unit tests: why they earned nothing (with the compiler's last words), or the tasks and
 * the failures. */
static void html_unit_tests(FILE *f, const grade_part_result *p)
{
    char zero[1024];
    if (grade_words_unit_zero(p, zero, sizeof zero)) {
        html_wrapped(f, "<p class=\"fail\">Unit tests: 0 points: ", zero, "</p>\n");
        if (p->build.diagnostics[0])
            html_wrapped(f, "<p>The end of the compiler's output:</p><pre>", p->build.diagnostics, "</pre>\n");
        return;
    }
    fprintf(f, "<p class=\"%s\">Unit tests: %d of %d passed</p>\n", p->suite.failed ? "fail" : "pass", tests_passed(p),
            p->suite.run);
    char *text = malloc(GRADE_REPORT_TEXT);
    if (!text) return;
    if (grade_words_tasks(p, text, GRADE_REPORT_TEXT) > 0) html_markdown(f, "<pre>", text, "</pre>\n");
    grade_words_failures(p, text, GRADE_REPORT_TEXT);
    if (text[0]) html_markdown(f, "<pre>", text, "</pre>\n");
    free(text);
}

/* One image case: its verdict in words, the trace commands, and the three pictures side by side. */
static void html_case(FILE *f, const grade_part_result *p, const grade_case_result *c, const char *folder)
{
    static const char *const captions[3] = {
        "your render", "the reference",
        "difference per block: <span class=\"scale\"></span> darker &harr; brighter (t from -5 to +5)"};
    static const char *const alts[3] = {"your render", "the reference", "difference per block"};
    char text[4096], trace[1536];
    grade_words_case(c, p->part, p->folder, text, sizeof text);
    fprintf(f, "<div class=\"case\"><h3>%s%s: <span class=\"%s\">%s</span></h3>", c->spec->name,
            c->spec->hidden ? " (hidden)" : "", c->pass ? "pass" : "fail", c->pass ? "passes" : "fails");
    html_wrapped(f, "<p><i>", c->spec->shows, "</i></p>");
    html_markdown(f, "<p>", text, "</p>\n");
    grade_words_trace(c, trace, sizeof trace);
    if (trace[0])
        html_wrapped(f, "<p>The pixels that differ most, and the command that shows every path of each as your render "
                        "computed it (handout: \"Debugging with a trace\"):</p><pre>", trace, "</pre>\n");
    bool shown[3];
    write_pictures(c, folder, shown);
    if (shown[0] || shown[1] || shown[2]) {
        fprintf(f, "<div class=\"imgs\">");
        for (int m = 0; m < 3; m++)
            if (shown[m])
                fprintf(f, "<figure><img src=\"%s\" alt=\"%s\"><figcaption>%s</figcaption></figure>", c->images[m],
                        alts[m], captions[m]);
        fprintf(f, "</div>\n");
    }
    fprintf(f, "</div>\n");
}

pl_status grade_report_html(const grade_result *r, const char *folder, pl_diag *diag)
{
    char path[GRADE_PATH];
    if (!grade_join(folder, "index.html", path, sizeof path))
        return pl_fail(diag, PL_ERR_IO, "%s: the report's path is too long", folder);
    FILE *f = fopen(path, "w");
    if (!f) return pl_fail(diag, PL_ERR_IO, "%s: cannot write", path);
    html_head(f, r);
    html_summary(f, r);
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        fprintf(f, "<h2 id=\"part%d\">Part %d: %.1f / %.1f</h2>\n", p->part, p->part, p->score, p->max_score);
        html_unit_tests(f, p);
        for (int k = 0; k < p->num_cases; k++) html_case(f, p, &p->cases[k], folder);
    }
    fprintf(f, "</body></html>\n");
    if (fclose(f) != 0) return pl_fail(diag, PL_ERR_IO, "%s: cannot write", path);
    return PL_OK;
}
