/* Grader machinery: not part of any assignment. Reads grading/cases.json (jansson).
 *
 * The cases file decides every point a student can earn, and it is edited by hand, so it is
 * read strictly: every object's members are checked against a list (a misspelt key is an error,
 * not a check silently skipped), every value against its type and range, and every message names
 * the file, the part or the case, and what was expected (grading/README.md is the file's manual).
 * The hidden cases' file (grading/hidden/cases.json) has the same form and adds its cases to the
 * public file's parts. */
#include "grade_spec.h"
#include "../framework/exr.h"
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A case's "flags" or "reference_flags": an array of at most GRADE_MAX_FLAGS strings, copied. */
static pl_status read_flags(const char *path, const char *name, json_t *array, char **out, int *count, pl_diag *diag)
{
    if (!json_is_array(array) || json_array_size(array) > GRADE_MAX_FLAGS)
        return pl_fail(diag, PL_ERR_PARSE, "%s: case %s: expected an array of at most %d flags", path, name,
                       GRADE_MAX_FLAGS);
    size_t i;
    json_t *f;
    json_array_foreach(array, i, f) {
        const char *s = json_string_value(f);
        if (!s) return pl_fail(diag, PL_ERR_PARSE, "%s: case %s: flag %zu is not a string", path, name, i + 1);
        if (!(out[(*count)++] = strdup(s))) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    }
    return PL_OK;
}

/* The members an object may have, with their types ('s' string, 'i' integer, 'n' number, 'b' true or
 * false, 'a' array, 'o' object). */
typedef struct { const char *name; char type; } member;

static const member case_members[] = {
    {"name", 's'}, {"scene", 's'}, {"flags", 'a'}, {"resolution", 'a'}, {"samples", 'i'}, {"reference_samples", 'i'},
    {"reference_flags", 'a'}, {"points", 'n'}, {"visibility", 's'}, {"shows", 's'}, {"block_side", 'i'},
    {"work_check", 'b'}, {"statistic", 's'}, {"grazing", 'b'}, {"noise_check", 'b'}, {"tolerance", 'n'}, {NULL, 0}};
static const member part_members[] = {{"part", 'i'}, {"unit_points", 'n'}, {"unit_tests", 'i'}, {"unit_tasks", 'a'},
                                      {"cases", 'a'}, {NULL, 0}};
static const member task_members[] = {{"task", 's'}, {"functions", 's'}, {"points", 'n'}, {"tests", 'i'}, {"match", 'a'},
                                      {NULL, 0}};
static const member root_members[] = {{"about", 's'}, {"family_alpha", 'n'}, {"parts", 'a'}, {NULL, 0}};

/* Whether v is of the member type letter (member above): JSON's integer is also a number. */
static bool has_type(json_t *v, char type)
{
    switch (type) {
    case 's': return json_is_string(v);
    case 'i': return json_is_integer(v);
    case 'n': return json_is_number(v);
    case 'b': return json_is_boolean(v);
    case 'a': return json_is_array(v);
    default: return json_is_object(v);
    }
}

/* Every member of obj is a known one of its type: a misspelt key ("work_checks") would otherwise be
 * ignored and the check it asks for skipped in silence, and "work_check": "yes" read as false. */
static pl_status check_members(const char *path, const char *where, json_t *obj, const member *known, pl_diag *diag)
{
    if (!json_is_object(obj)) return pl_fail(diag, PL_ERR_PARSE, "%s: %s: expected an object", path, where);
    const char *key;
    json_t *v;
    json_object_foreach(obj, key, v) {
        const member *m = known;
        while (m->name && strcmp(m->name, key)) m++;
        if (!m->name) return pl_fail(diag, PL_ERR_PARSE, "%s: %s: unknown member \"%.40s\"", path, where, key);
        if (!has_type(v, m->type))
            return pl_fail(diag, PL_ERR_PARSE, "%s: %s: \"%s\" has the wrong type", path, where, key);
    }
    return PL_OK;
}

/* Every field is checked, with the case named: a typo in a case must not become a silent 0. */
static pl_status read_case(const char *path, int part, json_t *j, grade_case *c, pl_diag *diag)
{
    memset(c, 0, sizeof *c);
    const char *name = json_string_value(json_object_get(j, "name"));
    if (!name || strlen(name) >= sizeof c->name || strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789_") != strlen(name))
        return pl_fail(diag, PL_ERR_PARSE, "%s: part %d: a case needs a \"name\" of [a-z0-9_], under %zu characters",
                       path, part, sizeof c->name);
    snprintf(c->name, sizeof c->name, "%s", name);
    char where[96];
    snprintf(where, sizeof where, "case %s", c->name);
    pl_status checked = check_members(path, where, j, case_members, diag);
    if (checked != PL_OK) return checked;
    if (!json_is_number(json_object_get(j, "points")))
        return pl_fail(diag, PL_ERR_PARSE, "%s: case %s: expected \"points\"", path, c->name);
    const char *scene = json_string_value(json_object_get(j, "scene"));
    const char *vis = json_string_value(json_object_get(j, "visibility"));
    json_t *res = json_object_get(j, "resolution"), *flags = json_object_get(j, "flags");
    if (!scene || strlen(scene) >= sizeof c->scene || !json_is_array(res) || json_array_size(res) != 2 ||
        !json_is_array(flags) || json_array_size(flags) > GRADE_MAX_FLAGS || !vis ||
        (strcmp(vis, "public") && strcmp(vis, "hidden")))
        return pl_fail(diag, PL_ERR_PARSE,
                       "%s: case %s: expected \"scene\", \"flags\" (at most %d strings), \"resolution\" [w, h] "
                       "and \"visibility\" public|hidden", path, c->name, GRADE_MAX_FLAGS);
    snprintf(c->scene, sizeof c->scene, "%s", scene);
    c->hidden = !strcmp(vis, "hidden");
    /* The render: what the candidate renders, and at how many samples the reference was made. */
    c->width = (int)json_integer_value(json_array_get(res, 0));
    c->height = (int)json_integer_value(json_array_get(res, 1));
    c->samples = (int)json_integer_value(json_object_get(j, "samples"));
    c->reference_samples = (int)json_integer_value(json_object_get(j, "reference_samples"));

    /* The verdict: points, block size, the optional checks and the statistic (grading/README.md). */
    c->points = json_number_value(json_object_get(j, "points"));
    c->block_side = (int)json_integer_value(json_object_get(j, "block_side"));
    c->work_check = json_is_true(json_object_get(j, "work_check"));
    c->noise_check = json_is_true(json_object_get(j, "noise_check"));
    c->tolerance = json_number_value(json_object_get(j, "tolerance"));
    const char *statistic = json_string_value(json_object_get(j, "statistic"));
    c->known_variance = statistic && !strcmp(statistic, "known_variance");
    c->grazing = json_is_true(json_object_get(j, "grazing"));
    c->rounding = statistic && !strcmp(statistic, "rounding");

    if (statistic && !c->known_variance && !c->rounding && strcmp(statistic, "paired_t"))
        return pl_fail(diag, PL_ERR_PARSE, "%s: case %s: statistic '%.40s': expected paired_t, known_variance "
                       "or rounding", path, c->name, statistic);
    /* Only a render with no randomness in it can be compared up to rounding. */
    if (c->rounding && (json_integer_value(json_object_get(j, "samples")) != 1 ||
                        json_integer_value(json_object_get(j, "reference_samples")) != 1))
        return pl_fail(diag, PL_ERR_PARSE, "%s: case %s: statistic rounding needs samples 1 and "
                       "reference_samples 1 (a deterministic render)", path, c->name);

    const char *shows = json_string_value(json_object_get(j, "shows"));
    snprintf(c->shows, sizeof c->shows, "%s", shows ? shows : "");
    /* The films of a case must be ones the film reader accepts (exr.h's caps). */
    if (c->width < 1 || c->height < 1 || c->width > 4096 || c->height > 4096 ||
        (long)c->width * c->height > EXR_MAX_PIXELS || c->samples < 1 || c->points < 0 ||
        c->reference_samples < c->samples || c->reference_samples > EXR_MAX_SAMPLES || c->block_side < 0 ||
        !(c->tolerance >= 0.0 && c->tolerance <= 0.25))
        return pl_fail(diag, PL_ERR_PARSE,
                       "%s: case %s: expected a resolution in 1..4096 of at most %ld pixels, samples >= 1, points >= 0, "
                       "samples <= reference_samples <= %d and a tolerance in 0..0.25", path, c->name, EXR_MAX_PIXELS,
                       EXR_MAX_SAMPLES);
    pl_status st = read_flags(path, c->name, flags, c->flags, &c->num_flags, diag);
    json_t *ref_flags = json_object_get(j, "reference_flags");
    if (!st && ref_flags) st = read_flags(path, c->name, ref_flags, c->reference_flags, &c->num_reference_flags, diag);
    return st;
}

/* A part's "unit_tasks": each task's share of the unit points and the tests that carry it. The shares
 * must add up to "unit_points" and the tests to "unit_tests", so that no test and no point is left
 * out; that every test of the suite matches a task is make test-grader-process's to check. */
static pl_status read_tasks(const char *path, json_t *tasks, grade_part_spec *p, pl_diag *diag)
{
    if (!json_is_array(tasks) || json_array_size(tasks) < 1 || json_array_size(tasks) > GRADE_MAX_TASKS)
        return pl_fail(diag, PL_ERR_PARSE, "%s: part %d: expected \"unit_tasks\", 1 to %d tasks", path, p->part,
                       GRADE_MAX_TASKS);
    double points = 0.0;
    int tests = 0;
    for (size_t i = 0; i < json_array_size(tasks); i++) {
        json_t *tj = json_array_get(tasks, i), *match = json_object_get(tj, "match");
        char where[64];
        snprintf(where, sizeof where, "part %d: unit_tasks[%zu]", p->part, i);
        pl_status checked = check_members(path, where, tj, task_members, diag);
        if (checked != PL_OK) return checked;
        grade_task *t = &p->tasks[p->num_tasks++];
        const char *task = json_string_value(json_object_get(tj, "task"));
        const char *functions = json_string_value(json_object_get(tj, "functions"));
        t->points = json_number_value(json_object_get(tj, "points"));
        t->tests = (int)json_integer_value(json_object_get(tj, "tests"));
        if (!task || strlen(task) >= sizeof t->task || !functions || strlen(functions) >= sizeof t->functions ||
            !(t->points >= 0) || t->tests < 1 || !json_is_array(match) || json_array_size(match) < 1 ||
            json_array_size(match) > GRADE_MAX_MATCH)
            return pl_fail(diag, PL_ERR_PARSE, "%s: %s: expected \"task\", \"functions\", \"points\" >= 0, \"tests\" "
                           ">= 1 and \"match\", 1 to %d test-name prefixes", path, where, GRADE_MAX_MATCH);
        snprintf(t->task, sizeof t->task, "%s", task);
        snprintf(t->functions, sizeof t->functions, "%s", functions);
        for (size_t m = 0; m < json_array_size(match); m++) {
            const char *prefix = json_string_value(json_array_get(match, m));
            if (!prefix || !prefix[0] || strlen(prefix) >= sizeof t->match[0])
                return pl_fail(diag, PL_ERR_PARSE, "%s: %s: match %zu: expected a test-name prefix under %zu characters",
                               path, where, m + 1, sizeof t->match[0]);
            snprintf(t->match[t->num_match++], sizeof t->match[0], "%s", prefix);
        }
        points += t->points;
        tests += t->tests;
    }
    if (tests != p->unit_tests || fabs(points - p->unit_points) > 1e-9)
        return pl_fail(diag, PL_ERR_PARSE, "%s: part %d: the unit_tasks hold %d tests and %g points, but unit_tests is %d "
                       "and unit_points %g", path, p->part, tests, points, p->unit_tests, p->unit_points);
    return PL_OK;
}

/* Adds the cases of one file's "parts" to out. The base file (grading/cases.json) lists the course's
 * parts, each once, in increasing order, with its unit tests; the hidden file adds cases to parts the
 * base lists. */
static pl_status read_parts(const char *path, json_t *root, bool base, grade_spec *out, pl_diag *diag)
{
    pl_status checked = check_members(path, "the top level", root, root_members, diag);
    if (checked != PL_OK) return checked;
    json_t *parts = json_object_get(root, "parts");
    if (!json_is_array(parts) || (base && json_array_size(parts) == 0))
        return pl_fail(diag, PL_ERR_PARSE, "%s: expected \"parts\": %s", path,
                       base ? "one entry per part of the course, in increasing order" : "an array");
    int last = 0;
    for (size_t k = 0; k < json_array_size(parts); k++) {
        json_t *pj = json_array_get(parts, k), *cases = json_object_get(pj, "cases");
        char where[32];
        snprintf(where, sizeof where, "parts[%zu]", k);
        if ((checked = check_members(path, where, pj, part_members, diag)) != PL_OK) return checked;
        int part = (int)json_integer_value(json_object_get(pj, "part"));
        if (part < 1 || part > GRADE_MAX_PART || (base && part <= last) || !json_is_array(cases))
            return pl_fail(diag, PL_ERR_PARSE, "%s: parts[%zu]: expected \"part\" 1..%d (each once, in increasing "
                           "order) and \"cases\"", path, k, GRADE_MAX_PART);
        last = part;
        grade_part_spec *p = &out->parts[part - 1];
        if (!base && p->part != part)
            return pl_fail(diag, PL_ERR_PARSE, "%s: parts[%zu]: part %d has hidden cases, but %s does not list it",
                           path, k, part, GRADE_CASES);
        p->part = part;
        if (base) {
            p->unit_points = json_number_value(json_object_get(pj, "unit_points"));
            p->unit_tests = (int)json_integer_value(json_object_get(pj, "unit_tests"));
            if (p->unit_tests < 1)
                return pl_fail(diag, PL_ERR_PARSE, "%s: part %d: expected \"unit_tests\", the number of tests its "
                               "suite runs, >= 1", path, part);
            pl_status st = read_tasks(path, json_object_get(pj, "unit_tasks"), p, diag);
            if (st) return st;
        }
        if (p->num_cases + json_array_size(cases) > GRADE_MAX_CASES)
            return pl_fail(diag, PL_ERR_PARSE, "%s: part %d: more than %d cases", path, part, GRADE_MAX_CASES);
        for (size_t i = 0; i < json_array_size(cases); i++) {
            pl_status st = read_case(path, part, json_array_get(cases, i), &p->cases[p->num_cases++], diag);
            if (st) return st;
        }
    }
    return PL_OK;
}

pl_status grade_spec_load(const char *path, const char *hidden_path, grade_spec *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    json_error_t err;
    json_t *root = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    if (!root) return pl_fail(diag, PL_ERR_PARSE, "%s:%d: %s", path, err.line, err.text);
    out->family_alpha = json_number_value(json_object_get(root, "family_alpha"));
    pl_status st = out->family_alpha > 0 && out->family_alpha < 0.1
                       ? read_parts(path, root, true, out, diag)
                       : pl_fail(diag, PL_ERR_PARSE, "%s: expected \"family_alpha\" in (0, 0.1)", path);
    json_decref(root);

    /* The hidden cases, where this tree has them (never in a student's). */
    FILE *probe = hidden_path ? fopen(hidden_path, "r") : NULL;
    if (!st && probe) {
        fclose(probe);
        root = json_load_file(hidden_path, JSON_REJECT_DUPLICATES, &err);
        st = root ? read_parts(hidden_path, root, false, out, diag)
                  : pl_fail(diag, PL_ERR_PARSE, "%s:%d: %s", hidden_path, err.line, err.text);
        json_decref(root);
    }
    if (st) grade_spec_free(out);
    return st;
}

void grade_spec_free(grade_spec *s)
{
    if (!s) return;
    for (int k = 0; k < GRADE_MAX_PART; k++)
        for (int i = 0; i < s->parts[k].num_cases; i++)
            for (int f = 0; f < GRADE_MAX_FLAGS; f++) {
                free(s->parts[k].cases[i].flags[f]);
                free(s->parts[k].cases[i].reference_flags[f]);
            }
    memset(s, 0, sizeof *s);
}

int grade_spec_task_of(const grade_part_spec *p, const char *name)
{
    /* Test functions are named test_<function>__<behaviour>: the prefix is matched after "test_". */
    if (!strncmp(name, "test_", 5)) name += 5;
    for (int t = 0; t < p->num_tasks; t++)
        for (int m = 0; m < p->tasks[t].num_match; m++)
            if (!strncmp(name, p->tasks[t].match[m], strlen(p->tasks[t].match[m]))) return t;
    return -1;
}

bool grade_spec_adaptive(const grade_case *k)
{
    for (int f = 0; f < k->num_flags; f++)
        if (!strcmp(k->flags[f], "-a")) return true;
    return false;
}
