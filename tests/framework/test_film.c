/* Test machinery: not part of any assignment. The film (framework/film.c): fixed-point sums that
 * add up the same in any order; and, through the real binary, sample ranges (--samples A:B) that
 * merge (--merge) into the same bytes as the single render, PNG and EXR, for several splits and
 * thread counts, and merges that must be refused (gap, overlap, another render, and every hostile
 * film tests/data/make_hostile_films.py writes, each within 1 GB and 10 s). No randomness is judged
 * here: every check is exact. */
#include "../common/test.h"
#include "../../framework/film.h"
#include "../../framework/exr.h"
#include "../../framework/file.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---- fixed point ---------------------------------------------------------------------------- */

static void test_film_quantise__rounds_to_multiples_of_2_pow_minus_32(void **state)
{
    (void)state;
    uint64_t q;
    assert_true(film_quantise(1.0f, &q));
    assert_true(q == (uint64_t)1 << 32);
    assert_true(film_quantise(0.0f, &q));
    assert_true(q == 0);
    assert_true(film_quantise(0x1p-33f, &q));   /* exactly half a step: rounds away from zero */
    assert_true(q == 1);
    assert_true(film_quantise(0x1p-34f, &q));   /* a quarter step: rounds to 0 */
    assert_true(q == 0);
    assert_true(film_quantise(0.1f, &q));
    assert_true(q == (uint64_t)llround(ldexp((double)0.1f, 32)));
}

static void test_film_quantise__bad_values_are_refused(void **state)
{
    (void)state;
    uint64_t q;
    assert_false(film_quantise(NAN, &q));
    assert_false(film_quantise(INFINITY, &q));
    assert_false(film_quantise(-1e-6f, &q));
    assert_false(film_quantise(2147483648.0f, &q));  /* FILM_MAX_VALUE */
    assert_true(film_quantise(2147483520.0f, &q));   /* the largest float below it */
}

/* A bad sample counts in n and in bad, and adds nothing to any sum. */
static void test_film_pixel_add__bad_sample_counts_as_black(void **state)
{
    (void)state;
    film_pixel p = {0};
    assert_true(film_pixel_add(&p, rgb_make(1, 2, 3)));
    assert_false(film_pixel_add(&p, rgb_make(NAN, 1, 1)));
    assert_false(film_pixel_add(&p, rgb_make(1, -1, 1)));
    assert_int_equal(3, p.n);
    assert_int_equal(2, p.bad);
    assert_true(film_pixel_mean(&p, 2) == 1.0);  /* 3 / 3 */
}

/* Sums of many values of mixed magnitudes, added one by one in three different groupings and
 * orders, are the same bits. */
static void test_film_pixel__sums_are_the_same_in_any_grouping(void **state)
{
    (void)state;
    enum { N = 1000 };
    static rgb v[N];
    uint64_t x = 88172645463325252ull;
    for (int i = 0; i < N; i++) {
        float c[3];
        for (int k = 0; k < 3; k++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;  /* xorshift: fixed values, no RNG order assumed */
            c[k] = (float)ldexp((double)(x >> 40), -24) * (k == 0 ? 1e-3f : k == 1 ? 1.0f : 1e4f);
        }
        v[i] = rgb_make(c[0], c[1], c[2]);
    }
    film_pixel forward, backward, pieces, piece[3];
    memset(&forward, 0, sizeof forward), memset(&backward, 0, sizeof backward), memset(&pieces, 0, sizeof pieces);
    memset(piece, 0, sizeof piece);
    for (int i = 0; i < N; i++) film_pixel_add(&forward, v[i]);
    for (int i = N - 1; i >= 0; i--) film_pixel_add(&backward, v[i]);
    for (int i = 0; i < N; i++) film_pixel_add(&piece[i < 100 ? 0 : i < 601 ? 1 : 2], v[i]);
    film_pixel_merge(&pieces, &piece[2]);
    film_pixel_merge(&pieces, &piece[0]);
    film_pixel_merge(&pieces, &piece[1]);
    assert_memory_equal(&forward, &backward, sizeof forward);
    assert_memory_equal(&forward, &pieces, sizeof forward);
}

static void test_film_pixel__variance_of_the_mean(void **state)
{
    (void)state;
    film_pixel p = {0};
    film_pixel_add(&p, rgb_gray(1.0f));
    assert_true(film_pixel_variance_of_mean(&p, 0) == 0.0);  /* n = 1: no estimate */
    film_pixel_add(&p, rgb_gray(3.0f));
    /* samples 1 and 3: sample variance 2, variance of the mean 2 / 2 = 1 */
    assert_true(film_pixel_variance_of_mean(&p, 1) == 1.0);
    assert_true(film_pixel_mean(&p, 1) == 2.0);
}

static void test_film_pixel_merge__refuses_counts_that_wrap(void **state)
{
    (void)state;
    film_pixel a = {.n = 4}, b = {.n = 4294967295u}, c = {.n = 1, .bad = 4294967295u};
    assert_false(film_pixel_merge(&a, &b));
    assert_int_equal(a.n, 4);  /* unchanged */
    assert_false(film_pixel_merge(&c, &c));
    b.n = 4294967291u;
    assert_true(film_pixel_merge(&a, &b));
    assert_int_equal(a.n, 4294967295u);
}

static void test_film_check__names_the_pixel_and_field(void **state)
{
    (void)state;
    film f;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, film_alloc(&f, 3, 2));
    for (int i = 0; i < 6; i++) f.pixels[i].n = 2;
    assert_int_equal(PL_OK, film_check(&f, 2, 2, "x.exr", &d));
    /* One sample of value 1 (2^32 units) and one bad: consistent; then sums with no good sample. */
    f.pixels[4].bad = 1;
    for (int c = 0; c < 4; c++) f.pixels[4].sum[c] = f.pixels[4].sum_sq[c] = (film_sum)1 << 32;
    assert_int_equal(PL_OK, film_check(&f, 2, 2, "x.exr", &d));
    f.pixels[4].bad = 2;
    assert_int_equal(PL_ERR_PARSE, film_check(&f, 2, 2, "x.exr", &d));
    assert_string_equal(d.error, "x.exr: pixel (1, 1): acc.sum.R / acc.sq.R: sums without a good sample (n = 2, bad = 2)");
    /* Two samples of 1 have sum 2 and squares 2: a sum of 3 is more than they allow. */
    f.pixels[4].bad = 0;
    for (int c = 0; c < 4; c++) f.pixels[4].sum[c] = (film_sum)3 << 32, f.pixels[4].sum_sq[c] = (film_sum)2 << 32;
    assert_int_equal(PL_ERR_PARSE, film_check(&f, 2, 2, "x.exr", &d));
    assert_non_null(strstr(d.error, "a sum too large for its sum of squares"));
    f.pixels[4].sum[0] = (film_sum)2 << 32;  /* the R channel now fine, G still not */
    assert_int_equal(PL_ERR_PARSE, film_check(&f, 2, 2, "x.exr", &d));
    assert_non_null(strstr(d.error, "acc.sum.G"));
    film_free(&f);
}

/* ---- split renders merge into the same bytes, through the real binary ----------------------- */

#define RENDER "bin/pathtracer -q -r 24 16 -s 6 -m 2 -l 2 --seed 7"
#define SCENE "scenes/cornell_spheres.dae"

static char dir[64];

static int run(const char *fmt, const char *a, const char *b, const char *c)
{
    char cmd[1024], line[900];
    snprintf(line, sizeof line, fmt, a, b, c);
    snprintf(cmd, sizeof cmd, "%s >/dev/null 2>>%s/stderr.txt", line, dir);
    int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void expect_same_bytes(const char *want, const char *got)
{
    char *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all(want, "render", 1 << 26, &a, &na, &d));
    assert_int_equal(PL_OK, file_read_all(got, "merge", 1 << 26, &b, &nb, &d));
    if (na != nb || memcmp(a, b, na) != 0) fail_msg("%s (%zu bytes) and %s (%zu bytes) differ", want, na, got, nb);
    free(a);
    free(b);
}

static int merge_setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/pathlab-film-XXXXXX");
    if (!mkdtemp(dir)) return -1;
    char path[128];
    snprintf(path, sizeof path, "%s/full", dir);
    if (run(RENDER " -t 1 -f %s.exr " SCENE, path, "", "") != 0) return -1;
    return run(RENDER " -t 1 -f %s.png " SCENE, path, "", "");
}

static int merge_teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : -1;
}

/* Renders the ranges (each "A:B") on `threads` threads, merges them to EXR and PNG, compares. */
static void split_and_merge(const char *const *ranges, int count, int threads)
{
    char inputs[512] = "", t[8], path[128], out[160];
    snprintf(t, sizeof t, "%d", threads);
    for (int i = 0; i < count; i++) {
        snprintf(path, sizeof path, "%s/range%d.exr", dir, i);
        assert_int_equal(0, run(RENDER " -t %s --samples %s -f %s " SCENE, t, ranges[i], path));
        strcat(inputs, " ");
        strcat(inputs, path);
    }
    static const char *const ext[] = {"exr", "png"};
    for (int e = 0; e < 2; e++) {
        snprintf(out, sizeof out, "%s/merged.%s", dir, ext[e]);
        assert_int_equal(0, run("bin/pathtracer --merge -f %s%s%s", out, inputs, ""));
        snprintf(path, sizeof path, "%s/full.%s", dir, ext[e]);
        expect_same_bytes(path, out);
    }
}

static void test_merge__one_piece_one_thread(void **state)
{
    (void)state;
    const char *r[] = {"0:6"};
    split_and_merge(r, 1, 1);
}

static void test_merge__two_pieces_two_threads(void **state)
{
    (void)state;
    const char *r[] = {"3:6", "0:3"};
    split_and_merge(r, 2, 2);
}

static void test_merge__three_uneven_pieces_three_threads(void **state)
{
    (void)state;
    const char *r[] = {"0:1", "1:5", "5:6"};
    split_and_merge(r, 3, 3);
}

/* Each refused merge exits 2, names the problem and writes nothing. */
static void expect_refused(const char *const *ranges, int count, const char *extra_flags, const char *message)
{
    char inputs[512] = "", path[128], out[160];
    for (int i = 0; i < count; i++) {
        snprintf(path, sizeof path, "%s/bad%d.exr", dir, i);
        assert_int_equal(0, run(RENDER " %s --samples %s -f %s " SCENE, i == count - 1 ? extra_flags : "", ranges[i], path));
        strcat(inputs, " ");
        strcat(inputs, path);
    }
    snprintf(out, sizeof out, "%s/refused.exr", dir);
    snprintf(path, sizeof path, "%s/stderr.txt", dir);
    remove(path);
    assert_int_equal(2, run("bin/pathtracer --merge -f %s%s%s", out, inputs, ""));
    assert_int_equal(-1, access(out, F_OK));
    char *text = NULL;
    size_t n = 0;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all(path, "stderr", 1 << 20, &text, &n, &d));
    if (!strstr(text, message)) fail_msg("expected the message to contain '%s', got: %s", message, text);
    free(text);
}

static void test_merge__refuses_a_gap(void **state)
{
    (void)state;
    const char *r[] = {"0:2", "3:6"};
    expect_refused(r, 2, "", "samples 2:3 are missing");
}

static void test_merge__refuses_a_missing_end(void **state)
{
    (void)state;
    const char *r[] = {"0:2", "2:5"};
    expect_refused(r, 2, "", "samples 5:6 are missing");
}

static void test_merge__refuses_an_overlap(void **state)
{
    (void)state;
    const char *r[] = {"0:4", "3:6"};
    expect_refused(r, 2, "", "overlaps");
}

static void test_merge__refuses_another_render(void **state)
{
    (void)state;
    const char *r[] = {"0:3", "3:6"};
    expect_refused(r, 2, "-H", "not pieces of the same render");
}

/* Every hostile film of the generator is refused with its located error and no output, within 1 GB
 * of address space and 10 s; its two controls (one film, two ranges of one render) are accepted, so
 * the generator writes what pathlab writes and each refusal is the one change's. */
static void test_merge__refuses_every_hostile_film(void **state)
{
    (void)state;
    char cwd[512], hostile[128], cmd[2048], line[1024];
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(hostile, sizeof hostile, "%s/hostile", dir);
    snprintf(cmd, sizeof cmd, "python3 tests/data/make_hostile_films.py %s", hostile);
    assert_int_equal(0, system(cmd));
    snprintf(line, sizeof line, "%s/manifest.txt", hostile);
    FILE *manifest = fopen(line, "r");
    assert_non_null(manifest);
    int cases = 0;
    while (fgets(line, sizeof line, manifest)) {
        line[strcspn(line, "\n")] = '\0';
        char *files = strchr(line, '|');
        assert_non_null(files);
        *files++ = '\0';
        snprintf(cmd, sizeof cmd, "cd %s && rm -f out.exr && (ulimit -v 1048576; exec timeout 10 %s/bin/pathtracer "
                 "--merge -f out.exr %s) >/dev/null 2>msg.txt", hostile, cwd, files);
        int status = system(cmd), code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        char path[256], *msg = NULL;
        size_t n = 0;
        pl_diag d = pl_diag_default();
        snprintf(path, sizeof path, "%s/msg.txt", hostile);
        assert_int_equal(PL_OK, file_read_all(path, "stderr", 1 << 20, &msg, &n, &d));
        snprintf(path, sizeof path, "%s/out.exr", hostile);
        bool ok = !strcmp(line, "ok") ? code == 0 : code == 2 && strstr(msg, line) && access(path, F_OK) != 0;
        if (!ok) fail_msg("%s: expected %s%s, got exit %d: %s", files, strcmp(line, "ok") ? "exit 2 and " : "success",
                          strcmp(line, "ok") ? line : "", code, msg);
        free(msg);
        cases++;
    }
    fclose(manifest);
    assert_true(cases >= 50);
}

/* --merge takes its options in any order, and -q beside them; an option of a render is refused. */
static void test_merge__options_in_any_order(void **state)
{
    (void)state;
    char a[128], b[128], out[160], full[160];
    snprintf(a, sizeof a, "%s/order0.exr", dir);
    snprintf(b, sizeof b, "%s/order1.exr", dir);
    assert_int_equal(0, run(RENDER " -t 1 --samples 0:2 -f %s%s " SCENE, a, "", ""));
    assert_int_equal(0, run(RENDER " -t 1 --samples 2:6 -f %s%s " SCENE, b, "", ""));
    snprintf(full, sizeof full, "%s/full.exr", dir);
    snprintf(out, sizeof out, "%s/order_a.exr", dir);
    assert_int_equal(0, run("bin/pathtracer %s -q --merge -f %s %s", b, out, a));
    expect_same_bytes(full, out);
    snprintf(out, sizeof out, "%s/order_b.exr", dir);
    assert_int_equal(0, run("bin/pathtracer -f %s %s --merge %s", out, a, b));
    expect_same_bytes(full, out);
    snprintf(out, sizeof out, "%s/order_c.exr", dir);
    assert_int_equal(2, run("bin/pathtracer --merge -s 4 -f %s %s %s", out, a, b));
    assert_int_equal(-1, access(out, F_OK));
}

static void test_samples__refused_with_adaptive_or_beyond_spp(void **state)
{
    (void)state;
    assert_int_equal(2, run("bin/pathtracer -q -r 8 8 -s 6 -a 2 0.1 --samples 0:3 %s%s%s", SCENE, "", ""));
    assert_int_equal(2, run("bin/pathtracer -q -r 8 8 -s 6 --samples 2:7 %s%s%s", SCENE, "", ""));
    assert_int_equal(2, run("bin/pathtracer -q -r 8 8 -s 6 --samples 3:3 %s%s%s", SCENE, "", ""));
}

int film_tests(void)
{
    const struct CMUnitTest unit[] = {
        cmocka_unit_test(test_film_quantise__rounds_to_multiples_of_2_pow_minus_32),
        cmocka_unit_test(test_film_quantise__bad_values_are_refused),
        cmocka_unit_test(test_film_pixel_add__bad_sample_counts_as_black),
        cmocka_unit_test(test_film_pixel__sums_are_the_same_in_any_grouping),
        cmocka_unit_test(test_film_pixel__variance_of_the_mean),
        cmocka_unit_test(test_film_pixel_merge__refuses_counts_that_wrap),
        cmocka_unit_test(test_film_check__names_the_pixel_and_field),
    };
    const struct CMUnitTest merge[] = {
        cmocka_unit_test(test_merge__one_piece_one_thread),
        cmocka_unit_test(test_merge__two_pieces_two_threads),
        cmocka_unit_test(test_merge__three_uneven_pieces_three_threads),
        cmocka_unit_test(test_merge__refuses_a_gap),
        cmocka_unit_test(test_merge__refuses_a_missing_end),
        cmocka_unit_test(test_merge__refuses_an_overlap),
        cmocka_unit_test(test_merge__refuses_another_render),
        cmocka_unit_test(test_merge__refuses_every_hostile_film),
        cmocka_unit_test(test_merge__options_in_any_order),
        cmocka_unit_test(test_samples__refused_with_adaptive_or_beyond_spp),
    };
    int failed = cmocka_run_group_tests_name("film: fixed-point accumulators", unit, NULL, NULL);
    failed += cmocka_run_group_tests_name("film: split renders merge into the same bytes (bin/pathtracer)", merge,
                                          merge_setup, merge_teardown);
    return failed;
}
