/* Grader machinery: not part of any assignment. facts.json: a grading's verdicts as data for course
 * staff (grade_facts.h says who reads it and why a student never does). */
#include "grade_facts.h"
#include "grade_image.h"
#include "grade_score.h"
#include "grade_words.h"
#include "../framework/file.h"
#include "../framework/utf8.h"
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- causes: one stable code and the report's words for each kind of failure ----------------- */

/* Why a case did not run, from its why's code (grade_why.h). */
static const char *not_run_cause(const grade_why *w, const char **words)
{
    switch (w->code) {
    case GRADE_WHY_NOT_BUILT: return *words = "the part did not build", "not_built";
    case GRADE_WHY_RENDER_STUB: return *words = "a task is still a stub", "stub";
    case GRADE_WHY_RENDER_REFUSED: return *words = "the framework refused the BVH", "malformed_tree";
    case GRADE_WHY_RENDER_SYSCALL: return *words = "a system call the sandbox forbids", "forbidden_call";
    case GRADE_WHY_RENDER_TIMED_OUT:
    case GRADE_WHY_RENDER_CPU: return *words = "ran past its time", "timed_out";
    case GRADE_WHY_RENDER_OUT_OF_TIME: return *words = "the grading ran out of time", "out_of_time";
    case GRADE_WHY_RENDER_MEMORY_ERROR:
    case GRADE_WHY_RENDER_SIGNAL: return *words = "crashed", "crashed";
    case GRADE_WHY_FILM_UNUSABLE:
    case GRADE_WHY_FILM_TOO_BIG:
    case GRADE_WHY_FILM_COUNTS:
    case GRADE_WHY_FILM_SUMS: return *words = "sent no usable film", "no_film";
    case GRADE_WHY_COURSE: return *words = "the course's reference or scene (not the student's)", "course_error";
    case GRADE_WHY_GRADER: return *words = "the grader could not go on (not the student's)", "grader_error";
    case GRADE_WHY_RENDER_BUILD_ERROR:
    case GRADE_WHY_RENDER_STATUS: return *words = "the render stopped with an error", "render_error";
    default: return *words = "did not run", "did_not_run";
    }
}

/* The failed verdict's hint (verdict.c) as the class report names it. */
static const struct { const char *code, *words; } hints[] = {
    {"factor_2", "too bright by 2"},
    {"factor_1/2", "too dark by 1/2"},
    {"factor_pi", "too bright by pi"},
    {"factor_1/pi", "too dark by 1/pi"},
    {"black", "black where the reference is lit"},
    {"self_shadowing", "self-shadowing where light grazes"},
};

/* A case that ran and whose image matched, but a figure of its render failed. */
static const char *figure_cause(const grade_case_result *c, const char **words)
{
    if (!grade_image_noise_ok(c))
        return *words = "noisier than the course's", "noisier";
    if (!grade_image_spp_ok(c)) return *words = "samples per pixel unlike the course's", "samples_per_pixel";
    if (!grade_image_rate_ok(c)) return *words = "samples spent unlike the course's (not adaptive)", "not_adaptive";
    if (!grade_image_work_ok(c)) return *words = "slower than the course's BVH", "slow";
    return *words = "a figure of its render is off", "figure";
}

const char *grade_facts_case_cause(const grade_part_result *p, const grade_case_result *c, const char **words)
{
    *words = "";
    if (c->pass) return NULL;
    if (!c->ran && p && !p->build.built) return *words = "the part did not build", "not_built";
    if (!c->ran) return not_run_cause(&c->why, words);
    const verdict *v = &c->v;
    if (!v->pass) {
        if (v->bad_pixels) return *words = "NaN, infinite or negative pixels", "bad_pixels";
        for (size_t i = 0; v->hint_code && i < sizeof hints / sizeof hints[0]; i++)
            if (!strcmp(v->hint_code, hints[i].code)) return *words = hints[i].words, hints[i].code;
        if (v->deterministic) return *words = "pixels differ beyond rounding", "pixels_differ";
        double ratio = grade_result_mean_ratio(v);
        if (ratio > 1.05) return *words = "too bright overall", "too_bright";
        if (ratio < 0.95) return *words = "too dark overall", "too_dark";
        return *words = "differs in a region", "differs_locally";
    }
    return figure_cause(c, words);
}

const char *grade_facts_unit_cause(const grade_part_result *p)
{
    if (!p->build.built) return "not_built";
    if (!p->suite.judged) return "suite_stopped";
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
    const char *words, *cause = grade_facts_case_cause(p, c, &words);
    return json_pack("{s:o, s:b, s:f, s:f, s:b, s:b, s:b, s:o, s:o, s:o, s:o, s:o}", "name", text(c->spec->name),
                     "hidden", c->spec->hidden, "points", c->spec->points, "score", c->score, "passed", c->pass,
                     "ran", c->ran, "rendered_twice", c->rendered_twice, "cause", text(cause),
                     "cause_words", text(cause ? words : NULL), "p_value", c->ran ? number(c->v.p_value) : json_null(),
                     "mean_ratio", c->ran ? number(grade_result_mean_ratio(&c->v)) : json_null(),
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
    for (int i = 0; ok && i < p->suite.num_tests; i++) {
        const grade_test_fact *f = &p->suite.tests[i];
        int t = p->spec ? grade_spec_task_of(p->spec, f->name) : -1;
        if (!f->passed && !first_failed) first_failed = f->name;
        ok = !json_array_append_new(tests, json_pack("{s:o, s:o, s:b}", "name", text(f->name), "task",
                                                     text(t >= 0 ? p->spec->tasks[t].task : NULL), "passed", f->passed));
    }
    char zero[1024];
    bool unjudged = grade_words_unit_zero(p, zero, sizeof zero);
    for (int k = 0; ok && k < p->num_cases; k++) ok = !json_array_append_new(cases, case_facts(p, &p->cases[k]));
    json_t *j = ok ? json_pack("{s:i, s:f, s:f, s:f, s:f, s:b, s:o, s:o, s:i, s:i, s:o, s:O, s:O, s:O}", "part", p->part,
                               "score", p->score, "max_score", p->max_score, "unit_score", p->unit_score, "unit_max",
                               p->unit_max, "built", p->build.built, "unit_cause", text(grade_facts_unit_cause(p)),
                               "suite_reason", text(unjudged ? zero : NULL), "tests_run", p->suite.run,
                               "tests_failed", p->suite.failed, "first_failed_test", text(first_failed), "tasks", tasks,
                               "tests", tests, "cases", cases)
                   : NULL;
    json_decref(tasks), json_decref(tests), json_decref(cases);
    return j;
}

pl_status grade_facts_write(const grade_result *r, const char *path, pl_diag *diag)
{
    double max, total = grade_score_total(r, &max);
    json_t *parts = json_array();
    bool ok = parts != NULL;
    for (int i = 0; ok && i < r->num_parts; i++) ok = !json_array_append_new(parts, part_facts(&r->parts[i]));
    char seed[32], missing[512];
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)r->seed);  /* a string: seeds reach 2^64 */
    missing[0] = '\0';
    if (r->submission) grade_words_protections_missing(&r->sandbox, missing, sizeof missing);
    json_t *root = ok ? json_pack("{s:s, s:s, s:f, s:f, s:f, s:o, s:O}", "schema", GRADE_FACTS_SCHEMA, "seed", seed,
                                  "score", total, "max_score", max, "seconds", r->seconds, "unprotected",
                                  text(missing[0] ? missing : NULL), "parts", parts)
                      : NULL;
    char *dump = root ? json_dumps(root, JSON_INDENT(2) | JSON_SORT_KEYS) : NULL;
    json_decref(root);
    json_decref(parts);
    if (!dump) return pl_fail(diag, PL_ERR_NOMEM, "%s: the facts could not be written (out of memory)", path);
    pl_status st = file_write_atomic(path, dump, strlen(dump), diag);
    free(dump);
    return st;
}
