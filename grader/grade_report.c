/* Grader machinery: not part of any assignment. The three outputs of one grading run: a terminal
 * table, results.json in Gradescope's format, and a static HTML report.
 *
 * One text per verdict: case_text words a case's verdict once (Markdown), and results.json and the
 * report both show it, so a student reads the same sentence wherever they look. Every string that
 * reaches a student goes through report_text (valid UTF-8) and, in the HTML, html_escape: messages
 * hold whatever bytes a test or a compiler printed, and neither jansson nor a browser may be handed
 * them raw. And every number a render decides (ratios, p-values, counts, pixels) goes through
 * grade_figure (grade_figure.h) before it is formatted; a hidden case shows its verdict and a coarse
 * mean ratio alone (hidden_case_text). */
#include "grade.h"
#include "grade_figure.h"
#include "../framework/file.h"
#include "../framework/utf8.h"
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Channels by index, in the verdict's messages. */
static const char *const channel_names[3] = {"red", "green", "blue"};

/* ---- the figures shown: every number a render decides goes through grade_figure ---------------- */

/* A public case's figure (grade_figure.h: rounded to 3 significant digits, clamped to [lo, hi]). */
static double public_figure(double x, double lo, double hi)
{
    return grade_figure(x, GRADE_FIGURE_DIGITS, lo, hi);
}

static double shown_ratio(double ratio)
{
    return public_figure(ratio, 0.0, GRADE_RATIO_MAX);
}

static long case_pixels(const grade_case *k)
{
    return (long)k->width * k->height;
}

/* The run's time as shown: a render that sleeps chooses it to the millisecond, so it is a figure
 * too (3 significant digits, printed in whole seconds: about 10 bits a run instead of 17 a case). */
static double run_seconds(const grade_result *r)
{
    return public_figure(r->seconds, 0.0, GRADE_SECONDS_MAX);
}

/* Plain text (a reason: the grader's words, with a file's name or a figure in them) as Markdown: every
 * character that could make markup escaped (grade_md_escape). Into a static buffer: one at a time. */
static const char *md(const char *plain)
{
    static char out[2 * 1024 + 1];
    grade_md_escape(plain, strlen(plain), out, sizeof out);
    return out;
}

/* A fence for a block of text holding anything: one backtick longer than the longest run of
 * backticks in it (at least three), so nothing in the block can close it (CommonMark 4.5). */
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

/* A deterministic case's verdict: how many pixels are beyond the rounding tolerance, against the
 * ties allowed, and the largest difference. A pass within the tolerance is never called a failure. */
static int rounding_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    int len = snprintf(out, size, "%s: %ld pixels differ by more than the rounding tolerance %.1e (at most %ld may: "
                       "rays that graze an edge go either way); the largest difference is %.3g",
                       v->pass ? "**matches the reference** up to rounding" : "**differs from the reference**",
                       grade_figure_count(v->beyond_tolerance, case_pixels(k)), v->tolerance, v->tie_pixels,
                       public_figure(v->max_diff, 0.0, GRADE_RATIO_MAX));
    if (len >= 0 && (size_t)len < size && v->max_x >= 0)
        len += snprintf(out + len, size - len, ", in the %s channel at x=%d y=%d (from the bottom-left)",
                        channel_names[v->max_channel % 3], grade_figure_pixel(v->max_x, k->width),
                        grade_figure_pixel(v->max_y, k->height));
    if (len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, ". relMSE %.3g, mean ratio red %.3g green %.3g blue %.3g.",
                        public_figure(v->rel_mse, 0.0, GRADE_REL_MSE_MAX), shown_ratio(v->ratio[0]), shown_ratio(v->ratio[1]),
                        shown_ratio(v->ratio[2]));
    return len;
}

/* Whether case k's flags hold flag. */
static bool case_has_flag(const grade_case *k, const char *flag)
{
    for (int i = 0; i < k->num_flags; i++)
        if (!strcmp(k->flags[i], flag)) return true;
    return false;
}

/* An adaptive case's figures: its mean samples per pixel, and where it spends them (the map). */
static int adaptive_text(const grade_case_result *c, char *out, size_t size)
{
    bool ok = grade_case_spp_ok(c);
    int len = snprintf(out, size, " Samples per pixel: %.3g on average, the course's %.3g (%s %.0f%%).",
                       public_figure(c->spp, 0.0, GRADE_SPP_MAX), public_figure(c->course_spp, 0.0, GRADE_SPP_MAX),
                       ok ? "within" : "more than", 100.0 * GRADE_SPP_TOLERANCE);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " %s", c->spp > c->course_spp
                        ? "Pixels stop later than the course's: adaptive_converged says yes too late (is I = 1.96 "
                          "sqrt(var / n) the mean's error, with var / n and not var alone?)."
                        : "Pixels stop earlier than the course's: adaptive_converged says yes too early (check I = "
                          "1.96 sqrt(var / n) <= maxTolerance x mean, on the samples' luminance).");
    if (c->rate_distance < 0 || len < 0 || (size_t)len >= size) return len;
    ok = grade_case_rate_ok(c);
    len += snprintf(out + len, size - len, " Where the samples go (the sample-rate map, block by block): yours misses "
                    "%.2g%% of the course's variation from block to block (at most %.0f%%).",
                    public_figure(100.0 * c->rate_distance, 0.0, 1e6), 100.0 * GRADE_RATE_TOLERANCE);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " The course's render spends many samples where the image is noisy and "
                        "few where it is smooth; yours does not: does each pixel stop by its own confidence interval "
                        "(task 5.1), rather than after a number of samples?");
    return len;
}

/* A work_check case's figure: the render's CPU time against the baseline's (grade_image.c). */
static int work_text(const grade_case_result *c, char *out, size_t size)
{
    bool ok = grade_case_work_ok(c);
    int len = c->base_is_scan
        ? snprintf(out, size, " CPU time: %.3gx faster than the framework's linear scan on this case (at least %.0fx).",
                   public_figure(c->cpu > 0 ? c->base_cpu / c->cpu : 0.0, 0.0, GRADE_RATIO_MAX), GRADE_SCAN_FACTOR)
        : snprintf(out, size, " CPU time: %.3gx the course's BVH on this case (at most %.0fx).",
                   public_figure(c->base_cpu > 0 ? c->cpu / c->base_cpu : 0.0, 0.0, GRADE_RATIO_MAX), GRADE_WORK_FACTOR);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " The image is right, but the tree does not save work: check the SAH split, "
                        "the leaf size, the nearest-first traversal, skipping boxes entered beyond the nearest hit, and "
                        "stopping a shadow ray at its first hit (tasks 2.2 to 2.4).");
    return len;
}

/* The figures of a public case's own render beside its image (samples per pixel and where they go,
 * noise, CPU time), where the case judges them. A hidden case shows none: its verdict alone. */
static int figures_text(const grade_case_result *c, char *out, size_t size)
{
    int len = 0;
    if (c->course_spp > 0) len += adaptive_text(c, out, size);
    if (c->spec->noise_check && len >= 0 && (size_t)len < size) {
        bool ok = c->noise <= GRADE_NOISE_FACTOR;
        len += snprintf(out + len, size - len, " Noise per sample: %.3g x the course's (%s %.2fx).",
                        shown_ratio(c->noise), ok ? "within" : "more than", GRADE_NOISE_FACTOR);
        /* A cause only when the mean passed: an image whose mean is off is that first (where_text),
         * and its noise follows. A case that prescribes --no-rr says so, since then no roulette rule
         * (the handout allows several) can be the cause. */
        if (!ok && c->ran && c->v.pass && (size_t)len < size)
            len += snprintf(out + len, size - len, " The image is right on average but noisier than it should be%s: "
                            "does every one of the -l light samples draw its own random numbers, and are they spent "
                            "where the handout says?",
                            case_has_flag(c->spec, "--no-rr") ? " (the case renders with --no-rr, so roulette is not "
                            "the cause)" : "");
    }
    if (c->spec->work_check && c->ran && len >= 0 && (size_t)len < size) len += work_text(c, out + len, size - len);
    return len;
}

/* The mean of the lit channels' ratios (NaN when none is lit): a hidden case's one figure. */
static double mean_ratio(const verdict *v)
{
    double sum = 0.0;
    int lit = 0;
    for (int ch = 0; ch < 3; ch++)
        if (!isnan(v->ratio[ch])) sum += v->ratio[ch], lit++;
    return lit ? sum / lit : NAN;
}

/* The region a failed verdict differs in: its blocks' extent as pixels, and their brightness. */
static int region_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    /* Blocks to pixels from the bottom-left, as the renderer and --trace-pixel count them. */
    int x0 = v->region_x0 * k->width / v->blocks_x, x1 = (v->region_x1 + 1) * k->width / v->blocks_x - 1;
    int y1 = k->height - 1 - v->region_y0 * k->height / v->blocks_y;
    int y0 = k->height - (v->region_y1 + 1) * k->height / v->blocks_y;
    bool whole = v->region_blocks == v->blocks_x * v->blocks_y;
    return snprintf(out, size, " The image differs %s: %d of its %d blocks, within x = %d..%d and y = %d..%d (from the "
                    "bottom-left), are %.3g times the reference's brightness together%s.",
                    whole ? "everywhere, but not by one factor" : "in a region", v->region_blocks, v->blocks_x * v->blocks_y,
                    grade_figure_pixel(x0, k->width), grade_figure_pixel(x1, k->width), grade_figure_pixel(y0, k->height),
                    grade_figure_pixel(y1, k->height), public_figure(v->region_ratio, 0.0, GRADE_RATIO_MAX),
                    whole ? "" : "; the rest matches: look at what that region shows (one object, one light, one material?)");
}

/* Where a statistical verdict failed: the first bad pixel, or the block (or the whole image) that
 * differs most, and the hint. */
static int where_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    int len = 0;
    if (v->bad_pixels)
        len = snprintf(out, size, " %ld pixels are NaN, infinite or negative; the first at x=%d y=%d (from the "
                       "bottom-left).", grade_figure_count(v->bad_pixels, case_pixels(k)),
                       grade_figure_pixel(v->bad_x, k->width), grade_figure_pixel(v->bad_y, k->height));
    /* In order of likelihood: bad pixels; then one factor everywhere (a mean off by more than 5%, far
     * beyond a case's noise, with the differing blocks agreeing on it); then a region (the blocks
     * that differ, named with their ratio); then the one block, or channel, that differs most. */
    else if (!v->pass && !v->deterministic && v->uniform_factor && fabs(mean_ratio(v) - 1.0) > 0.05)
        len = snprintf(out, size, " The whole image is %s: %.3g times the reference's brightness on average, and its "
                       "blocks agree, so look for a factor that applies everywhere before a place.",
                       mean_ratio(v) > 1.0 ? "too bright" : "too dark", public_figure(mean_ratio(v), 0.0, GRADE_RATIO_MAX));
    else if (!v->pass && !v->deterministic && v->region_blocks > 0)
        len = region_text(k, v, out, size);
    else if (!v->pass && !v->deterministic && v->worst_block_x >= 0)  /* rounding_text says where */    /* The hint's factor is measured where it is telling (verdict.c: pixels that see no light directly),
     * so it may differ from the whole image's ratio above: said so, or the two read as a contradiction. */
    if (!v->pass && v->hint[0] && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " Hint%s: %s.",
                        strncmp(v->hint, "about ", 6) ? "" : ", from the pixels that do not see a light directly", v->hint);
    return len;
}


/* A hidden case: its scene is the course's secret, and its render may have read it, so the student
 * sees its verdict alone, passed or failed: no figure, no pixel or block, no trace command, nothing
 * of what its render made (grading/README.md, "What reaches the student"). */
static void hidden_case_text(const grade_case_result *c, char *out, size_t size)
{
    if (!c->ran) {
        snprintf(out, size, "**did not run**: %s", md(c->reason));
        return;
    }
    snprintf(out, size, "%s (a hidden case: its verdict alone is shown).%s",
             c->pass ? "**passes**" : "**fails**",
             c->rendered_twice ? " It was rendered twice: a correct render fails a case by chance about once in a "
                                 "thousand gradings at most, so a first failure is rendered again, and only the second "
                                 "render is judged." : "");
}

/* One case's verdict in words (Markdown): the same text in results.json and the HTML report. */
static void case_text(const grade_case_result *c, char *out, size_t size)
{
    const grade_case *k = c->spec;
    const verdict *v = &c->v;
    if (k->hidden) {
        hidden_case_text(c, out, size);
        return;
    }
    /* Rendered twice (grade_image.h): say so first; what follows judges the second render. */
    int len = 0;
    if (c->rendered_twice)
        len = snprintf(out, size, "Rendered twice: the first render (seed %llu) differed from the reference (p-value "
                       "%.3g). A correct render fails a case by chance about once in a thousand gradings at most, so "
                       "the case was rendered again at seed %llu. %s ", c->first_seed, public_figure(c->first_p, 0.0, 1.0), c->seed,
                       c->pass ? "That render is judged here, and the first failure was chance, not your code:"
                       : c->ran ? "That render differs too, so the difference is your code's, not chance:"
                                : "That render");
    if (len < 0 || (size_t)len >= size) return;
    out += len, size -= (size_t)len;
    if (!c->ran) {
        snprintf(out, size, "**did not run**: %s", md(c->reason));
        return;
    }
    len = v->deterministic ? rounding_text(k, v, out, size)
                           : snprintf(out, size, "%s. p-value %.3g (the case fails below %.0e), relMSE %.3g, "
                                      "mean ratio red %.3g green %.3g blue %.3g.",
                                      v->pass ? "**matches the reference**" : "**differs from the reference**",
                                      public_figure(v->p_value, 0.0, 1.0), v->alpha, public_figure(v->rel_mse, 0.0, GRADE_REL_MSE_MAX),
                                      shown_ratio(v->ratio[0]), shown_ratio(v->ratio[1]), shown_ratio(v->ratio[2]));
    if (len >= 0 && (size_t)len < size) len += where_text(k, v, out + len, size - len);
    if (len >= 0 && (size_t)len < size) figures_text(c, out + len, size - len);
}

/* A failing case's pixels and the commands that trace them (grade_image.c), after its text. */
static void append_trace(const grade_case_result *c, char *text, size_t size)
{
    size_t len = strlen(text);
    if (c->trace[0] && len < size)
        snprintf(text + len, size - len, "\n\nThe pixels that differ most, and the command that shows every path of "
                 "each as your render computed it (handout: \"Debugging with a trace\"):\n\n```\n%s```\n", c->trace);
}

/* How many of the part's tasks lost their share. */
static int tasks_failed(const grade_part_result *p)
{
    int n = 0;
    for (int t = 0; p->spec && t < p->spec->num_tasks; t++) n += p->task_score[t] < p->spec->tasks[t].points;
    return n;
}

/* When several tasks failed: one bug can fail another task's tests, since a task's tests call the
 * part's functions of the tasks before it. Said with this part's own: the first failed task, and the
 * functions of the tasks before it that its tests may be failing through. Into a static buffer. */
static const char *cascade_text(const grade_part_result *p)
{
    static char text[640];
    if (tasks_failed(p) <= 1) return "";
    int first = 0;
    while (first < p->spec->num_tasks && p->task_score[first] >= p->spec->tasks[first].points) first++;
    int len = snprintf(text, sizeof text, "Several tasks failed, but one bug can fail the tests of another task as "
                       "well: a task's tests run the part's functions of the tasks before it too");
    for (int t = first + 1, named = 0; t < p->spec->num_tasks && len >= 0 && (size_t)len < sizeof text; t++)
        if (p->task_score[t] < p->spec->tasks[t].points && !named++)
            len += snprintf(text + len, sizeof text - len, " (task %s's tests run your %s, whose task %s failed too)",
                            p->spec->tasks[t].task, p->spec->tasks[first].functions, p->spec->tasks[first].task);
    if (len >= 0 && (size_t)len < sizeof text)
        snprintf(text + len, sizeof text - len, ": fix the first failure the suite names, task %s's, then run it again.",
                 p->spec->tasks[first].task);
    return text;
}

/* A failing public case's cause in one line (the report's words): why it did not run; where its
 * image differs (bad pixels, the whole image's brightness, the block), hint apart; or, for an image
 * that matches, the figure that failed (samples per pixel, noise, work). */
static void case_cause(const grade_case_result *c, char *out, size_t size)
{
    char text[2048] = "";
    if (!c->ran) snprintf(text, sizeof text, "did not run: %s", c->reason);
    else if (!c->v.pass) {
        verdict v = c->v;
        v.hint[0] = '\0';  /* printed on a line of its own */
        where_text(c->spec, &v, text, sizeof text);
        if (!text[0]) snprintf(text, sizeof text, "the image differs from the reference (see the report)");
    }
    else {
        int len = snprintf(text, sizeof text, "the image matches the reference, but a figure of its render does not:");
        if (len >= 0 && (size_t)len < sizeof text) figures_text(c, text + len, sizeof text - (size_t)len);
    }
    snprintf(out, size, "%s", text + (text[0] == ' '));
}

/* make grade: under the table, what each part lost and why: its failed tasks with their failed
 * tests, and for each failing public case its cause, its hint, the seed its trace commands replay
 * and why, and the pixels to trace. */
static void print_causes(const grade_result *r, FILE *out)
{
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        for (int t = 0; !p->suite_reason[0] && p->spec && t < p->spec->num_tasks; t++) {
            const grade_task *k = &p->spec->tasks[t];
            if (p->task_score[t] >= k->points) continue;
            fprintf(out, "part %d, task %s (%s): %g / %g points; failed:", p->part, k->task, k->functions, p->task_score[t],
                    k->points);
            int shown = 0;
            for (int j = 0; j < p->num_tests; j++)
                if (!p->tests[j].passed && grade_task_of(p->spec, p->tests[j].name) == t)
                    fprintf(out, "%s %s", shown++ ? "," : "", p->tests[j].name);
            fprintf(out, "%s\n", shown ? "" : " (tests that did not run)");
        }
        if (!p->suite_reason[0] && tasks_failed(p) > 1) fprintf(out, "part %d: %s\n", p->part, cascade_text(p));
        if (p->suite_reason[0]) fprintf(out, "part %d, unit tests: 0 points: %s\n", p->part, p->suite_reason);
        for (int k = 0; k < p->num_cases; k++) {
            const grade_case_result *c = &p->cases[k];
            if (c->pass || c->spec->hidden) continue;
            char cause[2048];
            case_cause(c, cause, sizeof cause);
            fprintf(out, "part %d, %s: %s\n", p->part, c->spec->name, cause);
            if (c->ran && c->v.hint[0]) fprintf(out, "part %d, %s: %s\n", p->part, c->spec->name, c->v.hint);
            if (!c->trace[0]) continue;
            if (c->rendered_twice)
                fprintf(out, "part %d, %s: rendered twice (the first render, seed %llu, failed, and so did the second: the "
                        "difference is your code's), so its commands replay the second, seed %llu:\n", p->part,
                        c->spec->name, c->first_seed, c->seed);
            else fprintf(out, "part %d, %s: the pixels that differ most:\n", p->part, c->spec->name);
            fprintf(out, "%s", c->trace);
        }
    }
}

/* ---- the terminal table (make grade) ------------------------------------------------------------- */

/* A line per part (unit tests passed, cases matched, score), the total, and the pixels to trace. */
void grade_print_table(const grade_result *r, FILE *out)
{
    double max, total = grade_score_total(r, &max);
    fprintf(out, "%-5s  %-12s  %-24s  %s\n", "part", "unit tests", "image cases", "score");
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        int passed = 0;
        for (int k = 0; k < p->num_cases; k++) passed += p->cases[k].pass;
        char unit[32];
        if (p->suite_reason[0]) snprintf(unit, sizeof unit, "0 (see report)");
        else snprintf(unit, sizeof unit, "%d/%d passed", p->tests_run - p->tests_failed, p->tests_run);
        fprintf(out, "%-5d  %-12s  %2d/%-2d matched            %5.1f / %.1f\n", p->part, unit, passed, p->num_cases,
                p->score, p->max_score);
    }
    fprintf(out, "total%52.1f / %.1f   (seed %llu, %.0f s)\n", total, max, (unsigned long long)r->seed,
            run_seconds(r));
    if (r->unprotected[0]) fprintf(out, "unavailable protections: %s\n", r->unprotected);
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

/* A part's unit points task by task (cases.json's "unit_tasks"), one Markdown line each: the task,
 * its functions, its share earned or not, and how many of its tests passed. */
static int tasks_text(const grade_part_result *p, char *out, size_t size)
{
    int len = 0;
    for (int t = 0; p->spec && t < p->spec->num_tasks && len >= 0 && (size_t)len < size; t++) {
        const grade_task *k = &p->spec->tasks[t];
        len += snprintf(out + len, size - len, "- task %s (%s): %g / %g points, %d of %d tests passed%s\n", k->task,
                        k->functions, p->task_score[t], k->points, p->task_passed[t], k->tests,
                        p->task_score[t] < k->points ? " (a task's share is earned when all its tests pass)" : "");
    }
    if (tasks_failed(p) > 1 && len >= 0 && (size_t)len < size) len += snprintf(out + len, size - len, "\n%s\n", cascade_text(p));
    return len;
}

/* results.json: every part's unit-test entry and every case's, each always present (an entry that
 * cannot be made fails the whole file rather than vanishing), written atomically (file.h): a
 * platform never reads half a file. */
pl_status grade_write_results_json(const grade_result *r, const char *path, pl_diag *diag)
{
    json_t *tests = json_array();
    double max, total = grade_score_total(r, &max);
    bool complete = tests != NULL;
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        char name[128], text[sizeof p->build_output + 1024];
        snprintf(name, sizeof name, "Part %d: unit tests", p->part);
        /* Unit tests: why nothing was earned (with the compiler's last lines, the student's own
         * files only: grade_diag.c), or how many passed and the failures' messages. */
        char fence[64];
        md_fence(p->build_output, fence, sizeof fence);
        if (p->suite_reason[0] && p->build_output[0])
            snprintf(text, sizeof text, "**0 points**: %s. The end of the compiler's output:\n\n%s\n%s\n%s\n",
                     md(p->suite_reason), fence, p->build_output, fence);
        else if (p->suite_reason[0])
            snprintf(text, sizeof text, "**0 points**: %s.", md(p->suite_reason));
        else {
            int len = snprintf(text, sizeof text, "%d of %d tests passed.\n\n", p->tests_run - p->tests_failed, p->tests_run);
            len += tasks_text(p, text + len, sizeof text - (size_t)len);
            if (len >= 0 && (size_t)len < sizeof text) snprintf(text + len, sizeof text - (size_t)len, "\n%s", p->failures);
        }
        complete = complete && append_entry(tests, test_entry(name, p->unit_score, p->unit_max,
                                                              !p->suite_reason[0] && p->tests_failed == 0, text, false));
        for (int k = 0; k < p->num_cases; k++) {
            const grade_case_result *c = &p->cases[k];
            snprintf(name, sizeof name, "Part %d: image %s%s", p->part, c->spec->name, c->spec->hidden ? " (hidden)" : "");
            case_text(c, text, sizeof text);
            append_trace(c, text, sizeof text);
            complete = complete && append_entry(tests, test_entry(name, c->score, c->spec->points, c->pass, text,
                                                                  c->spec->hidden));
        }
    }
    /* The run's line: its seed (to grade again the same way) and any protection it lacked. */
    char summary[512];
    snprintf(summary, sizeof summary, "pathlab grader, seed %llu.%s%s", (unsigned long long)r->seed,
             r->unprotected[0] ? " Unavailable protections: " : "", r->unprotected);
    char *shown = report_text(summary);
    json_t *root = complete && shown ? json_pack("{s:f, s:f, s:s, s:O}", "score", total, "execution_time", run_seconds(r),
                                                 "output", shown, "tests", tests) : NULL;
    char *text = root ? json_dumps(root, JSON_INDENT(2)) : NULL;
    free(shown);
    json_decref(root);
    json_decref(tests);
    if (!text) return pl_fail(diag, PL_ERR_NOMEM, "%s: an entry could not be written (out of memory)", path);
    pl_status st = file_write_atomic(path, text, strlen(text), diag);
    free(text);
    return st;
}

/* ---- the HTML report: one page, a row per case with its three pictures ----------------------- */

/* Escapes text for HTML (valid UTF-8 first: report_text). With markdown (the verdicts' shared text,
 * results.json's): its bold (**...**) becomes <b>, and a character escaped for Markdown (a
 * backslash before it: grade_md_escape) shows as itself. Plain text (a compiler's lines, a command)
 * is shown exactly as it is. */
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

static void html_trace(FILE *f, const grade_case_result *c)
{
    if (!c->trace[0]) return;
    html_wrapped(f, "<p>The pixels that differ most, and the command that shows every path of each as your render "
                    "computed it (handout: \"Debugging with a trace\"):</p><pre>", c->trace, "</pre>\n");
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
            (unsigned long long)r->seed, run_seconds(r));
    if (r->unprotected[0]) html_wrapped(f, "<p class=\"fail\">Unavailable protections: ", r->unprotected, "</p>\n");
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
                p->part, p->part, p->tests_run - p->tests_failed, p->tests_run, passed, p->num_cases, p->score,
                p->max_score);
    }
    fprintf(f, "</table>\n");
}

/* A part's unit tests: why they earned nothing (with the compiler's last words), or the failures. */
static void html_unit_tests(FILE *f, const grade_part_result *p)
{
    if (p->suite_reason[0]) {
        html_wrapped(f, "<p class=\"fail\">Unit tests: 0 points: ", p->suite_reason, "</p>\n");
        if (p->build_output[0]) html_wrapped(f, "<p>The end of the compiler's output:</p><pre>", p->build_output, "</pre>\n");
        return;
    }
    fprintf(f, "<p class=\"%s\">Unit tests: %d of %d passed</p>\n", p->tests_failed ? "fail" : "pass",
            p->tests_run - p->tests_failed, p->tests_run);
    char tasks[2048];
    if (tasks_text(p, tasks, sizeof tasks) > 0) html_markdown(f, "<pre>", tasks, "</pre>\n");
    if (p->failures[0]) html_markdown(f, "<pre>", p->failures, "</pre>\n");
}

/* One image case: its verdict in words, the trace command, and the three pictures side by side. */
static void html_case(FILE *f, const grade_case_result *c)
{
    static const char *const captions[3] = {
        "your render", "the reference",
        "difference per block: <span class=\"scale\"></span> darker &harr; brighter (t from -5 to +5)"};
    static const char *const alts[3] = {"your render", "the reference", "difference per block"};
    char text[2048];
    case_text(c, text, sizeof text);
    fprintf(f, "<div class=\"case\"><h3>%s%s: <span class=\"%s\">%s</span></h3>", c->spec->name,
            c->spec->hidden ? " (hidden)" : "", c->pass ? "pass" : "fail", c->pass ? "passes" : "fails");
    html_wrapped(f, "<p><i>", c->spec->shows, "</i></p>");
    html_markdown(f, "<p>", text, "</p>\n");
    html_trace(f, c);
    if (c->ran && c->images[0][0] && !c->spec->hidden) {  /* a hidden case's render is not shown (case_text) */
        fprintf(f, "<div class=\"imgs\">");
        for (int m = 0; m < 3; m++)
            if (c->images[m][0])
                fprintf(f, "<figure><img src=\"%s\" alt=\"%s\"><figcaption>%s</figcaption></figure>", c->images[m],
                        alts[m], captions[m]);
        fprintf(f, "</div>\n");
    }
    fprintf(f, "</div>\n");
}

pl_status grade_write_html(const grade_result *r, const char *folder, pl_diag *diag)
{
    char path[4096];
    if (!grade_path(path, sizeof path, "%s/index.html", folder))
        return pl_fail(diag, PL_ERR_IO, "%s: the report's path is too long", folder);
    FILE *f = fopen(path, "w");
    if (!f) return pl_fail(diag, PL_ERR_IO, "%s: cannot write", path);
    html_head(f, r);
    html_summary(f, r);
    for (int i = 0; i < r->num_parts; i++) {
        const grade_part_result *p = &r->parts[i];
        fprintf(f, "<h2 id=\"part%d\">Part %d: %.1f / %.1f</h2>\n", p->part, p->part, p->score, p->max_score);
        html_unit_tests(f, p);
        for (int k = 0; k < p->num_cases; k++) html_case(f, &p->cases[k]);
    }
    fprintf(f, "</body></html>\n");
    if (fclose(f) != 0) return pl_fail(diag, PL_ERR_IO, "%s: cannot write", path);
    return PL_OK;
}
