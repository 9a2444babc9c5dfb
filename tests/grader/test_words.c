/* Test machinery: not part of any assignment. What the grader writes, from a grading's facts: the
 * words (grader/grade_words.c), results.json and the report (grade_report.c), facts.json
 * (grade_facts.c). Each fact is planted here as a forged render or a hostile submission would
 * choose it: no entry is lost to bytes that are not UTF-8, no markup a submission plants survives a
 * course platform's Markdown, and a stopped render is named by the framework's reason, never by
 * its bytes. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_facts.h"
#include "../../grader/grade_fmt.h"
#include "../../grader/grade_render.h"
#include "../../grader/grade_report.h"
#include "../../grader/grade_result.h"
#include "../../grader/grade_suite.h"
#include "../../grader/grade_words.h"
#include <cmark.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

SCRATCH_FOLDER(scratch, "words-test")

/* ---- a stopped render -------------------------------------------------------------------------- */

/* What the words say of a render whose log holds text. */
static const char *log_reason_of(const char *text)
{
    static char why[512];
    char path[256];
    snprintf(path, sizeof path, "%s/render.log", scratch);
    scratch_write(path, text);
    grade_why w = grade_render_log_reason(path);
    grade_words_why(&w, 2, "part2_bvh", why, sizeof why);
    return why;
}

/* A render that stopped says why in the grader's words: the framework's reason selects a fixed
 * sentence, and nothing of the log (the render's own output) is copied into it. */
static void test_words__a_stopped_render_names_the_framework_reason_without_its_bytes(void **state)
{
    (void)state;
    const char *why = log_reason_of("pathtracer: SECRET-42 bvh_build made a malformed tree: node 7: leaf holds 9 "
                                    "primitives, max_leaf_size is 4 SECRET-43\n");
    assert_non_null(strstr(why, "a leaf holds more primitives than the leaf size allows"));
    assert_null(strstr(why, "SECRET"));
    assert_null(strstr(why, "7"));
    assert_non_null(strstr(log_reason_of("pathtracer: bvh_build made a malformed tree: node 3: a child box (node 4 or 5) "
                                         "pokes out of it\n"), "a child's box pokes out of its parent's"));
    assert_non_null(strstr(log_reason_of("pathtracer: bvh_build made a malformed tree: node 2: child 9 >= num_nodes 5\n"),
                           "a child's index is not a node of the tree"));
    assert_non_null(strstr(log_reason_of("bvh_build is not implemented yet\n"), "still a stub"));
    assert_string_equal(log_reason_of("anything the render chose to print\n"), "");
}

/* Every why the grader can record has words, and none of them is empty: a student is never told
 * "0 points:" and nothing after it. */
static void test_words__every_why_has_words(void **state)
{
    (void)state;
    for (int code = GRADE_WHY_NONE + 1; code < GRADE_WHY_CODES; code++) {
        grade_why w = grade_why_of((grade_why_code)code);
        snprintf(w.file, sizeof w.file, "bvh.c");
        snprintf(w.detail, sizeof w.detail, "a detail");
        w.step = GRADE_STEP_COMPILE;
        char out[1024];
        grade_words_why(&w, 2, "part2_bvh", out, sizeof out);
        if (strlen(out) < 10) fail_msg("why code %d has no words (\"%s\")", code, out);
    }
}

/* ---- a case's verdict ------------------------------------------------------------------------- */

/* A verdict that failed in one block, with no bad pixel and no factor: its words name the block and
 * its t (rounded), then the hint, once. */
static void test_words__a_block_that_differs_is_named_with_its_t(void **state)
{
    (void)state;
    static grade_case k = {.name = "one_block", .width = 160, .height = 120, .samples = 16};
    static grade_case_result c;
    memset(&c, 0, sizeof c);
    c.spec = &k, c.ran = true;
    c.v.p_value = 1e-9, c.v.alpha = 1e-3, c.v.rel_mse = 0.1;
    c.v.ratio[0] = c.v.ratio[1] = c.v.ratio[2] = 1.01;
    c.v.blocks_x = 10, c.v.blocks_y = 7;
    c.v.worst_block_x = 3, c.v.worst_block_y = 4, c.v.worst_channel = 1, c.v.worst_t = -6.283185307179586;
    snprintf(c.v.hint, sizeof c.v.hint, "a hint of the verdict's");
    char text[4096];
    grade_words_case(&c, 1, "part1_raytrace", text, sizeof text);
    print_message("%s\n", text);
    assert_non_null(strstr(text, "Most different: the green channel of block (3, 4) from the top-left (t = -6.28: darker"));
    assert_null(strstr(text, "6.283"));
    assert_non_null(strstr(text, "Hint: a hint of the verdict's."));
    assert_null(strstr(strstr(text, "Hint:") + 1, "Hint:"));
    /* The one-line cause (make grade's) names the block too, and leaves the hint to its own line. */
    grade_words_case_cause(&c, 1, "part1_raytrace", text, sizeof text);
    assert_non_null(strstr(text, "block (3, 4)"));
    assert_null(strstr(text, "Hint"));
}

/* A failed verdict whose differing blocks do not agree on one factor: most of the image (a constant
 * missing on every surface but the lights) is said as the whole image, a few blocks as a region. */
static void test_words__most_of_the_image_is_the_whole_image_a_few_blocks_a_region(void **state)
{
    (void)state;
    static grade_case k = {.name = "regions", .width = 160, .height = 120, .samples = 16};
    static grade_case_result c;
    memset(&c, 0, sizeof c);
    c.spec = &k, c.ran = true;
    c.v.p_value = 0.0, c.v.alpha = 1e-4;
    c.v.ratio[0] = c.v.ratio[1] = c.v.ratio[2] = 1.8;
    c.v.blocks_x = 10, c.v.blocks_y = 7, c.v.worst_block_x = 1, c.v.worst_block_y = 1;
    c.v.region_blocks = 63, c.v.region_ratio = 2.2;
    c.v.region_x0 = 0, c.v.region_x1 = 9, c.v.region_y0 = 0, c.v.region_y1 = 6;
    char text[4096];
    grade_words_case_cause(&c, 3, "part3_direct", text, sizeof text);
    assert_non_null(strstr(text, "The whole image is too bright, but not by one factor: 63 of its 70 blocks"));
    c.v.region_blocks = 6, c.v.region_ratio = 0.5;
    c.v.region_x0 = 2, c.v.region_x1 = 4, c.v.region_y0 = 3, c.v.region_y1 = 4;
    grade_words_case_cause(&c, 3, "part3_direct", text, sizeof text);
    assert_non_null(strstr(text, "The image differs in a region: 6 of its 70 blocks, within x = 32..79 and y = 35..68"));
    assert_non_null(strstr(text, "0.5 times the reference's brightness"));
}

/* ---- facts.json ------------------------------------------------------------------------------ */

/* facts.json names each failure's cause by its stable code, for the class report: a stub, a known
 * factor, an image off overall, a figure off on a matching image, and a part that did not build. */
static void test_facts__each_failure_has_its_cause(void **state)
{
    (void)state;
    grade_result *res = grade_result_new();
    static grade_case cases[5];
    assert_non_null(res);
    res->num_parts = 2;
    grade_part_result *p = &res->parts[0], *q = &res->parts[1];
    p->part = 3, p->build.built = true, p->suite.judged = true, p->num_cases = 5;
    for (int i = 0; i < 5; i++) {
        snprintf(cases[i].name, sizeof cases[i].name, "case%d", i);
        cases[i].points = 1;
        p->cases[i].spec = &cases[i];
        p->cases[i].v.ratio[0] = p->cases[i].v.ratio[1] = p->cases[i].v.ratio[2] = 1.0;
    }
    p->cases[0].why = grade_why_of(GRADE_WHY_RENDER_STUB);
    p->cases[1].ran = true, p->cases[1].v.hint_code = "factor_1/pi";
    p->cases[2].ran = true, p->cases[2].v.ratio[0] = p->cases[2].v.ratio[1] = p->cases[2].v.ratio[2] = 0.5;
    p->cases[3].ran = true, p->cases[3].v.pass = true, cases[3].noise_check = true, p->cases[3].noise = 2.0;
    p->cases[4].ran = true, p->cases[4].pass = true, p->cases[4].v.pass = true;
    q->part = 4, q->build.built = false;
    q->build.why = grade_why_of(GRADE_WHY_BUILD_FAILS);
    q->build.why.step = GRADE_STEP_COMPILE;
    snprintf(q->build.why.file, sizeof q->build.why.file, "x.c");
    static const char *const want[5] = {"stub", "factor_1/pi", "too_dark", "noisier", NULL};
    const char *words;
    for (int i = 0; i < 5; i++) {
        const char *got = grade_facts_case_cause(p, &p->cases[i], &words);
        if (want[i] ? !got || strcmp(got, want[i]) : got != NULL)
            fail_msg("case %d: expected cause %s, got %s", i, want[i] ? want[i] : "none", got ? got : "none");
    }
    assert_string_equal(grade_facts_unit_cause(q), "not_built");
    char path[256];
    pl_diag d = pl_diag_default();
    snprintf(path, sizeof path, "%s/facts.json", scratch);
    assert_int_equal(PL_OK, grade_facts_write(res, path, &d));
    json_error_t err;
    json_t *j = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    assert_non_null(j);
    assert_string_equal(json_string_value(json_object_get(j, "schema")), GRADE_FACTS_SCHEMA);
    json_t *parts = json_object_get(j, "parts");
    json_t *c1 = json_array_get(json_object_get(json_array_get(parts, 0), "cases"), 1);
    assert_string_equal(json_string_value(json_object_get(c1, "cause")), "factor_1/pi");
    assert_string_equal(json_string_value(json_object_get(c1, "cause_words")), "too dark by 1/pi");
    const char *reason = json_string_value(json_object_get(json_array_get(parts, 1), "suite_reason"));
    assert_non_null(reason);
    assert_non_null(strstr(reason, "part 4 does not compile: x.c"));
    json_decref(j);
    grade_result_free(res);
}

/* ---- results.json --------------------------------------------------------------------------- */

/* Every part's entries are present, whatever bytes the messages hold. Before, one invalid byte in a
 * part's failures made jansson refuse its entry, and results.json silently lacked it. */
static void test_report__every_entry_present_for_hostile_messages(void **state)
{
    (void)state;
    grade_result *res = grade_result_new();
    enum { PARTS = 5 };
    static grade_case cases[PARTS];
    assert_non_null(res);
    static const char *const hostile[] = {"bad byte \xff here", "cut \xe2\x82", "\xc0\xaf overlong", "surrogate \xed\xa0\x80",
                                          "quote \" backslash \\ control \x01"};
    res->num_parts = PARTS;
    for (int p = 0; p < PARTS; p++) {
        grade_part_result *r = &res->parts[p];
        r->part = p + 1;
        r->build.built = true;
        r->suite.judged = p % 2 == 0;  /* an odd part's suite could not be judged, for a course's reason */
        r->suite.run = 3, r->suite.failed = 1;
        grade_test_fact *t = grade_suite_note(&r->suite, "t", false);
        snprintf(t->message, sizeof t->message, "%s", hostile[p]);
        r->suite.why = grade_why_of(GRADE_WHY_COURSE);
        snprintf(r->suite.why.detail, sizeof r->suite.why.detail, "%s", hostile[(p + 1) % 5]);
        snprintf(cases[p].name, sizeof cases[p].name, "case%d", p + 1);
        r->num_cases = 1;
        r->cases[0].spec = &cases[p];
        r->cases[0].why = grade_why_of(GRADE_WHY_FILM_UNUSABLE);
        snprintf(r->cases[0].why.detail, sizeof r->cases[0].why.detail, "%s", hostile[(p + 2) % 5]);
    }
    char path[256];
    pl_diag d = pl_diag_default();
    snprintf(path, sizeof path, "%s/results.json", scratch);
    assert_int_equal(PL_OK, grade_report_results_json(res, path, &d));
    json_error_t err;
    json_t *j = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    assert_non_null(j);
    json_t *tests = json_object_get(j, "tests");
    assert_int_equal(json_array_size(tests), 2 * PARTS);
    for (int p = 0; p < PARTS; p++) {
        char unit[64], image_name[64];
        snprintf(unit, sizeof unit, "Part %d: unit tests", p + 1);
        snprintf(image_name, sizeof image_name, "Part %d: image case%d", p + 1, p + 1);
        bool has_unit = false, has_image = false;
        for (size_t i = 0; i < json_array_size(tests); i++) {
            const char *name = json_string_value(json_object_get(json_array_get(tests, i), "name"));
            has_unit = has_unit || (name && !strcmp(name, unit));
            has_image = has_image || (name && !strcmp(name, image_name));
        }
        if (!has_unit || !has_image) fail_msg("results.json lacks '%s' or '%s'", unit, image_name);
    }
    /* The message, its bad byte shown as \xff (utf8_sanitize). */
    assert_non_null(strstr(json_string_value(json_object_get(json_array_get(tests, 0), "output")), "bad byte \\xff here"));
    json_decref(j);
    assert_int_equal(PL_OK, grade_report_html(res, scratch, &d));
    grade_result_free(res);
}

/* Markup planted in every field of results.json a submission can influence (the compiler's lines
 * about its files, a test's message, the framework's words about a film, a course file's error)
 * shows as text once a course platform renders it: each "output" is rendered with CommonMark's
 * reference library, and no tag, link, image, heading, emphasis or entity of the plant survives. */
static const char *const planted[] = {
    "<img src=x onerror=alert(1)>", "<script>alert(2)</script>", "[click](javascript:alert(3))", "![i](http://x/y.png)",
    "**bold** __strong__ *em* _em_", "`code` ``` fence", "&lt;entity&gt; &amp;", "# heading", "| a | b |\n|---|---|",
    "~~strike~~", "<http://autolink.example>", "line\n- list item\n1. numbered", "\\*escaped\\*", "> quote"};

static void test_report__no_markup_a_submission_plants_survives(void **state)
{
    (void)state;
    grade_result *res = grade_result_new();
    static grade_case cases[2];
    static char joined[2048];
    assert_non_null(res);
    size_t n = 0;
    for (size_t i = 0; i < sizeof planted / sizeof planted[0]; i++)
        n += (size_t)snprintf(joined + n, sizeof joined - n, "%s ", planted[i]);
    res->num_parts = 2;
    grade_part_result *built = &res->parts[0], *refused = &res->parts[1];
    /* A failed test's message, as the suite reader keeps it (raw: the words escape it). */
    char dir[256], file[300], body[4096], why[200];
    snprintf(dir, sizeof dir, "%s/markup", scratch);
    assert_int_equal(0, mkdir(dir, 0755));
    snprintf(file, sizeof file, "%s/part1: g.xml", dir);
    snprintf(body, sizeof body, "<testsuites><testsuite name=\"part1: g\" tests=\"1\" failures=\"1\" errors=\"0\">"
             "<testcase name=\"test_x\"><failure><![CDATA[%s]]></failure></testcase></testsuite></testsuites>", joined);
    scratch_write(file, body);
    assert_true(grade_suite_read(dir, NULL, 1, &built->suite, why, sizeof why));
    built->part = 1, built->build.built = true, built->suite.judged = true, built->num_cases = 1;
    snprintf(cases[0].name, sizeof cases[0].name, "case_a");
    built->cases[0].spec = &cases[0];
    built->cases[0].why = grade_why_of(GRADE_WHY_FILM_UNUSABLE);
    grade_msg(built->cases[0].why.detail, sizeof built->cases[0].why.detail, "%s", joined);
    refused->part = 2, refused->num_cases = 1;
    refused->build.why = grade_why_of(GRADE_WHY_COURSE);
    grade_msg(refused->build.why.detail, sizeof refused->build.why.detail, "%s", joined);
    grade_msg(refused->build.diagnostics, sizeof refused->build.diagnostics, "x.c:1: error: %s\n```\n%s", joined, joined);
    snprintf(cases[1].name, sizeof cases[1].name, "case_b");
    cases[1].hidden = true;
    refused->cases[0].spec = &cases[1];
    refused->cases[0].why = grade_why_of(GRADE_WHY_COURSE);
    grade_msg(refused->cases[0].why.detail, sizeof refused->cases[0].why.detail, "%s", joined);
    char path[256];
    pl_diag d = pl_diag_default();
    snprintf(path, sizeof path, "%s/markup.json", scratch);
    assert_int_equal(PL_OK, grade_report_results_json(res, path, &d));
    json_t *j = json_load_file(path, 0, NULL);
    json_t *tests = json_object_get(j, "tests");
    assert_int_equal(4, json_array_size(tests));
    /* (A literal "&lt;" renders "&amp;lt;"; an entity that survived would render "&lt;".) */
    static const char *const survivors[] = {"<img", "<script", "<a ", "<h1", "<h2", "<table", "<del", "<em", "<blockquote",
                                            "<ol", "&lt;entity", "onerror=alert(1)>"};
    for (size_t i = 0; i < json_array_size(tests); i++) {
        const char *md = json_string_value(json_object_get(json_array_get(tests, i), "output"));
        char *html = cmark_markdown_to_html(md, strlen(md), CMARK_OPT_DEFAULT);
        for (size_t k = 0; k < sizeof survivors / sizeof survivors[0]; k++)
            if (strstr(html, survivors[k]))
                fail_msg("results.json's entry %zu renders planted markup (%s):\n%s", i, survivors[k], html);
        /* The planted text is there, as text (a reason planted whole shows whole). */
        if (!strstr(html, "alert(1)")) fail_msg("entry %zu lost the planted text:\n%s", i, html);
        free(html);
    }
    json_decref(j);
    grade_result_free(res);
}

int words_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_words__a_stopped_render_names_the_framework_reason_without_its_bytes),
        cmocka_unit_test(test_words__every_why_has_words),
        cmocka_unit_test(test_words__a_block_that_differs_is_named_with_its_t),
        cmocka_unit_test(test_words__most_of_the_image_is_the_whole_image_a_few_blocks_a_region),
        cmocka_unit_test(test_facts__each_failure_has_its_cause),
        cmocka_unit_test(test_report__every_entry_present_for_hostile_messages),
        cmocka_unit_test(test_report__no_markup_a_submission_plants_survives),
    };
    return cmocka_run_group_tests_name("grader words: results.json, the report, facts.json", tests, scratch_setup,
                                       scratch_teardown);
}
