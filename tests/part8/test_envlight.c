/* Test machinery: not part of any assignment.
 * Part 8, the environment light, one task at a time: tasks 8.3 and 8.4 get tables this file builds
 * (oracle_tables), never task 8.2's, so each task is judged on its own.
 * Task 8.1 (env_sample_uniform): unit directions, pdf 1 / (4 pi), the map's radiance; uniform over
 * the sphere (chi-square over 8 bands of equal area by 16 sectors); a constant map's irradiance.
 * Task 8.2 (env_build_distribution): the tables are CDFs; within a row a texel's probability is in
 * proportion to its luminance (black texels never drawn); rows weigh by sin(theta) (any weight
 * within the row's range of sin(theta) passes: its centre's, or its exact solid angle's); tables
 * that follow the map's rows in reverse order are named as such.
 * Task 8.3 (env_pdf): the closed form p(x, y) w h / (2 pi^2 sin(theta)) at points of every texel,
 * and a density that integrates to 1 over the sphere.
 * Task 8.4 (env_sample_importance): the directions follow the texels' probabilities and are uniform
 * in (theta, phi) within a texel (chi-square over 2 x 2 cells of each texel; the messages compare
 * each direction with the texel its u draws by the contract, to tell the texel choice from the point
 * within it, a texel's corner and rows in reverse order); the pdf and radiance it returns are those
 * of the direction (the pdf the closed form's, or the candidate's own env_pdf's there: the contract
 * lets 8.4 call 8.3, whose mistakes are then 8.3's alone); weighed by the closed forms, its
 * directions give the irradiance of a constant map and of a map with a sun, and on the sun's map a
 * variance far below uniform sampling's.
 * Irradiance closed form, normal +Y: E = sum over texels of L (2 pi / w) [sin^2(theta) / 2] over the
 * texel's rows above the horizon. Nothing depends on the order of draws or on the search used.
 * alpha: five statistical checks here, each at PART8_CHECK_ALPHA (part8_alpha.h). Seeds are fixed,
 * printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "part8_alpha.h"
#include "../../parts/part8_envlight/part8.h"

#define SEED mc_seed(0x5eed8001ull)

/* ---- maps and tables ------------------------------------------------------------------------- */

/* 16 x 8 texels of varied colours and brightness; row 2 black, two black texels in row 5, and one
 * texel 100 times the others (a small sun) in row 3. */
static void test_map(envmap *e)
{
    assert_int_equal(PL_OK, envmap_make_constant(e, 16, 8, rgb_gray(0.0f)));
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++) {
            float v = 0.2f + 0.1f * (float)((x * 7 + y * 3) % 5);
            e->texels[y * 16 + x] = y == 2 || (y == 5 && (x == 3 || x == 4)) ? rgb_gray(0.0f) : rgb_make(v, 0.8f * v, 1.3f * v);
        }
    e->texels[3 * 16 + 11] = rgb_make(40.0f, 38.0f, 30.0f);
}

/* 64 x 32 texels of sky 0.5 and a sun of 2 x 2 texels of 200 in rows 10-11. */
static void sun_map(envmap *e)
{
    assert_int_equal(PL_OK, envmap_make_constant(e, 64, 32, rgb_gray(0.5f)));
    for (int y = 10; y < 12; y++)
        for (int x = 20; x < 22; x++) e->texels[y * 64 + x] = rgb_gray(200.0f);
}

/* The test's own tables for e: weights luminance x sin(theta at the row's centre), summed in double. */
static void oracle_tables(const envmap *e, env_distribution *d)
{
    assert_int_equal(PL_OK, env_distribution_alloc(d, e->width, e->height));
    double *row_w = calloc((size_t)e->height, sizeof *row_w), total = 0.0;
    assert_non_null(row_w);
    for (int y = 0; y < e->height; y++) {
        float *c = d->conditional_cdf + (size_t)y * (e->width + 1);
        double sum = 0.0, acc = 0.0;
        for (int x = 0; x < e->width; x++) sum += rgb_luminance(envmap_texel(e, x, y));
        for (int x = 0; x < e->width; x++) {
            acc += rgb_luminance(envmap_texel(e, x, y));
            c[x + 1] = sum > 0.0 ? (float)(acc / sum) : (float)(x + 1) / (float)e->width;
        }
        c[e->width] = 1.0f;
        row_w[y] = sum * sin((y + 0.5) * M_PI / e->height);
        total += row_w[y];
    }
    double acc = 0.0;
    for (int y = 0; y < e->height; y++) {
        acc += row_w[y];
        d->marginal_cdf[y + 1] = (float)(acc / total);
    }
    d->marginal_cdf[e->height] = 1.0f;
    free(row_w);
    assert_true(env_distribution_check(d, (char[160]){0}, 160));
}

/* Texel (x, y)'s probability in tables d. */
static double texel_p(const env_distribution *d, int x, int y)
{
    const float *c = d->conditional_cdf + (size_t)y * (d->width + 1);
    return ((double)d->marginal_cdf[y + 1] - d->marginal_cdf[y]) * ((double)c[x + 1] - c[x]);
}

/* The texel direction w falls in, and where in it (fractions of its width and height). */
static void texel_of(const envmap *e, vec3 w, int *x, int *y, double *fx, double *fy)
{
    vec2 a = envmap_angles(w);
    double u = a.y / (2.0 * M_PI) * e->width, v = a.x / M_PI * e->height;
    *x = (int)fmin(fmax(floor(u), 0), e->width - 1), *y = (int)fmin(fmax(floor(v), 0), e->height - 1);
    *fx = u - *x, *fy = v - *y;
}

/* How far a correct density may be from the closed form near a pole, relative: sin(theta) from
 * sinf(acosf(w.y)) in float (a natural way to write task 8.3) is off by about 6e-8 / sin(theta)^2
 * of itself there, so 1e-6 / sin^2 allows it with room; elsewhere this adds nothing. */
static double pole_rounding(double sin_theta) { return 1e-6 / (sin_theta * sin_theta); }

/* The irradiance of map e on a surface facing +Y, per luminance: the closed form above. */
static double irradiance_up(const envmap *e)
{
    double E = 0.0, dphi = 2.0 * M_PI / e->width;
    for (int y = 0; y < e->height; y++) {
        double t0 = y * M_PI / e->height, t1 = fmin((y + 1) * M_PI / e->height, M_PI / 2);
        if (t1 <= t0) continue;
        double band = 0.5 * (sin(t1) * sin(t1) - sin(t0) * sin(t0)) * dphi;
        for (int x = 0; x < e->width; x++) E += rgb_luminance(envmap_texel(e, x, y)) * band;
    }
    return E;
}

/* ---- task 8.1: env_sample_uniform ------------------------------------------------------------- */

static void test_env_sample_uniform__unit_directions_with_their_pdf_and_radiance(void **state)
{
    (void)state;
    envmap e;
    test_map(&e);
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            vec2 u = vec2_make((i + 0.5f) / 32.0f, (j + 0.5f) / 32.0f);
            vec3 wi;
            float pdf = -1.0f;
            rgb L = env_sample_uniform(&e, u, &wi, &pdf);
            assert_implemented();
            if (!(fabsf(vec3_length(wi) - 1.0f) < 1e-5f))
                PL_FAIL("wrong: env_sample_uniform(u = (%g, %g)) gave wi of length %g, expected a unit direction",
                        (double)u.x, (double)u.y, (double)vec3_length(wi));
            if (!(fabs(pdf * 4.0 * M_PI - 1.0) < 1e-5))
                PL_FAIL("wrong: env_sample_uniform's pdf is %g, expected 1 / (4 pi) = %g per steradian (handout/part8.md, "
                        "8.1)", (double)pdf, 1.0 / (4.0 * M_PI));
            rgb want = envmap_radiance(&e, wi);
            if (L.r != want.r || L.g != want.g || L.b != want.b)
                PL_FAIL("wrong: env_sample_uniform returned (%g, %g, %g) for wi = (%g, %g, %g), where the map holds (%g, "
                        "%g, %g): return envmap_radiance(e, *wi)", (double)L.r, (double)L.g, (double)L.b, (double)wi.x,
                        (double)wi.y, (double)wi.z, (double)want.r, (double)want.g, (double)want.b);
        }
    envmap_free(&e);
}

/* 8 bands of equal height in y (so of equal area: Archimedes) by 16 sectors of phi. */
static void test_env_sample_uniform__uniform_over_the_sphere(void **state)
{
    (void)state;
    enum { BANDS = 8, SECTORS = 16, CELLS = BANDS * SECTORS, N = CELLS * 1000 };
    static double observed[CELLS], expected[CELLS];
    memset(observed, 0, sizeof observed);
    envmap e;
    test_map(&e);
    uint64_t seed = SEED + 1;
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < N; i++) {
        vec3 wi;
        float pdf;
        env_sample_uniform(&e, rng_uniform2(&g), &wi, &pdf);
        if (i == 0) assert_implemented();
        int band = (int)fmin((wi.y + 1.0) / 2.0 * BANDS, BANDS - 1);
        int sector = (int)fmin(envmap_angles(wi).y / (2.0 * M_PI) * SECTORS, SECTORS - 1);
        observed[(band < 0 ? 0 : band) * SECTORS + sector] += 1.0;
    }
    for (int k = 0; k < CELLS; k++) expected[k] = (double)N / CELLS;
    stats_result r = stats_chi2_test(observed, expected, CELLS, 5.0, PART8_CHECK_ALPHA);
    if (r.reject) {
        double top = 0, bottom = 0;
        for (int s = 0; s < SECTORS; s++) top += observed[(BANDS - 1) * SECTORS + s], bottom += observed[s];
        mc_print_seed("env_sample_uniform", seed);
        PL_FAIL("wrong: env_sample_uniform's directions are not uniform over the sphere (chi-square %.1f with %.0f dof, "
                "p = %.3g < alpha %.3g): %.0f in the band around +Y, %.0f around -Y, %d each if uniform%s", r.stat, r.dof,
                r.p, PART8_CHECK_ALPHA, top, bottom, N / BANDS,
                top > 1.2 * N / BANDS ? " (crowded at the poles: theta uniform in [0, pi] is not uniform in area; "
                                        "sample_uniform_sphere is)" : "");
    }
    envmap_free(&e);
}

/* E[L cos / pdf] over the sphere's directions, per luminance, from n samples of sampler. */
typedef rgb (*env_sampler)(const envmap *e, const env_distribution *d, vec2 u, vec3 *wi, float *pdf);
static rgb uniform_sampler(const envmap *e, const env_distribution *d, vec2 u, vec3 *wi, float *pdf)
{
    (void)d;
    return env_sample_uniform(e, u, wi, pdf);
}

/* The density and radiance of direction w by tables d (the test's own) and map e: texel (x, y) of w
 * as texel_of finds it, both of that one texel, so a direction on an edge is weighed consistently. */
static double closed_form_pdf(const envmap *e, const env_distribution *d, vec3 w, rgb *L)
{
    int x, y;
    double fx, fy;
    texel_of(e, w, &x, &y, &fx, &fy);
    *L = envmap_texel(e, x, y);
    double sin_theta = hypot(w.x, w.z) / vec3_length(w);
    return sin_theta > 0.0 ? texel_p(d, x, y) * e->width * e->height / (2.0 * M_PI * M_PI * sin_theta) : 0.0;
}

/* n samples of L cos / pdf for a surface facing +Y, per luminance. Weighed by what the sampler
 * returned, or (closed, with d the test's own tables) by the closed forms at its directions: then
 * only the directions are judged, and a mistake of env_pdf's (task 8.3), which task 8.4 may call
 * for its *pdf, costs task 8.3 alone (its *pdf and radiance are checked one by one elsewhere). */
static stats_acc irradiance_samples(env_sampler sample, const envmap *e, const env_distribution *d, bool closed,
                                    uint64_t seed, int n)
{
    stats_acc a = {0};
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < n; i++) {
        vec3 wi;
        float pdf = 0.0f;
        rgb L = sample(e, d, rng_uniform2(&g), &wi, &pdf);
        if (i == 0) assert_implemented();
        double p = closed ? closed_form_pdf(e, d, wi, &L) : pdf;
        double v = p > 0.0 && wi.y > 0.0f ? rgb_luminance(L) * wi.y / p : 0.0;
        if (!isfinite(v)) PL_FAIL("wrong: sample %d gave L cos / pdf = %g (pdf %g): not a number", i, v, p);
        stats_acc_add(&a, v);
    }
    return a;
}

/* A constant map of radiance L lights a surface with irradiance pi L. */
static void test_env_sample_uniform__a_constant_map_gives_pi_L(void **state)
{
    (void)state;
    envmap e;
    assert_int_equal(PL_OK, envmap_make_constant(&e, 32, 16, rgb_gray(0.75f)));
    stats_acc a = irradiance_samples(uniform_sampler, &e, NULL, false, SEED + 2, 20000);
    mc_print_seed("env_sample_uniform, constant map", SEED + 2);
    assert_mean_matches(&a, M_PI * 0.75, PART8_CHECK_ALPHA, "irradiance from a constant map of 0.75 by env_sample_uniform");
    envmap_free(&e);
}

/* ---- task 8.2: env_build_distribution ----------------------------------------------------------- */

static void build(const envmap *e, env_distribution *d)
{
    assert_int_equal(PL_OK, env_distribution_alloc(d, e->width, e->height));
    env_build_distribution(e, d);
    assert_implemented();
    char why[160];
    if (!env_distribution_check(d, why, sizeof why))
        PL_FAIL("wrong: env_build_distribution's tables are not CDFs: %s (each starts at 0, never decreases and ends "
                "at 1; handout/part8.md, 8.2)", why);
}

static void test_env_build_distribution__tables_are_cdfs(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    test_map(&e);
    build(&e, &d);
    env_distribution_free(&d);
    envmap_free(&e);
    /* All black: nothing to prefer, and still CDFs. */
    assert_int_equal(PL_OK, envmap_make_constant(&e, 8, 4, rgb_gray(0.0f)));
    build(&e, &d);
    env_distribution_free(&d);
    envmap_free(&e);
}

/* Row y's luminance, summed over its texels. */
static double row_luminance(const envmap *e, int y)
{
    double sum = 0.0;
    for (int x = 0; x < e->width; x++) sum += rgb_luminance(envmap_texel(e, x, y));
    return sum;
}

/* Whether row y's conditional table follows the luminance of the map's row `from`. */
static bool row_follows(const envmap *e, const env_distribution *d, int y, int from)
{
    const float *c = d->conditional_cdf + (size_t)y * (e->width + 1);
    double lum_row = row_luminance(e, from);
    for (int x = 0; x < e->width && lum_row > 0.0; x++) {
        double share = (double)c[x + 1] - c[x], want = rgb_luminance(envmap_texel(e, x, from)) / lum_row;
        if (!(fabs(share - want) <= 1e-4 * want + 1e-7)) return false;
    }
    return true;
}

/* The spread (largest over smallest) of the rows' probabilities over the luminance of row from(y)
 * times sin(theta_y), over the rows where that luminance is not 0; HUGE_VAL if a row of probability
 * 0 has luminance or one of luminance 0 has probability. */
static double row_spread(const envmap *e, const env_distribution *d, bool mirrored)
{
    double lo = HUGE_VAL, hi = 0.0;
    for (int y = 0; y < e->height; y++) {
        double lum = row_luminance(e, mirrored ? e->height - 1 - y : y);
        double p = (double)d->marginal_cdf[y + 1] - d->marginal_cdf[y];
        if (lum == 0.0 && p > 1e-7) return HUGE_VAL;
        if (lum == 0.0) continue;
        double ratio = p / lum / sin((y + 0.5) * M_PI / e->height);
        lo = fmin(lo, ratio), hi = fmax(hi, ratio);
    }
    return lo > 0.0 ? hi / lo : HUGE_VAL;
}

/* Which of d's tables take the map's rows in reverse order (row y from row height - 1 - y), where the
 * map's own order would not fit and the reversed one does; NULL if none does. */
static const char *rows_reversed(const envmap *e, const env_distribution *d)
{
    bool own = true, mirrored = true;
    for (int y = 0; y < e->height; y++) {
        own = own && row_follows(e, d, y, y);
        mirrored = mirrored && row_follows(e, d, y, e->height - 1 - y);
    }
    if (!own && mirrored) return "conditional_cdf's";
    if (row_spread(e, d, false) > 1.03 && row_spread(e, d, true) <= 1.03) return "marginal_cdf's";
    return NULL;
}

static void test_env_build_distribution__texels_weigh_luminance_times_sine(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    test_map(&e);
    build(&e, &d);
    const char *reversed = rows_reversed(&e, &d);
    if (reversed)
        PL_FAIL("wrong: %s rows follow the map's rows in reverse order: table row y has the weights of the map's row "
                "%d - y. Row y of the map is envmap_texel(e, x, y), theta from 0 at y = 0 (straight up, +Y) to pi at "
                "the bottom: take the rows as they are (task 8.2, handout/part8.md)", reversed, e.height - 1);
    double row_ratio[8];
    int rows = 0;
    for (int y = 0; y < 8; y++) {
        double lum_row = row_luminance(&e, y), p_row = 0.0;
        for (int x = 0; x < 16; x++) p_row += texel_p(&d, x, y);
        for (int x = 0; x < 16; x++) {
            double lum = rgb_luminance(envmap_texel(&e, x, y)), p = texel_p(&d, x, y);
            if (lum == 0.0 && p > 1e-7)
                PL_FAIL("wrong: texel (%d, %d) is black but has probability %g: it would be drawn for no light (task "
                        "8.2)", x, y, p);
            if (lum > 0.0 && fabs(p / p_row - lum / lum_row) > 1e-4 * (lum / lum_row) + 1e-7)
                PL_FAIL("wrong: within row %d, texel %d has %.5f of the row's probability but %.5f of its luminance: "
                        "conditional_cdf should follow luminance (rgb_luminance; task 8.2, handout/part8.md)", y, x,
                        p / p_row, lum / lum_row);
        }
        if (lum_row > 0.0) row_ratio[rows++] = p_row / lum_row / sin((y + 0.5) * M_PI / 8);
        else if (p_row > 1e-7) PL_FAIL("wrong: row %d is black but has probability %g (task 8.2)", y, p_row);
    }
    /* Per unit luminance, each row's weight over sin(theta at its centre): equal within what another
     * weight from the row's range of sin(theta) allows (3%: the exact solid angle of the row). */
    double lo = row_ratio[0], hi = row_ratio[0];
    for (int i = 1; i < rows; i++) lo = fmin(lo, row_ratio[i]), hi = fmax(hi, row_ratio[i]);
    if (!(hi <= 1.03 * lo))
        PL_FAIL("wrong: the rows' probabilities per unit of luminance are not in proportion to sin(theta): they vary "
                "%.3g-fold from row to row once divided by it (a row near a pole covers less of the sphere; weigh each "
                "row by sin(theta) at its centre; task 8.2, handout/part8.md)", hi / lo);
    env_distribution_free(&d);
    envmap_free(&e);
}

/* ---- task 8.3: env_pdf --------------------------------------------------------------------------- */

static void test_env_pdf__closed_form_in_every_texel(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    test_map(&e);
    oracle_tables(&e, &d);
    const float at[3] = {0.5f, 0.2f, 0.8f};
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++)
            for (int k = 0; k < 3; k++) {
                float theta = ((float)y + at[k]) * PL_PI / 8.0f, phi = ((float)x + at[(k + 1) % 3]) * 2.0f * PL_PI / 16.0f;
                vec3 w = envmap_direction(theta, phi);
                float pdf = env_pdf(&e, &d, w);
                assert_implemented();
                double want = texel_p(&d, x, y) * 16.0 * 8.0 / (2.0 * M_PI * M_PI * sin(theta));
                if (!(fabs(pdf - want) <= (1e-4 + pole_rounding(sin(theta))) * want + 1e-7)) {
                    double ratio = want > 0.0 ? pdf / want : 0.0;
                    PL_FAIL("wrong: env_pdf at theta = %.4f, phi = %.4f (texel (%d, %d), probability %.5g) is %.6g, "
                            "expected p w h / (2 pi^2 sin(theta)) = %.6g%s", (double)theta, (double)phi, x, y,
                            texel_p(&d, x, y), (double)pdf, want,
                            fabs(ratio - sin(theta)) < 1e-3 * sin(theta) + 1e-6
                                ? " (off by sin(theta): the Jacobian divides by it; handout/part8.md, 8.3)" : "");
                }
            }
    float up = env_pdf(&e, &d, vec3_make(0, 1, 0)), down = env_pdf(&e, &d, vec3_make(0, -1, 0));
    if (!(isfinite(up) && up >= 0.0f && isfinite(down) && down >= 0.0f))
        PL_FAIL("wrong: env_pdf at the poles is %g and %g: expected finite densities (0 where sin(theta) is 0)",
                (double)up, (double)down);
    env_distribution_free(&d);
    envmap_free(&e);
}

/* The sum of pdf(w) dw over a grid of 4 x 4 points in each texel. */
static void test_env_pdf__integrates_to_one(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    test_map(&e);
    oracle_tables(&e, &d);
    double sum = 0.0, dtheta = M_PI / 32, dphi = 2 * M_PI / 64;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 64; j++) {
            double theta = (i + 0.5) * dtheta, phi = (j + 0.5) * dphi;
            sum += env_pdf(&e, &d, envmap_direction((float)theta, (float)phi)) * sin(theta) * dtheta * dphi;
            if (i == 0 && j == 0) assert_implemented();
        }
    if (!(fabs(sum - 1.0) < 2e-3))
        PL_FAIL("wrong: env_pdf integrates to %.4f over the sphere, expected 1 (the density per steradian: p w h / (2 pi^2 "
                "sin(theta)); handout/part8.md, 8.3)", sum);
    env_distribution_free(&d);
    envmap_free(&e);
}

/* ---- task 8.4: env_sample_importance ----------------------------------------------------------- */

/* The interval i of a CDF of n intervals with cdf[i] <= u < cdf[i + 1] (never an empty one). */
static int cdf_interval(const float *cdf, int n, float u)
{
    int i = 0;
    while (i < n - 1 && !(u < cdf[i + 1])) i++;
    return i;
}

/* The texel the handout's sampler draws for u from tables d: the row by u.y, then the column by u.x.
 * Only the messages use it: the verdict is the distribution's, whatever the search. */
static void texel_for_u(const env_distribution *d, vec2 u, int *x, int *y)
{
    *y = cdf_interval(d->marginal_cdf, d->height, u.y);
    *x = cdf_interval(d->conditional_cdf + (size_t)*y * (d->width + 1), d->width, u.x);
}

/* What the directions of env_sample_importance did, sample by sample, for the messages: how many sit
 * on a texel's corner, how many lie in the texel u draws, and how many in that texel's row mirrored
 * (row height - 1 - y). */
typedef struct { long corner, drawn, mirrored; } texel_tally;

static void tally_direction(texel_tally *t, const env_distribution *d, vec2 u, int x, int y, double fx, double fy)
{
    int ux, uy;
    texel_for_u(d, u, &ux, &uy);
    const double edge = 1e-3;
    t->corner += (fx < edge || fx > 1 - edge) && (fy < edge || fy > 1 - edge);
    t->drawn += x == ux && y == uy;
    t->mirrored += x == ux && y == d->height - 1 - uy && uy != d->height - 1 - uy;
}

/* A direction fell in a texel of probability 0: names the texel u draws, and the rows' order when the
 * direction is in its mirror image. */
static void fail_black_texel(const env_distribution *d, vec2 u, int x, int y)
{
    int ux, uy;
    texel_for_u(d, u, &ux, &uy);
    if (x == ux && y == d->height - 1 - uy)
        PL_FAIL("wrong: env_sample_importance(u = (%.6f, %.6f)) gave a direction in texel (%d, %d), whose probability is "
                "0; u draws texel (%d, %d) (marginal_cdf[y] <= u.y < marginal_cdf[y + 1]), and row %d is row %d counted "
                "from the bottom: the rows are in reverse order. theta = (y + fy) pi / height, from 0 at row 0 (straight "
                "up, +Y) (task 8.4, handout/part8.md)", (double)u.x, (double)u.y, x, y, ux, uy, y, uy);
    PL_FAIL("wrong: env_sample_importance(u = (%.6f, %.6f)) gave a direction in texel (%d, %d), whose probability is 0 "
            "(a black texel); u draws texel (%d, %d): the row y with marginal_cdf[y] <= u.y < marginal_cdf[y + 1], then "
            "the column the same way in row y's conditional_cdf (task 8.4, handout/part8.md)", (double)u.x, (double)u.y,
            x, y, ux, uy);
}

/* Why the directions do not follow the tables, where the counts say so beyond doubt: the texel
 * choice (the counts per texel) or the point within it (each texel's 2 x 2 cells against a quarter
 * of its own count each). Each at a level far below any check's, counted in no budget: a hint, not a
 * verdict, and none for a failure that is only chance (a correct solution's 1 in 1000). */
static const char *texel_hint(const double *observed, const double *expected, int texels, const texel_tally *t, long n)
{
    static double per_texel[2][512], within[2][2048];
    for (int k = 0; k < texels; k++) {
        per_texel[0][k] = observed[4 * k] + observed[4 * k + 1] + observed[4 * k + 2] + observed[4 * k + 3];
        per_texel[1][k] = expected[4 * k] + expected[4 * k + 1] + expected[4 * k + 2] + expected[4 * k + 3];
        for (int c = 0; c < 4; c++) within[0][4 * k + c] = observed[4 * k + c], within[1][4 * k + c] = per_texel[0][k] / 4;
    }
    const double sure = 1e-6;
    bool texels_wrong = stats_chi2_test(per_texel[0], per_texel[1], texels, 5.0, sure).reject;
    bool within_wrong = stats_chi2_test(within[0], within[1], 4 * texels, 5.0, sure).reject;
    if (t->corner > 0.9 * n)
        return ": every direction sits on a corner of its texel (theta = y pi / height, phi = x 2 pi / width: "
               "CS184's way), so each texel's samples take one direction. Place the point within the texel at the "
               "fraction of its step that u fell at, fy = (u.y - marginal_cdf[y]) / (marginal_cdf[y + 1] - "
               "marginal_cdf[y]) and fx likewise";
    if (t->mirrored > 0.5 * n)
        return ": most directions lie in the row of the texel u draws counted from the bottom, not from the top: the "
               "rows are in reverse order (theta = (y + fy) pi / height, from 0 at row 0, straight up)";
    if (texels_wrong && t->drawn < 0.5 * n)
        return ": the texels are not drawn in proportion to their probabilities, and most directions are not in the "
               "texel u draws (the row y with marginal_cdf[y] <= u.y < marginal_cdf[y + 1], then the column the same "
               "way in row y's conditional_cdf)";
    if (texels_wrong) return ": the texels are not drawn in proportion to their probabilities";
    if (within_wrong)
        return ": each texel gets its share, but the points within a texel are not uniform in (theta, phi): place "
               "each at the fraction of its step that u fell at";
    return "";
}

static void test_env_sample_importance__directions_follow_the_texels(void **state)
{
    (void)state;
    enum { W = 16, H = 8, CELLS = W * H * 4, N = 200000 };
    static double observed[CELLS], expected[CELLS];
    memset(observed, 0, sizeof observed);
    envmap e;
    env_distribution d;
    test_map(&e);
    oracle_tables(&e, &d);
    uint64_t seed = SEED + 3;
    rng g = rng_seeded(seed, 0);
    texel_tally tally = {0, 0, 0};
    for (int i = 0; i < N; i++) {
        vec3 wi;
        float pdf;
        vec2 u = rng_uniform2(&g);
        env_sample_importance(&e, &d, u, &wi, &pdf);
        if (i == 0) assert_implemented();
        int x, y;
        double fx, fy;
        texel_of(&e, wi, &x, &y, &fx, &fy);
        tally_direction(&tally, &d, u, x, y, fx, fy);
        /* A direction on the edge of a black texel: rounding put it across the edge from the texel it
         * was drawn in, which is the one beside it (its angles are rounded to a float). */
        if (texel_p(&d, x, y) == 0.0) {
            const double edge = 1e-4;
            if (fy < edge && y > 0 && texel_p(&d, x, y - 1) > 0.0) y--, fy = 0.75;
            else if (fy > 1 - edge && y < H - 1 && texel_p(&d, x, y + 1) > 0.0) y++, fy = 0.25;
            else if (fx < edge && texel_p(&d, (x + W - 1) % W, y) > 0.0) x = (x + W - 1) % W, fx = 0.75;
            else if (fx > 1 - edge && texel_p(&d, (x + 1) % W, y) > 0.0) x = (x + 1) % W, fx = 0.25;
            else fail_black_texel(&d, u, x, y);
        }
        observed[((y * W + x) * 2 + (fy >= 0.5)) * 2 + (fx >= 0.5)] += 1.0;
    }
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int k = 0; k < 4; k++) expected[(y * W + x) * 4 + k] = texel_p(&d, x, y) / 4.0 * N;
    stats_result r = stats_chi2_test(observed, expected, CELLS, 5.0, PART8_CHECK_ALPHA);
    if (r.reject) {
        mc_print_seed("env_sample_importance", seed);
        PL_FAIL("wrong: env_sample_importance's directions do not follow the tables (chi-square %.1f with %.0f dof, p = "
                "%.3g < alpha %.3g)%s (task 8.4, handout/part8.md)", r.stat, r.dof, r.p, PART8_CHECK_ALPHA,
                texel_hint(observed, expected, W * H, &tally, N));
    }
    env_distribution_free(&d);
    envmap_free(&e);
}

static void test_env_sample_importance__pdf_and_radiance_are_the_directions(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    test_map(&e);
    oracle_tables(&e, &d);
    rng g = rng_seeded(SEED + 4, 0);
    for (int i = 0; i < 4096; i++) {
        vec3 wi;
        float pdf;
        vec2 u = rng_uniform2(&g);
        rgb L = env_sample_importance(&e, &d, u, &wi, &pdf);
        if (i == 0) assert_implemented();
        if (!(fabsf(vec3_length(wi) - 1.0f) < 1e-5f))
            PL_FAIL("wrong: env_sample_importance gave wi of length %g: expected a unit direction", (double)vec3_length(wi));
        int x, y;
        double fx, fy;
        texel_of(&e, wi, &x, &y, &fx, &fy);
        if (fx < 1e-4 || fx > 1 - 1e-4 || fy < 1e-4 || fy > 1 - 1e-4) continue;  /* on a texel's edge: either side */
        /* sin(theta) from the direction itself: acos loses its digits near a pole. */
        double sin_theta = hypot(wi.x, wi.z) / vec3_length(wi);
        double want = texel_p(&d, x, y) * 16.0 * 8.0 / (2.0 * M_PI * M_PI * sin_theta);
        /* The closed form, or the candidate's own env_pdf at the direction, as the contract allows: a
         * mistake of task 8.3's is its own. */
        double slack = 1e-3 + pole_rounding(sin_theta);
        if (!(fabs(pdf - want) <= slack * want) && !(fabs(pdf - env_pdf(&e, &d, wi)) <= slack * fabs(pdf))) {
            int ux, uy;
            texel_for_u(&d, u, &ux, &uy);
            PL_FAIL("wrong: env_sample_importance(u = (%.6f, %.6f)) set *pdf = %.6g for a direction in texel (%d, %d), "
                    "whose density is %.6g (env_pdf's closed form), and env_pdf there says %.6g%s (task 8.4, "
                    "handout/part8.md)", (double)u.x, (double)u.y, (double)pdf, x, y, want, (double)env_pdf(&e, &d, wi),
                    x == ux && y == uy ? "" : "; u draws another texel, whose density it may be: is the direction "
                                              "in the texel drawn?");
        }
        rgb T = envmap_texel(&e, x, y);
        if (L.r != T.r || L.g != T.g || L.b != T.b)
            PL_FAIL("wrong: env_sample_importance returned (%g, %g, %g) for a direction in texel (%d, %d), which holds "
                    "(%g, %g, %g)", (double)L.r, (double)L.g, (double)L.b, x, y, (double)T.r, (double)T.g, (double)T.b);
    }
    env_distribution_free(&d);
    envmap_free(&e);
}

static void test_env_sample_importance__a_constant_map_gives_pi_L(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    assert_int_equal(PL_OK, envmap_make_constant(&e, 32, 16, rgb_gray(0.75f)));
    oracle_tables(&e, &d);
    stats_acc a = irradiance_samples(env_sample_importance, &e, &d, true, SEED + 5, 20000);
    mc_print_seed("env_sample_importance, constant map", SEED + 5);
    assert_mean_matches(&a, M_PI * 0.75, PART8_CHECK_ALPHA, "irradiance from a constant map of 0.75 by env_sample_importance");
    env_distribution_free(&d);
    envmap_free(&e);
}

/* The same light as uniform sampling (its closed form), with far less noise. The variances are
 * compared, not tested: their ratio is about 350 (printed below), and the bound is 10. */
static void test_env_sample_importance__a_sun_with_less_noise_than_uniform(void **state)
{
    (void)state;
    envmap e;
    env_distribution d;
    sun_map(&e);
    oracle_tables(&e, &d);
    double E = irradiance_up(&e);
    stats_acc imp = irradiance_samples(env_sample_importance, &e, &d, true, SEED + 6, 20000);
    mc_print_seed("env_sample_importance, a sun", SEED + 6);
    assert_mean_matches(&imp, E, PART8_CHECK_ALPHA, "irradiance from a sky with a sun by env_sample_importance");
    stats_acc uni = irradiance_samples(uniform_sampler, &e, NULL, false, SEED + 7, 20000);
    double ratio = stats_acc_var(&uni) / stats_acc_var(&imp);
    printf("    irradiance %.4f (closed form); variance of one sample: uniform %.4g, importance %.4g (%.1fx less)\n", E,
           stats_acc_var(&uni), stats_acc_var(&imp), ratio);
    if (!(ratio > 10.0))
        PL_FAIL("wrong: on a sky with a sun, importance sampling's variance is only %.2fx below uniform sampling's, "
                "expected far more: are the texels drawn in proportion to their brightness?", ratio);
    env_distribution_free(&d);
    envmap_free(&e);
}

int envlight_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_env_sample_uniform__unit_directions_with_their_pdf_and_radiance),
        cmocka_unit_test(test_env_sample_uniform__uniform_over_the_sphere),
        cmocka_unit_test(test_env_sample_uniform__a_constant_map_gives_pi_L),
        cmocka_unit_test(test_env_build_distribution__tables_are_cdfs),
        cmocka_unit_test(test_env_build_distribution__texels_weigh_luminance_times_sine),
        cmocka_unit_test(test_env_pdf__closed_form_in_every_texel),
        cmocka_unit_test(test_env_pdf__integrates_to_one),
        cmocka_unit_test(test_env_sample_importance__directions_follow_the_texels),
        cmocka_unit_test(test_env_sample_importance__pdf_and_radiance_are_the_directions),
        cmocka_unit_test(test_env_sample_importance__a_constant_map_gives_pi_L),
        cmocka_unit_test(test_env_sample_importance__a_sun_with_less_noise_than_uniform),
    };
    return cmocka_run_group_tests_name("part8: the environment light, task by task (tasks 8.1-8.4)", tests, NULL, NULL);
}
