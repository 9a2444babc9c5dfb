/* Grader machinery: not part of any assignment. facts.json: a grading's verdicts as data for course
 * staff (grade_facts.h says who reads it and why a student never does). */
#include "grade_facts.h"
#include "../framework/file.h"
#include "../framework/utf8.h"
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- causes: one stable code and the report's words for each kind of failure ----------------- */

/* Why a case did not run, from the grader's own reason (a sentence the grader wrote, never the
 * render's output: grade_image.c selects its sentences from fixed tables), first match wins. */
static const struct { const char *phrase, *code, *words; } not_run[] = {
    {"still a stub", "stub", "a task is still a stub"},
    {"refused the tree", "malformed_tree", "the framework refused the BVH"},
    {"forbids", "forbidden_call", "a system call the sandbox forbids"},
    {"ran past", "timed_out", "ran past its time"},
    {"crashed", "crashed", "crashed"},
    {"killed by a signal", "crashed", "crashed"},
    {"no usable film", "no_film", "sent no usable film"},
    {"the course's", "course_error", "the course's reference or scene (not the student's)"},
    {"error", "render_error", "the render stopped with an error"},
};

/* The failed verdict's hint (verdict.c) as the class report names it. */
static const struct { const char *code, *words; } hints[] = {
    {"factor_2", "too bright by 2"},
    {"factor_1/2", "too dark by 1/2"},
    {"factor_pi", "too bright by pi"},
    {"factor_1/pi", "too dark by 1/pi"},
    {"black", "black where the reference is lit"},
    {"self_shadowing", "self-shadowing where light grazes"},
};

/* The mean of the lit channels' ratios (NaN when none is lit). */
static double mean_ratio(const verdict *v)
{
    double sum = 0.0;
    int lit = 0;
    for (int ch = 0; ch < 3; ch++)
        if (!isnan(v->ratio[ch])) sum += v->ratio[ch], lit++;
    return lit ? sum / lit : NAN;
}

/* A case that ran and whose image matched, but a figure of its render failed. */
static const char *figure_cause(const grade_case_result *c, const char **words)
{
    if (c->spec->noise_check && !(c->noise <= GRADE_NOISE_FACTOR))
        return *words = "noisier than the course's", "noisier";
    if (!grade_case_spp_ok(c)) return *words = "samples per pixel unlike the course's", "samples_per_pixel";
    if (!grade_case_rate_ok(c)) return *words = "samples spent unlike the course's (not adaptive)", "not_adaptive";
    if (!grade_case_work_ok(c)) return *words = "slower than the course's BVH", "slow";
    return *words = "a figure of its render is off", "figure";
}

const char *grade_case_cause(const grade_part_result *p, const grade_case_result *c, const char **words)
{
    *words = "";
    if (c->pass) return NULL;
    if (!c->ran && p && !p->built) return *words = "the part did not build", "not_built";
    if (!c->ran) {
        for (size_t i = 0; i < sizeof not_run / sizeof not_run[0]; i++)
            if (strstr(c->reason, not_run[i].phrase)) return *words = not_run[i].words, not_run[i].code;
        return *words = "did not run", "did_not_run";
    }
    const verdict *v = &c->v;
    if (!v->pass) {
        if (v->bad_pixels) return *words = "NaN, infinite or negative pixels", "bad_pixels";
        for (size_t i = 0; v->hint_code && i < sizeof hints / sizeof hints[0]; i++)
            if (!strcmp(v->hint_code, hints[i].code)) return *words = hints[i].words, hints[i].code;
        if (v->deterministic) return *words = "pixels differ beyond rounding", "pixels_differ";
        double ratio = mean_ratio(v);
        if (ratio > 1.05) return *words = "too bright overall", "too_bright";
        if (ratio < 0.95) return *words = "too dark overall", "too_dark";
        return *words = "differs in a region", "differs_locally";
    }
    return figure_cause(c, words);
}

const char *grade_unit_cause(const grade_part_result *p)
{
    if (!p->built) return "not_built";
    if (p->suite_reason[0]) return "suite_stopped";
    return p->unit_score < p->unit_max ? "tests" : NULL;
}

/* ---- the document ---------------------------------------------------------------------------- */

/* A string member: valid UTF-8 (utf8_sanitize), or JSON null for NULL. */
static json_t *text(const char *s)
{
    if (!s) return json_null();
    size_t size = 4 * strlen(s) + 1;
    char *valid = malloc(size);
    json_t *j = valid ? json_string(utf8_sanitize(s, valid, size)) : NULL;
    free(valid);
    return j;
}

/* A number member: JSON null for NaN or an infinity, which JSON cannot hold. */
static json_t *number(double x)
{
    return isfinite(x) ? json_real(x) : json_null();
}

static json_t *task_facts(const grade_part_result *p, int t)
{
    const grade_task *k = &p->spec->tasks[t];
    return json_pack("{s:o, s:o, s:f, s:f, s:i, s:i}", "task", text(k->task), "functions", text(k->functions),
                     "points", k->points, "score", p->task_score[t], "tests", k->tests, "passed", p->task_passed[t]);
}

/* The figures a case judges beside its image, each where it judges them (else null). */
static json_t *figure_facts(const grade_case_result *c)
{
    bool work = c->spec->work_check && c->base_cpu > 0;
    return json_pack("{s:o, s:o, s:o, s:o, s:o, s:o}", "noise", c->spec->noise_check ? number(c->noise) : json_null(),
                     "samples_per_pixel", c->course_spp > 0 ? number(c->spp) : json_null(),
                     "rate_map_distance", c->rate_distance >= 0 ? number(c->rate_distance) : json_null(),
                     "cpu_seconds", work ? number(c->cpu) : json_null(),
                     "baseline_cpu_seconds", work ? number(c->base_cpu) : json_null(),
                     "baseline", work ? json_string(c->base_is_scan ? "linear scan" : "course") : json_null());
}

static json_t *case_facts(const grade_part_result *p, const grade_case_result *c)
{
    const char *words, *cause = grade_case_cause(p, c, &words);
    return json_pack("{s:o, s:b, s:f, s:f, s:b, s:b, s:b, s:o, s:o, s:o, s:o, s:o}", "name", text(c->spec->name),
                     "hidden", c->spec->hidden, "points", c->spec->points, "score", c->score, "passed", c->pass,
                     "ran", c->ran, "rendered_twice", c->rendered_twice, "cause", text(cause),
                     "cause_words", text(cause ? words : NULL), "p_value", c->ran ? number(c->v.p_value) : json_null(),
                     "mean_ratio", c->ran ? number(mean_ratio(&c->v)) : json_null(),
                     "figures", c->ran ? figure_facts(c) : json_null());
}

/* One part: its score, its unit tests task by task and test by test, its cases. NULL when out of
 * memory (the caller fails the file: an entry is never silently missing). */
static json_t *part_facts(const grade_part_result *p)
{
    json_t *tasks = json_array(), *tests = json_array(), *cases = json_array();
    const char *first_failed = NULL;
    bool ok = tasks && tests && cases;
    for (int t = 0; ok && p->spec && t < p->spec->num_tasks; t++) ok = !json_array_append_new(tasks, task_facts(p, t));
    for (int i = 0; ok && i < p->num_tests; i++) {
        int t = p->spec ? grade_task_of(p->spec, p->tests[i].name) : -1;
        if (!p->tests[i].passed && !first_failed) first_failed = p->tests[i].name;
        ok = !json_array_append_new(tests, json_pack("{s:o, s:o, s:b}", "name", text(p->tests[i].name), "task",
                                                     text(t >= 0 ? p->spec->tasks[t].task : NULL), "passed",
                                                     p->tests[i].passed));
    }
    for (int k = 0; ok && k < p->num_cases; k++) ok = !json_array_append_new(cases, case_facts(p, &p->cases[k]));
    json_t *j = ok ? json_pack("{s:i, s:f, s:f, s:f, s:f, s:b, s:o, s:o, s:i, s:i, s:o, s:O, s:O, s:O}", "part", p->part,
                               "score", p->score, "max_score", p->max_score, "unit_score", p->unit_score, "unit_max",
                               p->unit_max, "built", p->built, "unit_cause", text(grade_unit_cause(p)), "suite_reason",
                               text(p->suite_reason[0] ? p->suite_reason : NULL), "tests_run", p->tests_run,
                               "tests_failed", p->tests_failed, "first_failed_test", text(first_failed), "tasks", tasks,
                               "tests", tests, "cases", cases)
                   : NULL;
    json_decref(tasks), json_decref(tests), json_decref(cases);
    return j;
}

pl_status grade_write_facts(const grade_result *r, const char *path, pl_diag *diag)
{
    double max, total = grade_score_total(r, &max);
    json_t *parts = json_array();
    bool ok = parts != NULL;
    for (int i = 0; ok && i < r->num_parts; i++) ok = !json_array_append_new(parts, part_facts(&r->parts[i]));
    char seed[32];
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)r->seed);  /* a string: seeds reach 2^64 */
    json_t *root = ok ? json_pack("{s:s, s:s, s:f, s:f, s:f, s:o, s:O}", "schema", GRADE_FACTS_SCHEMA, "seed", seed,
                                  "score", total, "max_score", max, "seconds", r->seconds, "unprotected",
                                  text(r->unprotected[0] ? r->unprotected : NULL), "parts", parts)
                      : NULL;
    char *dump = root ? json_dumps(root, JSON_INDENT(2) | JSON_SORT_KEYS) : NULL;
    json_decref(root);
    json_decref(parts);
    if (!dump) return pl_fail(diag, PL_ERR_NOMEM, "%s: the facts could not be written (out of memory)", path);
    pl_status st = file_write_atomic(path, dump, strlen(dump), diag);
    free(dump);
    return st;
}
