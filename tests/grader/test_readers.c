/* Test machinery: not part of any assignment. What the grader reads, read as hostile input: the
 * course's references (grader/grade_refs.c: a broken one is the course's error, never a student's
 * 0 nor a check skipped), grading/cases.json (grader/grade_spec.c) and a suite's XML results
 * (grader/grade_suite.c), and the score made from them (grader/grade_score.c). Each hostile file is
 * written here, from the course's real ones. What the grader writes is test_words.c's. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_fmt.h"
#include "../../grader/grade_handout.h"
#include "../../grader/grade_plan.h"
#include "../../grader/grade_refs.h"
#include "../../grader/grade_result.h"
#include "../../grader/grade_score.h"
#include "../../grader/grade_spec.h"
#include "../../grader/grade_suite.h"
#include "../../framework/file.h"
#include "../../framework/exr.h"
#include "../../framework/utf8.h"
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

SCRATCH_FOLDER(scratch, "readers-test")

static void sh(const char *fmt, const char *a, const char *b)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, fmt, a, b);
    assert_int_equal(0, system(cmd));
}

/* ---- the references ------------------------------------------------------------------------ */

/* A root of the course's real part 2 and part 5 references, to break one file at a time. */
static void fresh_root(char *root, size_t size)
{
    snprintf(root, size, "%s/root", scratch);
    sh("rm -rf '%s' && mkdir -p '%s/reference_images'", root, root);
    sh("cp -r reference_images/part2 reference_images/part5 '%s/reference_images/'%s", root, "");
}

/* grade_refs_check on parts 2 and 5 of the real cases: the error, or "" when they pass. */
static const char *check(const char *root)
{
    static pl_diag d;
    grade_spec spec;
    d = pl_diag_default();
    assert_int_equal(PL_OK, grade_spec_load(GRADE_CASES, NULL, &spec, &d));
    pl_status s = grade_refs_check(root, &spec, "2,5", true, &d);
    grade_spec_free(&spec);
    return s == PL_OK ? "" : d.error;
}

static void expect_refused(const char *root, const char *words, const char *case_name)
{
    const char *why = check(root);
    char run[128];
    snprintf(run, sizeof run, "make references FORCE=1 CASES=%s", case_name);
    if (!strstr(why, words) || !strstr(why, run) || !strstr(why, "the course's reference"))
        fail_msg("expected the course's error naming '%s' and '%s', got: '%s'", words, run, why);
}

/* Edits a reference's JSON by member (never by its layout): in the object the member `within` holds
 * (the document itself when NULL), sets key to value (taken), or deletes it when value is NULL. With
 * twice, the member is written a second time before the first: a duplicate key, which jansson cannot
 * make, so it is spliced into jansson's own compact text of the document. */
static void ref_edit(const char *path, const char *within, const char *key, json_t *value, bool twice)
{
    json_error_t err;
    json_t *doc = json_load_file(path, 0, &err);
    if (!doc) fail_msg("%s:%d: %s", path, err.line, err.text);
    json_t *obj = within ? json_object_get(doc, within) : doc;
    if (!json_object_get(obj, key)) fail_msg("%s: no member %s%s%s to edit", path, within ? within : "", within ? "." : "", key);
    if (!twice) {
        if (value) json_object_set_new(obj, key, value); else json_object_del(obj, key);
        assert_int_equal(0, json_dump_file(doc, path, JSON_INDENT(2)));
        json_decref(doc);
        return;
    }
    char *text = json_dumps(doc, JSON_COMPACT), *member = json_dumps(value, JSON_ENCODE_ANY), quoted[96];
    snprintf(quoted, sizeof quoted, "\"%s\":", key);
    const char *at = text ? strstr(text, quoted) : NULL;
    assert_true(at && member);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "%.*s%s%s,%s", (int)(at - text), text, quoted, member, at);  /* the copy, then the document's own */
    assert_int_equal(0, fclose(f));
    free(text), free(member);
    json_decref(value), json_decref(doc);
}

static void test_refs__the_course_references_pass(void **state)
{
    (void)state;
    char root[128];
    fresh_root(root, sizeof root);
    assert_string_equal(check(root), "");
}

/* The JSON an adaptive case needs: missing, empty, broken, duplicated, zero, and its sample-rate map
 * missing or of another shape. Before, a missing part 2 JSON skipped its check, and a render without
 * the BVH got full marks. */
static void test_refs__the_json_a_check_needs_is_required(void **state)
{
    (void)state;
    char root[128], adaptive[256];
    fresh_root(root, sizeof root);
    snprintf(adaptive, sizeof adaptive, "%s/reference_images/part5/spheres_adaptive.json", root);
    assert_int_equal(0, unlink(adaptive));
    expect_refused(root, "spheres_adaptive.json", "spheres_adaptive");
    scratch_write(adaptive, "");
    expect_refused(root, "spheres_adaptive.json", "spheres_adaptive");
    scratch_write(adaptive, "{\"case\": \"spheres_adaptive\", \"part\": 5, \"samples\": 1, \"seed\": 1,");
    expect_refused(root, "spheres_adaptive.json", "spheres_adaptive");
    fresh_root(root, sizeof root);
    ref_edit(adaptive, "case_render", "mean_samples_per_pixel", json_integer(0), true);
    expect_refused(root, "duplicate", "spheres_adaptive");
    fresh_root(root, sizeof root);
    ref_edit(adaptive, "case_render", "mean_samples_per_pixel", NULL, false);
    expect_refused(root, "mean_samples_per_pixel and the rate_map of a case of its size (an adaptive case)", "spheres_adaptive");
    fresh_root(root, sizeof root);
    ref_edit(adaptive, "case_render", "rate_map", NULL, false);
    expect_refused(root, "the rate_map of a case of its size", "spheres_adaptive");
    fresh_root(root, sizeof root);
    ref_edit(adaptive, "case_render", "rate_map", json_pack("{s:i, s:i, s:[f]}", "columns", 1, "rows", 1, "mean", 4.0), false);
    expect_refused(root, "the rate_map of a case of its size", "spheres_adaptive");
    fresh_root(root, sizeof root);
    ref_edit(adaptive, NULL, "case", json_string("spheres_normals"), false);
    expect_refused(root, "expected \"case\" spheres_adaptive", "spheres_adaptive");
}

/* A film that is not the case's: a partial range, another flag, another size, a missing file. */
static void test_refs__the_film_must_be_the_cases(void **state)
{
    (void)state;
    char root[128], exr[256];
    fresh_root(root, sizeof root);
    snprintf(exr, sizeof exr, "%s/reference_images/part2/bunny_normals.exr", root);
    /* The seed the reference records, so that only the changed flag differs. */
    exr_info info;
    int w, h;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, exr_read_info(exr, &info, &w, &h, &d));
    /* Rendered beside, then copied over the film: a render's sidecar would replace the JSON. */
    char render[512], copy[600];
    snprintf(render, sizeof render, "bin/pathtracer --normals -r 160 120 --seed %llu -t 1 -q scenes/cornell_bunny.dae "
             "-f %s/film.exr", (unsigned long long)info.seed, scratch);
    snprintf(copy, sizeof copy, "cp %s/film.exr '%s'", scratch, exr);
    sh("%s -s 9 --samples 0:1 >/dev/null && %s", render, copy);
    expect_refused(root, "samples 0:1 of 9", "bunny_normals");
    sh("%s --no-bvh >/dev/null && %s", render, copy);
    expect_refused(root, "pathlab.command", "bunny_normals");
    sh("%s -r 80 60 >/dev/null && %s", render, copy);
    expect_refused(root, "80x60", "bunny_normals");
    assert_int_equal(0, unlink(exr));
    expect_refused(root, "bunny_normals.exr: cannot read", "bunny_normals");
    /* The same render again is accepted: the refusals above were the changes'. */
    sh("%s >/dev/null && %s", render, copy);
    assert_string_equal(check(root), "");
}

/* ---- the cases ----------------------------------------------------------------------------- */

/* The course's files are edited here as JSON documents, member by member, never by their layout:
 * the release writes grading/cases.json again (one member per line), so a pattern written for the
 * repository's layout would miss there, and a student would meet a failing test they cannot fix. */

/* grading/cases.json, parsed: the caller edits it and hands it to load_doc. */
static json_t *cases_doc(void)
{
    json_error_t err;
    json_t *doc = json_load_file(GRADE_CASES, JSON_REJECT_DUPLICATES, &err);
    if (!doc) fail_msg("%s:%d: %s", GRADE_CASES, err.line, err.text);
    return doc;
}

/* The i-th part of a cases document (its "parts" array), or the test fails. */
static json_t *part_at(json_t *doc, size_t i)
{
    json_t *part = json_array_get(json_object_get(doc, "parts"), i);
    if (!part) fail_msg("%s holds no parts[%zu]", GRADE_CASES, i);
    return part;
}

/* The first case of the course's first part: every course has one. */
static json_t *first_case(json_t *doc, const char **name)
{
    json_t *c = json_array_get(json_object_get(part_at(doc, 0), "cases"), 0);
    if (!c) fail_msg("%s: the first part has no case", GRADE_CASES);
    *name = json_string_value(json_object_get(c, "name"));
    return c;
}

/* Writes doc (taken) into the scratch folder and loads it as the grader does: the error, or "". */
static const char *load_doc(json_t *doc)
{
    static pl_diag d;
    char path[128];
    snprintf(path, sizeof path, "%s/cases.json", scratch);
    assert_int_equal(0, json_dump_file(doc, path, JSON_INDENT(2)));
    json_decref(doc);
    grade_spec spec;
    d = pl_diag_default();
    if (grade_spec_load(path, NULL, &spec, &d) != PL_OK) return d.error;
    grade_spec_free(&spec);
    return "";
}

/* Fails unless error holds want. */
static void expect_error(const char *error, const char *want)
{
    if (!strstr(error, want)) fail_msg("expected an error holding '%s', got '%s'", want, error);
}

/* A misspelt or mistyped member would skip the check it asks for in silence: each is refused. */
static void test_cases__every_member_known_and_typed(void **state)
{
    (void)state;
    const char *name;
    char want[160];
    assert_string_equal(load_doc(cases_doc()), "");
    json_t *doc = cases_doc();
    json_object_set_new(first_case(doc, &name), "work_checks", json_true());
    snprintf(want, sizeof want, "case %s: unknown member \"work_checks\"", name);
    expect_error(load_doc(doc), want);
    doc = cases_doc();
    json_object_set_new(first_case(doc, &name), "samples", json_string("yes"));
    snprintf(want, sizeof want, "case %s: \"samples\" has the wrong type", name);
    expect_error(load_doc(doc), want);
    doc = cases_doc();
    json_object_set_new(part_at(doc, 0), "unit_test", json_integer(1));
    expect_error(load_doc(doc), "unknown member \"unit_test\"");
    doc = cases_doc();
    json_object_del(first_case(doc, &name), "points");
    snprintf(want, sizeof want, "case %s: expected \"points\"", name);
    expect_error(load_doc(doc), want);
    doc = cases_doc();
    json_object_set_new(first_case(doc, &name), "resolution", json_pack("[ii]", 4096, 4096));
    expect_error(load_doc(doc), "at most 2097152 pixels");
}

/* The course's parts: each once, in increasing order, numbered 1..9; hidden cases only for a part
 * the base file lists (a hidden part 9 in a course without one would be graded with no unit tests).
 * Written for any course's file: a release holds only the course's parts (COURSE_PARTS). */
static void test_cases__parts_listed_once_in_order_and_hidden_ones_listed_too(void **state)
{
    (void)state;
    json_t *doc = cases_doc();
    size_t n = json_array_size(json_object_get(doc, "parts"));
    json_object_set_new(part_at(doc, 0), "part", json_integer(0));
    expect_error(load_doc(doc), "parts[0]: expected \"part\" 1..9 (each once, in increasing order)");
    doc = cases_doc();
    json_object_set_new(part_at(doc, 0), "part", json_integer(10));
    expect_error(load_doc(doc), "parts[0]: expected \"part\" 1..9");
    if (n >= 2) {  /* the second part listed again as the first */
        doc = cases_doc();
        json_object_set(part_at(doc, 1), "part", json_object_get(part_at(doc, 0), "part"));
        expect_error(load_doc(doc), "parts[1]: expected \"part\" 1..9 (each once, in increasing order)");
    }
    /* The course's file without its last part, and hidden cases for that part. */
    char base[128], hidden[128], text[64];
    snprintf(base, sizeof base, "%s/without_last.json", scratch);
    snprintf(hidden, sizeof hidden, "%s/hidden.json", scratch);
    doc = cases_doc();
    json_int_t last = json_integer_value(json_object_get(part_at(doc, n - 1), "part"));
    assert_int_equal(0, json_array_remove(json_object_get(doc, "parts"), n - 1));
    assert_int_equal(0, json_dump_file(doc, base, 0));
    json_decref(doc);
    snprintf(text, sizeof text, "{\"parts\": [{\"part\": %d, \"cases\": []}]}\n", (int)last);
    scratch_write(hidden, text);
    grade_spec spec;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_PARSE, grade_spec_load(base, hidden, &spec, &d));
    snprintf(text, sizeof text, "part %d has hidden cases, but", (int)last);
    expect_error(d.error, text);
}

/* The tasks' shares must account for every unit point and every test: a share left out would be a
 * point nobody can earn, a test left out one that costs nothing. */
static void test_cases__task_shares_add_up_to_the_part(void **state)
{
    (void)state;
    json_t *doc = cases_doc();
    json_t *part = part_at(doc, 0);
    int n = (int)json_integer_value(json_object_get(part, "part"));
    int tests = (int)json_integer_value(json_object_get(part, "unit_tests"));
    double points = json_number_value(json_object_get(part, "unit_points"));
    json_decref(doc);
    char want[200];
    /* One more point in the first task's share. */
    doc = cases_doc();
    json_t *task = json_array_get(json_object_get(part_at(doc, 0), "unit_tasks"), 0);
    json_object_set_new(task, "points", json_real(json_number_value(json_object_get(task, "points")) + 1));
    snprintf(want, sizeof want, "part %d: the unit_tasks hold %d tests and %g points, but unit_tests is %d and unit_points %g",
             n, tests, points + 1, tests, points);
    expect_error(load_doc(doc), want);
    /* One more test in it. */
    doc = cases_doc();
    task = json_array_get(json_object_get(part_at(doc, 0), "unit_tasks"), 0);
    json_object_set_new(task, "tests", json_integer(json_integer_value(json_object_get(task, "tests")) + 1));
    snprintf(want, sizeof want, "part %d: the unit_tasks hold %d tests", n, tests + 1);
    expect_error(load_doc(doc), want);
    /* A task that matches no test name. */
    doc = cases_doc();
    task = json_array_get(json_object_get(part_at(doc, 0), "unit_tasks"), 0);
    json_object_set_new(task, "match", json_array());
    snprintf(want, sizeof want, "part %d: unit_tasks[0]: expected", n);
    expect_error(load_doc(doc), want);
}

/* A task's share is earned whole or not at all, and a suite that could not be judged earns nothing. */
static void test_score__a_task_earns_its_share_when_all_its_tests_pass(void **state)
{
    (void)state;
    grade_spec spec;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, grade_spec_load(GRADE_CASES, NULL, &spec, &d));
    const grade_part_spec *p = &spec.parts[2];
    assert_int_equal(0, grade_spec_task_of(p, "test_bsdf_f__is_albedo_over_pi"));
    assert_int_equal(1, grade_spec_task_of(p, "test_bsdf_sample_f__matches_bsdf_pdf"));
    assert_int_equal(-1, grade_spec_task_of(p, "test_something_else"));
    grade_result *res = grade_result_new();
    assert_non_null(res);
    grade_part_result *r = &res->parts[0];
    r->build.built = r->suite.judged = true;
    /* Every test of every task passes, but one of task 3.2's: that task's share alone is lost. */
    for (int t = 0; t < p->num_tasks; t++)
        for (int k = 0; k < p->tasks[t].tests; k++) {
            char name[96];
            snprintf(name, sizeof name, "test_%s%d", p->tasks[t].match[0], k);
            assert_non_null(grade_suite_note(&r->suite, name, !(t == 1 && k == 0)));
        }
    r->suite.run = p->unit_tests;
    r->suite.failed = 1;
    grade_score_part(p, r);
    assert_float_equal(p->unit_points - p->tasks[1].points, r->unit_score, 1e-12);
    assert_float_equal(0.0, r->task_score[1], 0.0);
    assert_int_equal(p->tasks[1].tests - 1, r->task_passed[1]);
    /* A task with a test missing earns nothing, even if the ones there passed. */
    r->suite.num_tests--;
    r->suite.tests[p->tasks[0].tests].passed = true;  /* task 3.2 whole again */
    grade_score_part(p, r);
    assert_float_equal(0.0, r->task_score[p->num_tasks - 1], 0.0);
    /* A suite that could not be judged: nothing. */
    r->suite.judged = false;
    r->suite.why = grade_why_of(GRADE_WHY_SUITE_NO_RESULTS);
    grade_score_part(p, r);
    assert_float_equal(0.0, r->unit_score, 0.0);
    grade_result_free(res);
    grade_spec_free(&spec);
}

/* A bug that makes every render of a part wrong loses at least half of the part: its image cases
 * (public and, where this tree has them, hidden) are worth at least its unit points. */
static void test_cases__image_cases_weigh_at_least_the_unit_tests(void **state)
{
    (void)state;
    if (access(GRADE_HIDDEN_CASES, R_OK) != 0) {  /* a student's tree: the hidden cases are the course's */
        printf("no %s here: the course's tree checks this\n", GRADE_HIDDEN_CASES);
        skip();
    }
    grade_spec spec;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, grade_spec_load(GRADE_CASES, GRADE_HIDDEN_CASES, &spec, &d));
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        double images = 0.0;
        for (int i = 0; i < spec.parts[k].num_cases; i++) images += spec.parts[k].cases[i].points;
        if (images < spec.parts[k].unit_points)
            fail_msg("part %d: image cases worth %g, unit tests %g: a bug that breaks every render would lose less "
                     "than half the part", k + 1, images, spec.parts[k].unit_points);
    }
    grade_spec_free(&spec);
}

/* Each handout's grading table is grading/cases.json's, generated: they never drift apart. */
static void test_handout__grading_tables_are_the_cases_files(void **state)
{
    (void)state;
    grade_spec spec;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, grade_spec_load(GRADE_CASES, NULL, &spec, &d));
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        char path[64], folder[256];
        /* The course's parts only: a release may leave out a part cases.json lists (COURSE_PARTS). */
        if (spec.parts[k].part != k + 1 || !grade_plan_part_folder(".", k + 1, folder, sizeof folder)) continue;
        grade_plan_handout(k + 1, path, sizeof path);
        if (grade_handout_update(path, &spec.parts[k], false, &d) != PL_OK) fail_msg("%s", d.error);
    }
    grade_spec_free(&spec);
}

/* ---- the suite's results ------------------------------------------------------------------- */

static void suite_file(const char *dir, const char *name, const char *body)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    scratch_write(path, body);
}

/* A suite's facts with room for its tests (grade_result_new's, one part's). */
static grade_test_fact tests_room[GRADE_MAX_TESTS];

static bool read_dir(const char *name, const char *file, const char *body, grade_suite_facts *r, char *why)
{
    char dir[256];
    snprintf(dir, sizeof dir, "%s/%s", scratch, name);
    assert_int_equal(0, mkdir(dir, 0755));
    suite_file(dir, file, body);
    memset(r, 0, sizeof *r);
    r->tests = tests_room;
    return grade_suite_read(dir, NULL, 1, r, why, 200);
}

/* The message of the test named `name` in r, or NULL. */
static const char *message_of(const grade_suite_facts *r, const char *name)
{
    for (int i = 0; i < r->num_tests; i++)
        if (!strcmp(r->tests[i].name, name)) return r->tests[i].message;
    return NULL;
}

/* The names of r's failed tests in order, "a b c". */
static const char *failed_names(const grade_suite_facts *r)
{
    static char out[512];
    size_t n = 0;
    out[0] = '\0';
    for (int i = 0; i < r->num_tests; i++)
        if (!r->tests[i].passed) n += (size_t)snprintf(out + n, sizeof out - n, "%s%s", n ? " " : "", r->tests[i].name);
    return out;
}

static void test_suite__every_testcase_counted_and_skipped_is_not_passed(void **state)
{
    (void)state;
    grade_suite_facts r;
    char why[200] = "";
    /* A testcase nested in another element, and a skipped one: both counted, the skipped failed. */
    assert_true(read_dir("nested", "part1: g.xml",
                         "<testsuites><testsuite name=\"part1: g\" tests=\"3\" failures=\"0\" errors=\"0\" skipped=\"1\">"
                         "<testcase name=\"a\"/><x><testcase name=\"b\"><failure>no</failure></testcase></x>"
                         "<testcase name=\"c\"><skipped/></testcase></testsuite></testsuites>", &r, why) == false);
    assert_non_null(strstr(why, "tests=3 failures=0 errors=0 skipped=1, but it holds 3 tests of which 2 did not pass"));
    assert_true(read_dir("counted", "part1: g.xml",
                         "<testsuites><testsuite name=\"part1: g\" tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\">"
                         "<testcase name=\"a\"/><x><testcase name=\"b\"><failure>no</failure></testcase></x>"
                         "<testcase name=\"c\"><skipped/></testcase></testsuite></testsuites>", &r, why));
    assert_int_equal(r.run, 3);
    assert_int_equal(r.failed, 2);
    assert_non_null(message_of(&r, "c"));
    assert_non_null(strstr(message_of(&r, "c"), "skipped"));
    /* tests= that does not match what is there. */
    assert_false(read_dir("claims", "part1: g.xml",
                          "<testsuites><testsuite name=\"part1: g\" tests=\"9\" failures=\"0\" errors=\"0\">"
                          "<testcase name=\"a\"/></testsuite></testsuites>", &r, why));
    assert_non_null(strstr(why, "tests=9"));
}

static void test_suite__only_the_files_the_suite_writes(void **state)
{
    (void)state;
    grade_suite_facts r;
    char why[200] = "";
    static const char *const good = "<testsuites><testsuite name=\"part1: g\" tests=\"1\" failures=\"0\" errors=\"0\">"
                                    "<testcase name=\"a\"/></testsuite></testsuites>";
    assert_false(read_dir("name_xml", "results.xml.bak", good, &r, why));
    assert_non_null(strstr(why, "results.xml.bak: the suite writes 'part1: <group>.xml' files only"));
    assert_false(read_dir("other_part", "part2: g.xml", good, &r, why));
    assert_false(read_dir("renamed", "part1: h.xml", good, &r, why));
    assert_non_null(strstr(why, "expected one <testsuite name="));
    assert_true(read_dir("good", "part1: g.xml", good, &r, why));
    assert_int_equal(r.run, 1);
}

/* The groups' files are counted in the suite's order (its list), not the folder's: three groups whose
 * names sort the other way round, each with one failed test, are listed c, b, a as the list says;
 * without a list, by file name. */
static void test_suite__failures_in_the_suites_order(void **state)
{
    (void)state;
    char dir[256], why[200] = "", body[512];
    snprintf(dir, sizeof dir, "%s/%s", scratch, "ordered");
    assert_int_equal(0, mkdir(dir, 0755));
    const char *groups[] = {"a", "b", "c"};
    for (int g = 0; g < 3; g++) {
        char file[32];
        snprintf(file, sizeof file, "part1: %s.xml", groups[g]);
        snprintf(body, sizeof body, "<testsuites><testsuite name=\"part1: %s\" tests=\"2\" failures=\"1\" errors=\"0\">"
                 "<testcase name=\"test_%s_ok\"/><testcase name=\"test_%s_bad\"><failure>wrong</failure></testcase>"
                 "</testsuite></testsuites>", groups[g], groups[g], groups[g]);
        suite_file(dir, file, body);
    }
    grade_test_list order = {.count = 6};
    const char *names[] = {"test_c_ok", "test_c_bad", "test_b_ok", "test_b_bad", "test_a_ok", "test_a_bad"};
    for (int i = 0; i < 6; i++) snprintf(order.names[i], sizeof order.names[i], "%s", names[i]);
    grade_suite_facts r = {.tests = tests_room};
    assert_true(grade_suite_read(dir, &order, 1, &r, why, sizeof why));
    assert_int_equal(r.failed, 3);
    assert_string_equal(failed_names(&r), "test_c_bad test_b_bad test_a_bad");
    assert_string_equal(message_of(&r, "test_a_bad"), "wrong");
    r = (grade_suite_facts){.tests = tests_room};
    assert_true(grade_suite_read(dir, NULL, 1, &r, why, sizeof why));
    assert_string_equal(failed_names(&r), "test_a_bad test_b_bad test_c_bad");
}

/* A message cut at 700 bytes never splits a character (a 3-byte one straddles the cut here). */
static void test_suite__a_long_message_is_cut_between_characters(void **state)
{
    (void)state;
    char body[2048], why[200] = "";
    grade_suite_facts r;
    int n = snprintf(body, sizeof body, "<testsuites><testsuite name=\"part1: g\" tests=\"1\" failures=\"1\" errors=\"0\">"
                     "<testcase name=\"a\"><failure>");
    memset(body + n, 'x', 699);
    snprintf(body + n + 699, sizeof body - n - 699, "\xe2\x82\xac tail</failure></testcase></testsuite></testsuites>");
    assert_true(read_dir("cut", "part1: g.xml", body, &r, why));
    const char *msg = message_of(&r, "a");
    assert_non_null(msg);
    assert_true(strlen(msg) >= 690 && msg[strlen(msg) - 1] == 'x');
    assert_null(strstr(msg, "\xe2"));
}

/* ---- the grader's two ways to format into a fixed buffer (grade_fmt.c) ----------------------- */

/* A path that does not fit is refused, never cut (a cut path names another file); a message is
 * cut with "..." on a character boundary, however the cut falls in a multi-byte character. */
static void test_fmt__a_long_path_is_refused_a_long_message_cut_between_characters(void **state)
{
    (void)state;
    char path[16];
    assert_true(grade_path(path, sizeof path, "%s/%s", "work", "part1"));
    assert_string_equal(path, "work/part1");
    assert_false(grade_path(path, sizeof path, "%s/%s", "work", "part1/tree/bin"));
    assert_string_equal(path, "");
    for (int shift = 0; shift < 4; shift++) {
        char msg[12], text[64];
        /* shift ASCII bytes, then 4-byte characters (U+1F600): the cut lands at each byte of one. */
        snprintf(text, sizeof text, "%.*s%s", shift, "abc", "\xf0\x9f\x98\x80\xf0\x9f\x98\x80\xf0\x9f\x98\x80");
        grade_msg(msg, sizeof msg, "%s", text);
        size_t len = strlen(msg);
        assert_true(len >= 3 && !strcmp(msg + len - 3, "..."));
        assert_int_equal(utf8_valid_prefix(msg, len), len);
    }
    char whole[12];
    grade_msg(whole, sizeof whole, "%s", "fits");
    assert_string_equal(whole, "fits");
}

/* ---- the grader's own memory ---------------------------------------------------------------- */

/* A grading run ends normally: exit 0 (full marks) or 1 (a student's tree with stubs), its
 * results.json written; in the sanitizer build (make test SAN=1: bin/san/grade) with leak detection
 * on and any report made exit 86, so a leak fails it (each graded case once leaked its verdict's
 * 180-byte t map). */
static void test_grade__a_run_ends_cleanly_with_leak_detection(void **state)
{
    (void)state;
#ifdef __SANITIZE_ADDRESS__
    const char *grade = "ASAN_OPTIONS=detect_leaks=1:exitcode=86 bin/san/grade";
#else
    const char *grade = "bin/grade";
#endif
    char cmd[512], results[128];
    /* Without this suite's FILTER, which the graded suite would inherit and stop early on. */
    snprintf(cmd, sizeof cmd, "env -u PL_TEST_FILTER -u PL_TEST_LIST -u PL_TEST_MATCHED %s --parts 1 --seed 1 --out "
             "%s/grade >%s/grade.log 2>&1", grade, scratch, scratch);
    int status = system(cmd), code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    snprintf(results, sizeof results, "%s/grade/results.json", scratch);
    if ((code != 0 && code != 1) || access(results, F_OK) != 0) {
        snprintf(cmd, sizeof cmd, "tail -20 %s/grade.log", scratch);
        assert_int_equal(0, system(cmd));
        fail_msg("%s exited with %d (its output above)", grade, code);
    }
}

int readers_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refs__the_course_references_pass),
        cmocka_unit_test(test_refs__the_json_a_check_needs_is_required),
        cmocka_unit_test(test_refs__the_film_must_be_the_cases),
        cmocka_unit_test(test_cases__every_member_known_and_typed),
        cmocka_unit_test(test_cases__parts_listed_once_in_order_and_hidden_ones_listed_too),
        cmocka_unit_test(test_cases__task_shares_add_up_to_the_part),
        cmocka_unit_test(test_score__a_task_earns_its_share_when_all_its_tests_pass),
        cmocka_unit_test(test_cases__image_cases_weigh_at_least_the_unit_tests),
        cmocka_unit_test(test_handout__grading_tables_are_the_cases_files),
        cmocka_unit_test(test_suite__every_testcase_counted_and_skipped_is_not_passed),
        cmocka_unit_test(test_suite__only_the_files_the_suite_writes),
        cmocka_unit_test(test_suite__a_long_message_is_cut_between_characters),
        cmocka_unit_test(test_suite__failures_in_the_suites_order),
        cmocka_unit_test(test_fmt__a_long_path_is_refused_a_long_message_cut_between_characters),
        cmocka_unit_test(test_grade__a_run_ends_cleanly_with_leak_detection),
    };
    return cmocka_run_group_tests_name("grader readers: references, cases, suite results, the score", tests, scratch_setup,
                                       scratch_teardown);
}
