/* Test machinery: not part of any assignment.
 * The grader's containment, each audit finding with its proof:
 * - the allow-list refuses the framework's files, images and counter resets, not only libc's exit;
 * - a suite's XML scores only when it holds exactly the tests the suite has (an early _exit does not);
 * - a child's log is the grader's own fresh file: a planted symlink is never followed, and a flood
 *   is cut at its cap while the child runs;
 * - untrusted children always have a process limit, and the report names what is missing;
 * - as root, a child running as nobody cannot open a reference, a hidden case or the results;
 * - a failed build's message is its last lines. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../grader/grade_allow.h"
#include "../../grader/grade_plan.h"
#include "../../grader/grade_result.h"
#include "../../grader/grade_run.h"
#include "../../grader/grade_score.h"
#include "../../grader/grade_suite.h"
#include "../../grader/grade_words.h"
#include "../../grader/grade_guard.h"
#include "../../grader/grade_inspect.h"
#include "../../grader/grade_diag.h"
#include "../../framework/output.h"
#include <fcntl.h>
#include <math.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A scratch folder every user may enter (the nobody child must reach what it is refused, or the
 * test would prove only that /tmp/xxx is private). */
static char scratch[64];

static int make_scratch(void **state)
{
    (void)state;
    if (scratch_make(scratch, sizeof scratch, "grade-test") != 0) return -1;
    grade_sandbox_probe();
    return 0;
}

static int remove_scratch(void **state)
{
    (void)state;
    return scratch_remove(scratch);
}

static long file_size(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* This machine's sandbox, as a grading probes it (its folder: the scratch one). */
static const grade_sandbox *the_sandbox(void)
{
    static grade_sandbox s;
    static bool probed;
    if (!probed) {
        s = grade_sandbox_probe();
        grade_sandbox_keep(&s, scratch);
        probed = true;
    }
    return &s;
}

/* Runs sh -c script as the grader runs the compiler on student files (the sandbox's user and limits;
 * no filter, which would stop the shell's fork); its exit status (-1: did not exit). */
static int run_untrusted(const char *script, const char *log)
{
    char *argv[] = {"sh", "-c", (char *)script, NULL};
    grade_run_opts o = {.wall_seconds = 30, .cwd = scratch, .log_path = log, .log_max = 4096, .untrusted = true,
                        .compiler = true, .sandbox = the_sandbox()};
    grade_run_result r = grade_run(argv, &o);
    return r.exited ? r.status : -1;
}

/* A protection the test needs that this machine does not give: say so, and skip the test. */
static bool skipped_unless(bool available, const char *what, const char *why)
{
    if (!available) printf("  (skipped: %s: %s)\n", what, why);
    return !available;
}

/* The first line a child printed into its log (the test fails when there is none). */
static void first_line(const char *log, char *text, int size)
{
    FILE *f = fopen(log, "r");
    assert_non_null(f);
    bool got = fgets(text, size, f) != NULL;
    fclose(f);
    if (!got) fail_msg("%s is empty: the child printed nothing", log);
}

/* ---- the allow-list ------------------------------------------------------------------------ */

static void test_allowlist__framework_api_only(void **state)
{
    (void)state;
    static const char *const allowed[] = {"rng_uniform", "sample_cosine_hemisphere_pdf", "scene_prim_intersect",
                                          "render_intersect", "light_sample_L", "pl_todo_report", "mat4_point",
                                          "sqrtf", "tan", "memcpy", "malloc", "qsort", "printf",
                                          /* maths in every precision: a part in long double is correct */
                                          "sqrtl", "fabsl", "powl", "ceill", "sincosl", NULL};
    static const char *const refused[] = {"exr_read", "exr_write", "file_write_atomic", "file_read_all",
                                          "image_write_png", "image_read", "counters_take", "counters_add_visit",
                                          "counters_add_prim", "counters_trace_begin", "pl_todo_reset", "dae_load",
                                          "render_film", "system", "fopen", "exit", "_exit", "fork", "getenv",
                                          "syscall", "systeml", "exitl", "fopenf", NULL};
    for (const char *const *s = allowed; *s; s++)
        if (!grade_allow_has(*s)) fail_msg("the allow-list refuses %s, which part code needs", *s);
    for (const char *const *s = refused; *s; s++)
        if (grade_allow_has(*s)) fail_msg("the allow-list accepts %s", *s);
}

/* ---- the suite's results ------------------------------------------------------------------- */

/* dir/name.xml holding `tests` test cases, `failed` of them failed, as cmocka writes them. */
static void write_suite_xml(const char *dir, const char *name, int tests, int failed)
{
    char path[256];
    snprintf(path, sizeof path, "%s/part1: %s.xml", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<testsuites>\n<testsuite name=\"part1: %s\" tests=\"%d\" "
            "failures=\"%d\" errors=\"0\" skipped=\"0\">\n", name, tests, failed);
    for (int i = 0; i < tests; i++)
        fprintf(f, "<testcase name=\"test_%s__%d\" time=\"0.0\">%s</testcase>\n", name, i,
                i < failed ? "<failure><![CDATA[it broke]]></failure>" : "");
    fprintf(f, "</testsuite>\n</testsuites>\n");
    assert_int_equal(fclose(f), 0);
}

/* The suite's results in dir, scored as grade_part scores them (10 unit points in two tasks: group
 * a's 20 tests carry 6, group b's 8 carry 4; no case). */
static void score_results(const char *dir, int status, grade_part_result *r)
{
    grade_part_spec spec = {.part = 1, .unit_points = 10.0, .unit_tests = 28, .num_tasks = 2,
                            .tasks = {{.task = "1.1", .points = 6.0, .tests = 20, .match = {"a__"}, .num_match = 1},
                                      {.task = "1.2", .points = 4.0, .tests = 8, .match = {"b__"}, .num_match = 1}}};
    static grade_test_fact room[GRADE_MAX_TESTS];
    memset(r, 0, sizeof *r);
    r->part = 1;
    r->build.built = true;
    r->suite.tests = room;
    grade_suite_results(dir, NULL, 28, status, 1, &r->suite);
    grade_score_part(&spec, r);
}

/* Why the suite earned nothing as a whole, in the report's words ("" when it was judged). */
static const char *suite_reason(const grade_part_result *r)
{
    static char words[512];
    if (!grade_words_unit_zero(r, words, sizeof words)) words[0] = '\0';
    return words;
}

static void score_dir(const char *name, grade_part_result *r)
{
    char dir[256];
    snprintf(dir, sizeof dir, "%s/%s", scratch, name);
    score_results(dir, 0, r);
}

static void test_suite_score__only_a_suite_run_to_its_end(void **state)
{
    (void)state;
    grade_part_result r;
    char dir[256];
    /* The whole suite, in two groups, one test of a failed: b's task alone earns its share. */
    snprintf(dir, sizeof dir, "%s/whole", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    write_suite_xml(dir, "a", 20, 1);
    write_suite_xml(dir, "b", 8, 0);
    score_results(dir, 1, &r);
    assert_string_equal(suite_reason(&r), "");
    assert_float_equal(4.0, r.unit_score, 0.0);

    /* An _exit(0) in the second group: its file is missing, 20 tests of 28, all passed. */
    snprintf(dir, sizeof dir, "%s/early", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    write_suite_xml(dir, "a", 21, 0);
    score_dir("early", &r);
    assert_string_equal(suite_reason(&r), "the suite stopped after 21 of 28 tests");
    assert_true(r.unit_score == 0.0);

    /* Results of its own added by the code under test: more tests than the suite has. */
    snprintf(dir, sizeof dir, "%s/extra", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    write_suite_xml(dir, "a", 28, 0);
    write_suite_xml(dir, "fake", 5, 0);
    score_dir("extra", &r);
    assert_non_null(strstr(suite_reason(&r), "reported 33 tests, but it has 28"));
    assert_true(r.unit_score == 0.0);

    /* Malformed, and a results file that is a symlink (never followed, even to a good file). */
    snprintf(dir, sizeof dir, "%s/bad", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    write_suite_xml(dir, "a", 20, 0);
    char path[300];
    snprintf(path, sizeof path, "%s/part1: b.xml", dir);
    scratch_write(path, "<testsuites><testsuite><testcase name=");
    score_dir("bad", &r);
    assert_non_null(strstr(suite_reason(&r), "the suite's results are not what it writes: part1: b.xml"));
    assert_int_equal(unlink(path), 0);
    char target[300];
    snprintf(target, sizeof target, "%s/whole/part1: b.xml", scratch);
    assert_int_equal(symlink(target, path), 0);
    score_dir("bad", &r);
    assert_non_null(strstr(suite_reason(&r), "the suite's results are not what it writes: part1: b.xml"));
    assert_true(r.unit_score == 0.0);
}

/* ---- logs ---------------------------------------------------------------------------------- */

static void test_run__log_is_a_fresh_file_never_a_planted_link(void **state)
{
    (void)state;
    char victim[256], log[256], text[64] = "";
    snprintf(victim, sizeof victim, "%s/victim", scratch);
    snprintf(log, sizeof log, "%s/planted.log", scratch);
    scratch_write(victim, "precious\n");
    assert_int_equal(symlink(victim, log), 0);
    assert_int_equal(run_untrusted("echo from the child", log), 0);
    FILE *f = fopen(victim, "r");
    assert_non_null(f);
    assert_non_null(fgets(text, sizeof text, f));
    fclose(f);
    assert_string_equal(text, "precious\n");
    struct stat st;
    assert_int_equal(lstat(log, &st), 0);
    assert_true(S_ISREG(st.st_mode));
    assert_int_equal(st.st_uid, getuid());  /* the grader's, written by the grader */
}

static void test_run__a_flood_is_cut_while_the_child_runs(void **state)
{
    (void)state;
    char log[256];
    snprintf(log, sizeof log, "%s/flood.log", scratch);
    /* 64 MiB of output against a 4 KiB cap: the log never holds more than the cap and a note. */
    assert_int_equal(run_untrusted("head -c 67108864 /dev/zero", log), 0);
    long size = file_size(log);
    assert_true(size >= 4096 && size < 4096 + 64);
    char tail[200];
    grade_log_tail(log, 1, tail, sizeof tail);
    assert_string_equal(tail, "[grader: output cut here]");
}

/* ---- the filter: student code from its first instruction ----------------------------------- */

/* bin/grade-probe MODE run as the grader runs student code, from a copy in the scratch folder (the
 * sandbox's user may not enter bin/ once bin/grade --submission ran here as root); its exit status
 * (-1: did not exit). */
static int run_probe(const char *mode, const char *log, bool *cut)
{
    char probe[128], copy[300];
    snprintf(probe, sizeof probe, "%s/grade-probe", scratch);
    snprintf(copy, sizeof copy, "cp bin/grade-probe '%s'", probe);
    assert_int_equal(system(copy), 0);
    char *argv[] = {probe, (char *)mode, NULL};
    grade_run_opts o = {.wall_seconds = 30, .cwd = scratch, .log_path = log, .log_max = 1 << 16, .untrusted = true,
                        .sandbox = the_sandbox()};
    grade_run_result r = grade_run(argv, &o);
    if (cut) *cut = r.output_cut;
    return r.exited ? r.status : -1;
}

static void test_run__student_code_is_filtered_from_its_first_instruction(void **state)
{
    (void)state;
    grade_sandbox s = grade_sandbox_probe();
    if (skipped_unless(s.filter, "no filter on this machine", s.filter_why)) return;
    char log[256], tail[4096];
    snprintf(log, sizeof log, "%s/forbidden.log", scratch);
    int status = run_probe("forbidden", log, NULL);
    grade_log_tail(log, 40, tail, sizeof tail);
    if (status != 0) fail_msg("under the sandbox, grade-probe forbidden exited %d:\n%s", status, tail);
    /* The probe ran its checks (a probe that never started would also not succeed). */
    assert_non_null(strstr(tail, "fork()                                       refused"));
    assert_non_null(strstr(tail, "a thread                                     worked"));
    /* Unconfined, the same probe finds the forbidden things allowed: the test can fail. */
    char probe[128];
    snprintf(probe, sizeof probe, "%s/grade-probe", scratch);
    char *argv[] = {probe, "forbidden", NULL};
    grade_run_opts o = {.wall_seconds = 30, .cwd = scratch, .log_path = log, .log_max = 1 << 16};
    grade_run_result r = grade_run(argv, &o);
    assert_true(r.exited && r.status != 0);
}

/* ---- namespaces: a stage sees only itself, and nothing of it outlives it ------------------- */

/* Processes on the machine whose command line holds marker (a sleeper a test left behind). */
static int processes_with(const char *marker)
{
    DIR *d = opendir("/proc");
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        char path[300], cmd[256] = "";
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        snprintf(path, sizeof path, "/proc/%s/cmdline", e->d_name);
        FILE *f = fopen(path, "r");
        size_t len = f ? fread(cmd, 1, sizeof cmd - 1, f) : 0;
        if (f) fclose(f);
        for (size_t i = 0; i < len; i++)
            if (!cmd[i]) cmd[i] = ' ';  /* arguments are NUL-separated */
        cmd[len] = '\0';
        n += strstr(cmd, marker) != NULL;
    }
    if (d) closedir(d);
    return n;
}

/* Attack: a child (here the compiler's stage, which may fork) starts a daemon with setsid, which
 * leaves the process group the timeout kills, and looks for the grader's processes in /proc. In a
 * PID namespace of its own it finds only its own few, and the daemon dies with the stage. */
static void test_run__a_stage_is_a_namespace_of_its_own(void **state)
{
    (void)state;
    if (skipped_unless(grade_sandbox_probe().isolated, "no PID namespace here",
                       "needs root, outside a container that refuses them")) return;
    char log[256], script[512], text[64] = "";
    snprintf(log, sizeof log, "%s/namespace.log", scratch);
    snprintf(script, sizeof script,
             "setsid sh -c 'exec sleep 97.25' </dev/null >/dev/null 2>&1 & "
             "if [ -e /proc/%d ]; then echo grader-visible; else ls /proc | grep -c '^[0-9]'; fi", (int)getpid());
    assert_int_equal(run_untrusted(script, log), 0);
    first_line(log, text, sizeof text);
    if (!strncmp(text, "grader-visible", 14)) fail_msg("the child saw the grader (pid %d) in its /proc", (int)getpid());
    long seen = atol(text);
    if (seen < 1 || seen > 8) fail_msg("the child's /proc lists %ld processes; its own namespace has a few", seen);
    if (processes_with("sleep 97.25")) fail_msg("a setsid daemon outlived the stage that started it");
}

/* Attack on the grader's own code: a stage that marks its child untrusted but forgets the grading's
 * sandbox settings. The child must not run unconfined: it exits before it runs anything (126), and
 * the file it would have written is never made. */
static void test_run__an_untrusted_child_needs_the_sandbox(void **state)
{
    (void)state;
    char log[256], text[64] = "";
    snprintf(log, sizeof log, "%s/unset.log", scratch);
    char *argv[] = {"sh", "-c", "echo ran", NULL};
    grade_run_opts o = {.wall_seconds = 30, .cwd = scratch, .log_path = log, .log_max = 4096, .untrusted = true,
                        .compiler = true};
    grade_run_result r = grade_run(argv, &o);
    assert_true(r.exited);
    assert_int_equal(r.status, 126);
    assert_true(file_size(log) == 0);  /* it printed nothing: it never ran the shell */
    /* With the settings, the same child runs (the test can fail). */
    o.sandbox = the_sandbox();
    r = grade_run(argv, &o);
    assert_true(r.exited && r.status == 0);
    first_line(log, text, sizeof text);
    assert_true(!strncmp(text, "ran", 3));
}

/* ---- limits and what the report says ------------------------------------------------------- */

static void test_run__untrusted_children_have_a_process_limit(void **state)
{
    (void)state;
    char log[256], text[64] = "";
    snprintf(log, sizeof log, "%s/nproc.log", scratch);
    assert_int_equal(run_untrusted("awk '/Max processes/ {print $3}' /proc/self/limits", log), 0);
    first_line(log, text, sizeof text);
    if (!strncmp(text, "unlimited", 9)) fail_msg("an untrusted child has no process limit (uid %u)", getuid());
    long limit = atol(text);
    assert_true(limit > 0 && limit < 100000);
}

static void test_sandbox__report_names_what_is_missing(void **state)
{
    (void)state;
    char text[256];
    grade_sandbox s = {.process_limit = 300, .filter_why = "built without libseccomp"};
    grade_words_protections_missing(&s, text, sizeof text);
    assert_non_null(strstr(text, "not root: student code ran as your own user"));
    assert_non_null(strstr(text, "had the network"));
    assert_non_null(strstr(text, "no system-call filter: built without libseccomp"));
    s.as_other_user = s.no_network = s.filter = true;
    grade_words_protections_missing(&s, text, sizeof text);
    assert_string_equal(text, "");
}

/* ---- secrets, as root ---------------------------------------------------------------------- */

static void test_guard__nobody_cannot_open_a_reference(void **state)
{
    (void)state;
    grade_sandbox s = grade_sandbox_probe();
    if (skipped_unless(s.as_other_user, "needs root", "to run a child as nobody")) return;
    char path[512], script[2048], log[256];
    static const char *const dirs[] = {"course", "course/reference_images", "course/reference_images/part1",
                                       "course/grading", "course/grading/hidden", "course/scenes", "out",
                                       "out/report", NULL};
    for (const char *const *d = dirs; *d; d++) {
        snprintf(path, sizeof path, "%s/%s", scratch, *d);
        assert_int_equal(mkdir(path, 0755), 0);
    }
    static const char *const files[] = {"course/reference_images/part1/case.exr", "course/grading/hidden/cases.json",
                                        "course/scenes/public.dae", "out/report/part1_case_reference.png",
                                        "out/results.json", NULL};
    for (const char *const *f = files; *f; f++) {
        snprintf(path, sizeof path, "%s/%s", scratch, *f);
        scratch_write(path, "secret\n");
        chmod(path, 0644);
    }
    snprintf(log, sizeof log, "%s/guard.log", scratch);
    /* Before: everything is readable to nobody (else the test below proves nothing). */
    snprintf(script, sizeof script, "cat '%s/course/reference_images/part1/case.exr'", scratch);
    assert_int_equal(run_untrusted(script, log), 0);

    /* The secrets as the plan lists them for a grading of this course into out/. */
    static grade_run_plan rp;
    grade_secrets secrets;
    char why[256] = "";
    snprintf(rp.root, sizeof rp.root, "%s/course", scratch);
    snprintf(rp.report, sizeof rp.report, "%s/out/report", scratch);
    snprintf(rp.results, sizeof rp.results, "%s/out/results.json", scratch);
    grade_plan_secrets(&rp, &secrets);
    if (!grade_guard_secrets(&secrets, &s, why, sizeof why)) fail_msg("%s", why);
    for (const char *const *f = files; *f; f++) {
        snprintf(script, sizeof script, "id -u >&2; cat '%s/%s'", scratch, *f);
        int status = run_untrusted(script, log);
        bool is_public = strstr(*f, "public") != NULL;
        if ((status == 0) != is_public)
            fail_msg("a child as nobody %s %s (exit status %d)", is_public ? "cannot read" : "read", *f, status);
    }
    snprintf(script, sizeof script, "ls '%s/course/grading/hidden' '%s/course/reference_images'", scratch, scratch);
    assert_int_not_equal(run_untrusted(script, log), 0);

    /* A render "written" as a link to the reference is refused by the grader, root though it is. */
    snprintf(path, sizeof path, "%s/render.exr", scratch);
    snprintf(script, sizeof script, "%s/course/reference_images/part1/case.exr", scratch);
    assert_int_equal(symlink(script, path), 0);
    assert_int_equal(grade_guard_open_child_file(path, 1 << 20), -1);
}

/* ---- a failed build's message --------------------------------------------------------------- */

static void test_log_tail__last_lines_bounded(void **state)
{
    (void)state;
    char path[256], text[4096];
    snprintf(path, sizeof path, "%s/build.log", scratch);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int i = 1; i <= 100; i++) fprintf(f, "line %d\n", i);
    fclose(f);
    grade_log_tail(path, 40, text, sizeof text);
    assert_true(!strncmp(text, "line 61\n", 8));
    assert_non_null(strstr(text, "\nline 100"));
    /* A small buffer keeps the last whole lines that fit. */
    char small[32];
    grade_log_tail(path, 40, small, sizeof small);
    assert_true(strlen(small) < sizeof small);
    assert_non_null(strstr(small, "line 100"));
    assert_true(!strncmp(small, "line ", 5));
    grade_log_tail("/nonexistent/build.log", 40, small, sizeof small);
    assert_string_equal(small, "");
}

/* The compiler's lines a student sees: their own files' only, printable, bounded. */
static void test_diagnostics__only_the_parts_own_files(void **state)
{
    (void)state;
    char path[256], text[4096];
    snprintf(path, sizeof path, "%s/diag.log", scratch);
    scratch_write(path, "  CC     parts/part3_direct/direct.c\n"
                     "In file included from parts/part3_direct/direct.c:2:\n"
                     "grading/hidden/secret.dae:1:1: error: expected identifier before '<' token\n"
                     "    1 | <COLLADA secret scene line>\n"
                     "      | ^\n"
                     "parts/part3_direct/direct.c:7:5: error: 'x' undeclared \xff\x1b[31m\n"
                     "    7 |     x = 1;\n"
                     "      |     ^\n"
                     "parts/part3_direct/../../framework/render.c:3:1: error: in another file\n"
                     "    3 | framework line\n"
                     "make: *** [Makefile:75: build/release/parts/part3_direct/direct.o] Error 1\n");
    grade_diagnostics(path, "part3_direct", 40, text, sizeof text);
    assert_string_equal(text, "parts/part3_direct/direct.c:7:5: error: 'x' undeclared ??[31m\n"
                              "    7 |     x = 1;\n"
                              "      |     ^");
    /* Bounded by lines. */
    grade_diagnostics(path, "part3_direct", 1, text, sizeof text);
    assert_string_equal(text, "parts/part3_direct/direct.c:7:5: error: 'x' undeclared ??[31m");
}

/* The film stream: what a render sends is what the grader receives, bit for bit; a stream cut
 * short, of another size or with trailing bytes is refused whole. */
static void test_film_stream__round_trip_and_refusals(void **state)
{
    (void)state;
    film f = {0}, got = {0};
    assert_int_equal(film_alloc(&f, 3, 2), PL_OK);
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 1 + i; k++) film_pixel_add(&f.pixels[i], rgb_make(0.25f * (float)k, 1e-7f, 3.5f));
    film_pixel_add(&f.pixels[5], rgb_make(NAN, 0, 0));
    int fds[2];
    assert_int_equal(pipe(fds), 0);
    output_film_counts sent = {10, 20, 30, 21}, counts;
    pl_diag d = pl_diag_default();
    assert_int_equal(output_film_send(fds[1], &f, &sent, &d), PL_OK);
    close(fds[1]);
    static char buf[4096];
    ssize_t n = read(fds[0], buf, sizeof buf);
    close(fds[0]);
    assert_int_equal(n, 48 + 6 * OUTPUT_FILM_PIXEL_BYTES + 8);
    assert_int_equal(output_film_receive(buf, (size_t)n, 3, 2, &got, &counts, &d), PL_OK);
    assert_memory_equal(got.pixels, f.pixels, 6 * sizeof *f.pixels);
    assert_true(counts.rays == 10 && counts.node_visits == 20 && counts.prim_tests == 30 && counts.samples == 21);
    film_free(&got);
    assert_int_not_equal(output_film_receive(buf, (size_t)n - 1, 3, 2, &got, &counts, &d), PL_OK);
    assert_int_not_equal(output_film_receive(buf, (size_t)n, 2, 3, &got, &counts, &d), PL_OK);
    assert_non_null(strstr(d.error, "the film's size is not the case's: the case renders 2x3"));
    assert_null(strstr(d.error, "3x2"));  /* the film's own size is the candidate's number: never shown */
    buf[n] = 'x';
    assert_int_not_equal(output_film_receive(buf, (size_t)n + 1, 3, 2, &got, &counts, &d), PL_OK);
    film_free(&f);
}

int sandbox_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_allowlist__framework_api_only),
        cmocka_unit_test(test_suite_score__only_a_suite_run_to_its_end),
        cmocka_unit_test(test_run__log_is_a_fresh_file_never_a_planted_link),
        cmocka_unit_test(test_run__a_flood_is_cut_while_the_child_runs),
        cmocka_unit_test(test_run__untrusted_children_have_a_process_limit),
        cmocka_unit_test(test_run__an_untrusted_child_needs_the_sandbox),
        cmocka_unit_test(test_run__a_stage_is_a_namespace_of_its_own),
        cmocka_unit_test(test_run__student_code_is_filtered_from_its_first_instruction),
        cmocka_unit_test(test_sandbox__report_names_what_is_missing),
        cmocka_unit_test(test_guard__nobody_cannot_open_a_reference),
        cmocka_unit_test(test_log_tail__last_lines_bounded),
        cmocka_unit_test(test_diagnostics__only_the_parts_own_files),
        cmocka_unit_test(test_film_stream__round_trip_and_refusals),
    };
    return cmocka_run_group_tests_name("grader sandbox", tests, make_scratch, remove_scratch);
}
