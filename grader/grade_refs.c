/* Grader machinery: not part of any assignment. The course's references, checked before grading.
 *
 * What of the render key can be checked: the key hashes the code version, the normalised flags, the
 * scene's bytes and the seed. The grader recomputes it from the case (its reference flags, size,
 * samples, scene file) and the seed and version the reference records. The version itself is not
 * compared with the grader's: a reference stays valid across commits that do not change the image
 * (regenerating every reference at each commit would cost hours of cluster time), and the
 * course's tests (make test-course, make references) are what tie the references to the code. So a
 * reference made for other flags, another size, another sample count or another scene file is
 * refused; one made by another code version with the same inputs is accepted. */
#include "grade_refs.h"
#include "grade_fmt.h"
#include "grade_plan.h"
#include "../framework/cli.h"
#include "../framework/exr.h"
#include "../framework/film.h"
#include "../framework/range.h"
#include <jansson.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An adaptive case: the candidate's flags hold -a. */
static bool adaptive_case(const grade_case *k)
{
    for (int f = 0; f < k->num_flags; f++)
        if (!strcmp(k->flags[f], "-a")) return true;
    return false;
}

/* The provenance the reference of k must record: the reference's own command (reference_flags or
 * flags, the case's size, reference_samples, the recorded seed) normalised as the renderer does. */
static pl_status expected_info(const grade_case *k, const exr_info *got, exr_info *want, pl_diag *diag)
{
    char w[16], h[16], n[16], seed[32];
    snprintf(w, sizeof w, "%d", k->width);
    snprintf(h, sizeof h, "%d", k->height);
    snprintf(n, sizeof n, "%d", k->reference_samples);
    snprintf(seed, sizeof seed, "%" PRIu64, got->seed);
    char *argv[2 * GRADE_MAX_FLAGS + 16];
    int argc = 0, nf = k->num_reference_flags ? k->num_reference_flags : k->num_flags;
    argv[argc++] = "pathtracer";
    for (int f = 0; f < nf; f++) argv[argc++] = k->num_reference_flags ? k->reference_flags[f] : k->flags[f];
    char *rest[] = {"-r", w, h, "-s", n, "--seed", seed, (char *)k->scene};
    for (size_t i = 0; i < sizeof rest / sizeof rest[0]; i++) argv[argc++] = rest[i];
    argv[argc] = NULL;
    options o = options_default();
    cli_action action = CLI_RUN;
    pl_status s = cli_parse(argc, argv, &o, &action, diag);
    if (s == PL_OK && action != CLI_RUN) s = pl_fail(diag, PL_ERR_INVALID, "the flags ask for help, not a render");
    if (s != PL_OK) return s;
    s = range_info_as(&o, got->version, want, diag);
    cli_free(&o);
    return s;
}

/* The film: strict, consistent, clean, complete, the case's size, made with the case's inputs. */
static pl_status check_film(const char *path, const grade_case *k, exr_info *info, pl_diag *diag)
{
    film f = {0};
    pl_status s = exr_read(path, &f, info, diag);
    if (s != PL_OK) return s;
    long bad = 0, pixels = (long)f.width * f.height;
    for (long i = 0; i < pixels; i++) bad += f.pixels[i].bad != 0;
    int width = f.width, height = f.height;
    film_free(&f);
    if (bad) return pl_fail(diag, PL_ERR_INVALID, "%s: %ld pixels hold bad samples (NaN, infinite or negative)", path, bad);
    if (width != k->width || height != k->height || info->sample_begin != 0 || info->sample_end != k->reference_samples ||
        info->sample_total != k->reference_samples)
        return pl_fail(diag, PL_ERR_INVALID, "%s: %dx%d, samples %d:%d of %d; the case needs %dx%d, 0:%d of %d", path,
                       width, height, info->sample_begin, info->sample_end, info->sample_total, k->width, k->height,
                       k->reference_samples, k->reference_samples);
    exr_info want;
    if (expected_info(k, info, &want, diag) != PL_OK) {
        char why[256];
        grade_msg(why, sizeof why, "%s", diag->error);
        return pl_fail(diag, PL_ERR_INVALID, "%s: the case's reference command does not parse: %s", path, why);
    }
    if (strcmp(want.command, info->command))
        return pl_fail(diag, PL_ERR_INVALID, "%s: pathlab.command '%.300s', the case's is '%.300s'", path, info->command,
                       want.command);
    if (strcmp(want.render_key, info->render_key))
        return pl_fail(diag, PL_ERR_INVALID, "%s: pathlab.render_key %s, the case's %s (the scene file changed?)", path,
                       info->render_key, want.render_key);
    return PL_OK;
}

/* A number member of a JSON object, finite and > 0 when `needed` (else any finite number or absent). */
static bool positive(json_t *obj, const char *name, bool needed, double *out)
{
    json_t *v = json_object_get(obj, name);
    *out = json_is_number(v) ? json_number_value(v) : 0.0;
    if (v && (!json_is_number(v) || !isfinite(*out))) return false;
    return !needed || *out > 0.0;
}

/* The reference's JSON beside ref_exr: strict (no duplicate key), loaded whole. */
static json_t *load_json(const char *ref_exr, char *path, size_t size, pl_diag *diag)
{
    if (!grade_plan_reference_json(ref_exr, path, size)) {
        pl_fail(diag, PL_ERR_IO, "%s: the path of its JSON does not fit", ref_exr);
        return NULL;
    }
    json_error_t err;
    json_t *j = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    if (!j) pl_fail(diag, PL_ERR_PARSE, "%s:%d: %s", path, err.line, err.text);
    else if (!json_is_object(j)) {
        json_decref(j);
        j = NULL;
        pl_fail(diag, PL_ERR_PARSE, "%s: expected a JSON object", path);
    }
    return j;
}

pl_status grade_refs_figures(const char *ref_exr, const grade_case *k, grade_course_figures *out, pl_diag *diag)
{
    char path[4200];
    memset(out, 0, sizeof *out);
    json_t *j = load_json(ref_exr, path, sizeof path, diag);
    if (!j) return PL_ERR_PARSE;
    json_t *r = json_object_get(j, "case_render");
    bool adaptive = adaptive_case(k);
    bool ok = json_is_object(r) && positive(r, "mean_samples_per_pixel", adaptive, &out->spp) &&
              (!adaptive || grade_rate_map_read(json_object_get(r, "rate_map"), k->width, k->height, &out->map));
    json_decref(j);
    return ok ? PL_OK : pl_fail(diag, PL_ERR_PARSE, "%s: case_render: expected a positive mean_samples_per_pixel%s",
                                path, adaptive ? " and the rate_map of a case of its size (an adaptive case)" : "");
}

/* The JSON names the case and matches the film's provenance; the figures the case judges are there. */
static pl_status check_json(const char *ref_exr, const grade_case *k, int part, const exr_info *info, pl_diag *diag)
{
    char path[4200];
    grade_course_figures *figures = malloc(sizeof *figures);  /* a map of blocks: not for the stack */
    pl_status st = figures ? grade_refs_figures(ref_exr, k, figures, diag) : pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    free(figures);
    if (st != PL_OK) return st;
    json_t *j = load_json(ref_exr, path, sizeof path, diag);
    if (!j) return PL_ERR_PARSE;
    /* Its "key" is the reference maker's own (what decides a re-render), not the film's render key. */
    const char *name = json_string_value(json_object_get(j, "case"));
    json_t *seed = json_object_get(j, "seed");
    bool ok = name && !strcmp(name, k->name) && json_integer_value(json_object_get(j, "part")) == part &&
              json_integer_value(json_object_get(j, "samples")) == k->reference_samples && json_is_integer(seed) &&
              (uint64_t)json_integer_value(seed) == info->seed;
    json_decref(j);
    return ok ? PL_OK : pl_fail(diag, PL_ERR_PARSE, "%s: expected \"case\" %s, \"part\" %d, \"samples\" %d and the "
                                "film's \"seed\" %" PRIu64, path, k->name, part, k->reference_samples, info->seed);
}

pl_status grade_refs_check(const char *root, const grade_spec *spec, const char *parts, bool public_only, pl_diag *diag)
{
    for (int p = 0; p < GRADE_MAX_PART; p++) {
        char digit[2] = {(char)('1' + p), 0};
        if (!strstr(parts, digit)) continue;
        for (int i = 0; i < spec->parts[p].num_cases; i++) {
            const grade_case *k = &spec->parts[p].cases[i];
            if (public_only && k->hidden) continue;
            char path[4096];
            exr_info info;
            grade_plan_reference(root, k, p + 1, path, sizeof path);
            pl_status s = check_film(path, k, &info, diag);
            if (s == PL_OK) s = check_json(path, k, p + 1, &info, diag);
            if (s != PL_OK) {
                char why[sizeof diag->error];
                grade_msg(why, sizeof why, "%s", diag->error);
                return pl_fail(diag, s, "the course's reference for part %d case %s is not usable, so nobody is graded: "
                               "%s\n  the course must run: make references FORCE=1 CASES=%s", p + 1, k->name, why, k->name);
            }
        }
    }
    return PL_OK;
}
