/* Test machinery: not part of any assignment.
 * Part 7, microfacet conductors, task by task, each against its closed form computed here in
 * double from the handout's formulas (never from the solution's code):
 * - beckmann_d (7.1): the value over angles and roughnesses, 0 below the surface, and its
 *   projected area, the integral of D cos(theta_h) over the hemisphere, 1 (numerical quadrature).
 * - fresnel_conductor (7.2): the value per channel for three metals over the cosines, 1 at grazing.
 * - microfacet_g (7.3): Smith's term with the Beckmann Lambda.
 * - microfacet_f (7.4): the value (with F at the half vector's angle), 0 unless both directions are
 *   above the surface (on pairs whose half vector is near the normal, where D(h) is far from 0),
 *   and reciprocity f(wo, wi) = f(wi, wo).
 * - microfacet_pdf (7.5): the value, the Jacobian 1 / (4 dot(wo, h)) and cos(theta_h) included;
 *   0 below the surface.
 * - microfacet_sample_f (7.6): every sample's f and pdf are microfacet_f's and microfacet_pdf's; the
 *   directions follow the pdf (Pearson's chi-square over 20 bands of equal cos(theta) by 32
 *   sectors, the expected counts from the pdf integrated over each cell, and one cell for the
 *   samples lost below the surface: the method of Nori and pbrt); and the mean weight
 *   f cos / pdf, by the closed forms at its directions, is the BSDF's albedo, the integral of f cos
 *   over the hemisphere (a furnace test: a sampler whose directions do not average to the albedo
 *   adds or loses energy), by t test.
 * Tasks 7.4 and 7.5 put earlier tasks together; the same file holds them, so no test can hand them
 * the course's D, F and G. A value that matches what the candidate's own 7.1-7.3 return, put
 * together right, passes as well as the closed form: a mistake in 7.1-7.3 costs only its own task.
 * Nothing depends on the order of a sampler's draws or on which of u.x and u.y picks the angle: the
 * samples are judged as a distribution.
 * alpha: six statistical checks (two per sampled case), each at PART7_CHECK_ALPHA (family alpha
 * 1e-3 and budget: part7_alpha.h). Seeds are fixed, printed, and changed by PL_TEST_SEED. */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "part7_alpha.h"
#include "../../parts/part7_microfacet/part7.h"

#define SEED mc_seed(0x5eed7001ull)
#define DIRECTIONS 2000

/* Three metals' eta and k at 650, 550 and 450 nm. */
static const rgb GOLD_ETA = {0.143f, 0.374f, 1.442f}, GOLD_K = {3.983f, 2.385f, 1.603f};
static const rgb AL_ETA = {1.657f, 0.880f, 0.521f}, AL_K = {9.224f, 6.270f, 4.837f};
static const rgb CU_ETA = {0.200f, 0.924f, 1.102f}, CU_K = {3.912f, 2.452f, 2.142f};

/* ---- the closed forms, in double ----------------------------------------------------------- */

static double ref_d(double alpha, double hz)
{
    if (!(hz > 0.0)) return 0.0;
    double c2 = hz * hz, tan2 = (1.0 - c2) / c2, a2 = alpha * alpha;
    return exp(-tan2 / a2) / (M_PI * a2 * c2 * c2);
}

static double ref_f1(double c, double eta, double k)
{
    double t = eta * eta + k * k, c2 = c * c;
    double rs = (t - 2 * eta * c + c2) / (t + 2 * eta * c + c2), rp = (t * c2 - 2 * eta * c + 1) / (t * c2 + 2 * eta * c + 1);
    return 0.5 * (rs + rp);
}

static double ref_lambda(double alpha, double z)
{
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    if (s == 0.0) return 0.0;
    double a = fabs(z) / (alpha * s);
    return a >= 1.6 ? 0.0 : (1 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
}

static double ref_g(double alpha, vec3 wo, vec3 wi) { return 1.0 / (1.0 + ref_lambda(alpha, wo.z) + ref_lambda(alpha, wi.z)); }

/* The half vector of wo and wi, in double; *len its unnormalised length. */
static void half_vector(vec3 wo, vec3 wi, double h[3])
{
    double x = (double)wo.x + wi.x, y = (double)wo.y + wi.y, z = (double)wo.z + wi.z, n = sqrt(x * x + y * y + z * z);
    h[0] = x / n, h[1] = y / n, h[2] = z / n;
}

/* f per channel c (0, 1, 2) with F at cos fresnel_cos. */
static double ref_f(const material *m, vec3 wo, vec3 wi, int c, bool at_surface)
{
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0;
    double h[3];
    half_vector(wo, wi, h);
    double cos_h = wi.x * h[0] + wi.y * h[1] + wi.z * h[2];
    const float *eta = &m->eta.r, *k = &m->k.r;
    double F = ref_f1(at_surface ? wi.z : fmin(1.0, cos_h), eta[c], k[c]);
    return F * ref_g(m->alpha, wo, wi) * ref_d(m->alpha, h[2]) / (4.0 * wo.z * wi.z);
}

static double ref_pdf(double alpha, vec3 wo, vec3 wi)
{
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0;
    double h[3];
    half_vector(wo, wi, h);
    double cos_o = wo.x * h[0] + wo.y * h[1] + wo.z * h[2];
    return ref_d(alpha, h[2]) * h[2] / (4.0 * cos_o);
}

static vec3 dir_at(double theta, double phi)
{
    return vec3_make((float)(sin(theta) * cos(phi)), (float)(sin(theta) * sin(phi)), (float)cos(theta));
}

static vec3 upper_dir(rng *g)
{
    vec2 u = rng_uniform2(g);
    return dir_at(acos(fmin(1.0, 0.02 + 0.98 * u.x)), 2.0 * M_PI * u.y);
}

static bool near(double got, double want, double rel, double floor_abs)
{
    return fabs(got - want) <= rel * fabs(want) + floor_abs;
}

static material metal(double alpha, rgb eta, rgb k)
{
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    m.kind = MATERIAL_MICROFACET;
    m.alpha = (float)alpha;
    m.eta = eta;
    m.k = k;
    return m;
}

/* ---- 7.1 ----------------------------------------------------------------------------------- */

static void test_beckmann_d__matches_the_closed_form(void **state)
{
    (void)state;
    const double alphas[] = {0.05, 0.2, 0.5, 1.0};
    for (int a = 0; a < 4; a++)
        for (int t = 0; t <= 85; t += 5)
            for (int p = 0; p < 3; p++) {
                vec3 h = dir_at(t * M_PI / 180.0, p * 2.1);
                float got = beckmann_d((float)alphas[a], h);
                assert_implemented();
                double want = ref_d(alphas[a], h.z), peak = ref_d(alphas[a], 1.0);
                if (!near(got, want, 1e-4, 1e-6 * peak))
                    PL_FAIL("wrong: beckmann_d(alpha %g, h at %d degrees) = %g, expected exp(-tan^2 / alpha^2) / (pi alpha^2 "
                            "cos^4) = %g (handout/part7.md, 7.1)%s", alphas[a], t, (double)got, want,
                            near(got / ((double)h.z * h.z), want, 1e-3, 1e-6 * peak) ? " (this is cos^2, not cos^4)" :
                            near(got / M_PI, want, 1e-3, 1e-6 * peak) ? " (the pi is missing)" : "");
            }
    if (beckmann_d(0.3f, vec3_make(0.6f, 0.0f, -0.8f)) != 0.0f)
        PL_FAIL("wrong: beckmann_d of a normal below the surface (h.z = -0.8) is not 0 (handout/part7.md, 7.1)");
}

static void test_beckmann_d__projected_area_is_one(void **state)
{
    (void)state;
    const double alphas[] = {0.1, 0.3, 0.6};
    for (int a = 0; a < 3; a++) {
        /* Simpson's rule over theta in [0, pi/2] of D cos sin, times 2 pi (D does not depend on phi). */
        const int n = 20000;
        double sum = 0.0, step = M_PI / 2 / n;
        for (int i = 0; i < n; i++) {  /* the last point, theta = pi/2, adds D cos = 0 */
            double th = i * step, w = i == 0 ? 1 : (i % 2 ? 4 : 2);
            sum += w * beckmann_d((float)alphas[a], dir_at(th, 0.7)) * cos(th) * sin(th);
        }
        assert_implemented();
        double area = 2 * M_PI * sum * step / 3;
        if (!(fabs(area - 1.0) < 2e-3))
            PL_FAIL("wrong: the integral of beckmann_d(alpha %g, h) cos(theta_h) over the hemisphere is %.5f, expected 1: the "
                    "microfacets' projected area must be the surface's (handout/part7.md, 7.1)", alphas[a], area);
    }
}

/* ---- 7.2, 7.3 ------------------------------------------------------------------------------ */

static void test_fresnel_conductor__matches_the_closed_form(void **state)
{
    (void)state;
    const rgb *etas[] = {&GOLD_ETA, &AL_ETA, &CU_ETA}, *ks[] = {&GOLD_K, &AL_K, &CU_K};
    const char *names[] = {"gold", "aluminium", "copper"};
    for (int mtl = 0; mtl < 3; mtl++)
        for (int i = 0; i <= 20; i++) {
            double c = i / 20.0;
            rgb got = fresnel_conductor((float)c, *etas[mtl], *ks[mtl]);
            assert_implemented();
            const float *g = &got.r, *e = &etas[mtl]->r, *k = &ks[mtl]->r;
            for (int ch = 0; ch < 3; ch++) {
                double want = ref_f1(c, e[ch], k[ch]);
                if (!near(g[ch], want, 1e-4, 1e-6))
                    PL_FAIL("wrong: fresnel_conductor(cos %.2f) for %s, channel %d, is %g, expected (Rs + Rp) / 2 = %g "
                            "(handout/part7.md, 7.2)%s", c, names[mtl], ch, (double)g[ch], want,
                            near(g[ch], ref_f1(c, e[ch], 0.0), 1e-3, 1e-6) ? " (this ignores k: a metal absorbs)" : "");
            }
        }
}

static void test_microfacet_g__matches_smith(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED, 3);
    const double alphas[] = {0.1, 0.4, 0.9};
    for (int a = 0; a < 3; a++)
        for (int i = 0; i < DIRECTIONS; i++) {
            vec3 wo = upper_dir(&g), wi = upper_dir(&g);
            float got = microfacet_g((float)alphas[a], wo, wi);
            assert_implemented();
            double want = ref_g(alphas[a], wo, wi);
            if (!near(got, want, 1e-4, 1e-7))
                PL_FAIL("wrong: microfacet_g(alpha %g, wo.z %.4f, wi.z %.4f) = %g, expected 1 / (1 + Lambda(wo) + Lambda(wi)) = "
                        "%g (handout/part7.md, 7.3)%s", alphas[a], (double)wo.z, (double)wi.z, (double)got, want,
                        near(got, 1.0 / (1.0 + ref_lambda(alphas[a], wi.z)), 1e-4, 1e-7)
                            ? " (this is wi's term alone: wo's masking counts too)" : "");
        }
}

/* ---- 7.4, 7.5 ------------------------------------------------------------------------------ */

/* Pairs with one direction below the surface whose half vector is near the normal, where D(h) is far
 * from 0, so a formula that ignores the side of the surface gives a colour there, never the 0 that
 * D's underflow would hand it (a half vector 73 degrees off the normal, at alpha 0.3): wo at 80
 * degrees against wi at 95 on the other side (theta_h 7.5 degrees, D(h) 0.85 of its peak), the same
 * swapped, and wo at 60 against wi at 100 (theta_h 20 degrees, D(h) 0.29 of its peak). */
static void below_surface_pair(int i, vec3 *wo, vec3 *wi)
{
    const double deg = M_PI / 180.0, pairs[][4] = {{80, 0.0, 95, M_PI}, {95, M_PI, 80, 0.0}, {60, 1.0, 100, 1.0 + M_PI}};
    *wo = dir_at(pairs[i][0] * deg, pairs[i][1]);
    *wi = dir_at(pairs[i][2] * deg, pairs[i][3]);
}
#define BELOW_SURFACE_PAIRS 3

/* The half vector's angle to the normal, in degrees, for the messages. */
static double half_angle(vec3 wo, vec3 wi)
{
    double h[3];
    half_vector(wo, wi, h);
    return acos(h[2]) * 180.0 / M_PI;
}

/* microfacet_f as the candidate's own tasks 7.1-7.3 make it, channel c: a mistake of theirs is theirs
 * alone, and 7.4 is judged on how it puts them together. Called only where the closed form fails. */
static double own_f(const material *m, vec3 wo, vec3 wi, int c)
{
    double h[3];
    half_vector(wo, wi, h);
    double cos_h = wi.x * h[0] + wi.y * h[1] + wi.z * h[2];
    rgb F = fresnel_conductor((float)fmin(1.0, cos_h), m->eta, m->k);
    float D = beckmann_d(m->alpha, vec3_make((float)h[0], (float)h[1], (float)h[2])), G = microfacet_g(m->alpha, wo, wi);
    return (double)(&F.r)[c] * G * D / (4.0 * wo.z * wi.z);
}

/* One pair: f against the closed form (or its own tasks' composition), then reciprocity. */
static void check_f_pair(const material *m, vec3 wo, vec3 wi)
{
    rgb got = microfacet_f(m, wo, wi), back = microfacet_f(m, wi, wo);
    assert_implemented();
    const float *gv = &got.r, *bv = &back.r;
    for (int c = 0; c < 3; c++) {
        vec3 mirror = vec3_make(-wo.x, -wo.y, wo.z);
        double want = ref_f(m, wo, wi, c, false), peak = ref_f(m, wo, mirror, c, false);
        if (!near(gv[c], want, 2e-4, 1e-6 * peak) && !near(gv[c], own_f(m, wo, wi, c), 2e-4, 1e-6 * peak))
            PL_FAIL("wrong: microfacet_f (alpha %g) for wo.z %.4f, wi.z %.4f, channel %d is %g, expected "
                    "F(dot(wi, h)) G D / (4 cos_o cos_i) = %g, %.2g%% off (task 7.4, handout/part7.md)%s", (double)m->alpha,
                    (double)wo.z, (double)wi.z, c, (double)gv[c], want, 100.0 * fabs(gv[c] / want - 1.0),
                    near(gv[c], ref_f(m, wo, wi, c, true), 2e-4, 1e-6 * peak)
                        ? " (F is taken at the surface's angle, wi.z: the microfacet that reflects is tilted, "
                          "take F at dot(wi, h))" : "");
        /* Unless its own 7.2 or 7.3 is what makes the two orders differ (their tests say so). */
        if (!near(bv[c], gv[c], 2e-4, 1e-6 * peak) && !near(bv[c], own_f(m, wi, wo, c), 2e-4, 1e-6 * peak))
            PL_FAIL("wrong: microfacet_f is not reciprocal: f(wo, wi) = %g but f(wi, wo) = %g (wo.z %.4f, wi.z %.4f; "
                    "task 7.4, handout/part7.md)", (double)gv[c], (double)bv[c], (double)wo.z, (double)wi.z);
    }
}

static void test_microfacet_f__matches_the_closed_form_and_is_reciprocal(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED, 4);
    const material ms[] = {metal(0.3, GOLD_ETA, GOLD_K), metal(0.08, AL_ETA, AL_K)};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < DIRECTIONS; i++) {
            vec3 wo = upper_dir(&g), wi = upper_dir(&g);
            check_f_pair(&ms[j], wo, wi);
        }
    for (int i = 0; i < BELOW_SURFACE_PAIRS; i++) {
        vec3 wo, wi;
        below_surface_pair(i, &wo, &wi);
        rgb f = microfacet_f(&ms[0], wo, wi);
        if (!rgb_is_black(f))
            PL_FAIL("wrong: microfacet_f(wo.z %.3f, wi.z %.3f) is (%g, %g, %g), expected black: %s below the surface, "
                    "and a conductor only reflects (task 7.4, handout/part7.md). The half vector is %.0f degrees from "
                    "the normal, where D(h) = %.3g is far from 0, so the formula alone does not give 0 there: check "
                    "wo.z > 0 and wi.z > 0 first", (double)wo.z, (double)wi.z, (double)f.r, (double)f.g, (double)f.b,
                    wo.z > 0.0f ? "wi is" : "wo is", half_angle(wo, wi), ref_d(ms[0].alpha, cos(half_angle(wo, wi) * M_PI / 180.0)));
    }
}

/* How a wrong pdf compares with the closed form, when it does in a telling way. */
static const char *pdf_hint(double got, double want, double alpha, vec3 wo, vec3 wi, double peak)
{
    double h[3];
    half_vector(wo, wi, h);
    if (near(got, ref_d(alpha, h[2]) * h[2], 2e-4, 1e-6 * peak))
        return " (the density of h, without the Jacobian 1 / (4 dot(wo, h)) that turns it into a density of wi)";
    if (near(got, want / h[2], 2e-4, 1e-6 * peak))
        return " (it is the closed form over cos(theta_h): the density of h is D(h) cos(theta_h), and the cos(theta_h) "
               "is missing; the two are near where h is near the normal, far apart where it is not)";
    return "";
}

static void test_microfacet_pdf__matches_the_closed_form(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED, 5);
    const double alphas[] = {0.1, 0.5};
    for (int a = 0; a < 2; a++) {
        material m = metal(alphas[a], GOLD_ETA, GOLD_K);
        for (int i = 0; i < DIRECTIONS; i++) {
            vec3 wo = upper_dir(&g), wi = upper_dir(&g);
            float got = microfacet_pdf(&m, wo, wi);
            assert_implemented();
            double want = ref_pdf(alphas[a], wo, wi), peak = ref_pdf(alphas[a], wo, vec3_make(-wo.x, -wo.y, wo.z));
            if (near(got, want, 2e-4, 1e-6 * peak)) continue;
            /* The candidate's own D (task 7.1) put together right is 7.5's part done. */
            double h[3];
            half_vector(wo, wi, h);
            float D = beckmann_d(m.alpha, vec3_make((float)h[0], (float)h[1], (float)h[2]));
            double cos_o = wo.x * h[0] + wo.y * h[1] + wo.z * h[2];
            if (near(got, D * h[2] / (4.0 * cos_o), 2e-4, 1e-6 * peak)) continue;
            PL_FAIL("wrong: microfacet_pdf (alpha %g) for wo.z %.4f, wi.z %.4f (theta_h %.1f degrees) is %g, expected "
                    "D(h) cos(theta_h) / (4 dot(wo, h)) = %g: a ratio of %.5g, far beyond float rounding (task 7.5, "
                    "handout/part7.md)%s", alphas[a], (double)wo.z, (double)wi.z, half_angle(wo, wi), (double)got, want,
                    got / want, pdf_hint(got, want, alphas[a], wo, wi, peak));
        }
        for (int i = 0; i < BELOW_SURFACE_PAIRS; i++) {
            vec3 wo, wi;
            below_surface_pair(i, &wo, &wi);
            float pdf = microfacet_pdf(&m, wo, wi);
            if (pdf != 0.0f)
                PL_FAIL("wrong: microfacet_pdf(wo.z %.3f, wi.z %.3f) is %g, expected 0: %s below the surface, where "
                        "task 7.6 never sends a sample (task 7.5, handout/part7.md; the half vector is %.0f degrees from "
                        "the normal, where D(h) is far from 0: check the sides first)", (double)wo.z, (double)wi.z,
                        (double)pdf, wo.z > 0.0f ? "wi is" : "wo is", half_angle(wo, wi));
        }
    }
}

/* ---- 7.6 ----------------------------------------------------------------------------------- */

#define BANDS 20
#define SECTORS 32
#define CELLS (BANDS * SECTORS + 1)  /* the last: samples lost below the surface */
#define SAMPLES 200000
#define QUAD 8  /* quadrature points per cell side */

/* The cell of a direction above the surface: bands of equal cos(theta), sectors of equal phi. */
static int cell_of(vec3 w)
{
    int band = (int)((1.0 - w.z) * BANDS), sector = (int)((atan2(w.y, w.x) + M_PI) / (2 * M_PI) * SECTORS);
    return (band < BANDS ? band : BANDS - 1) * SECTORS + (sector < SECTORS ? sector : SECTORS - 1);
}

/* The share of microfacet normals (drawn from D(h) cos(theta_h)) that reflect wo below the surface:
 * D cos over the normals h whose reflection of wo has z <= 0, by the midpoint rule on a fine grid
 * of theta_h and phi_h in double (a grid of u would miss the tail where they lie). */
static double lost_share(double alpha, vec3 wo)
{
    const int nt = 4000, np = 720;
    double sum = 0.0, dt = M_PI / 2 / nt, dp = 2 * M_PI / np;
    for (int i = 0; i < nt; i++) {
        double th = (i + 0.5) * dt, c = cos(th), s = sin(th), w = ref_d(alpha, c) * c * s * dt * dp;
        if (w == 0.0) continue;
        for (int j = 0; j < np; j++) {
            double phi = (j + 0.5) * dp, d = wo.x * s * cos(phi) + wo.y * s * sin(phi) + wo.z * c;
            if (2 * d * c - wo.z <= 0.0) sum += w;  /* wi.z of the reflection about h */
        }
    }
    return sum;
}

/* Expected share of each cell: the reference pdf integrated over it (midpoint rule, QUAD^2 points; a
 * cell's solid angle is d(cos theta) d(phi)), scaled so that the cells hold all but the lost share,
 * which the last cell holds (the quadrature's own error is far below the test's resolution). */
static void expected_shares(double alpha, vec3 wo, double *share)
{
    double total = 0.0;
    for (int b = 0; b < BANDS; b++)
        for (int s = 0; s < SECTORS; s++) {
            double sum = 0.0;
            for (int i = 0; i < QUAD; i++)
                for (int j = 0; j < QUAD; j++) {
                    double z = 1.0 - (b + (i + 0.5) / QUAD) / BANDS, phi = (s + (j + 0.5) / QUAD) / SECTORS * 2 * M_PI - M_PI;
                    double r = sqrt(fmax(0.0, 1.0 - z * z));
                    sum += ref_pdf(alpha, wo, vec3_make((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z));
                }
            share[b * SECTORS + s] = sum / (QUAD * QUAD) * (1.0 / BANDS) * (2 * M_PI / SECTORS);
            total += share[b * SECTORS + s];
        }
    double lost = lost_share(alpha, wo);
    for (int i = 0; i < CELLS - 1; i++) share[i] *= (1.0 - lost) / total;
    share[CELLS - 1] = lost;
}

/* The albedo of m seen from wo, the integral of f cos over the hemisphere (channel c), by the
 * midpoint rule on a fine grid of equal cos(theta) and phi. */
static double albedo(const material *m, vec3 wo, int c)
{
    const int nz = 400, np = 400;
    double sum = 0.0;
    for (int i = 0; i < nz; i++)
        for (int j = 0; j < np; j++) {
            double z = (i + 0.5) / nz, phi = (j + 0.5) / np * 2 * M_PI, r = sqrt(1.0 - z * z);
            vec3 wi = vec3_make((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z);
            sum += ref_f(m, wo, wi, c, false) * z;
        }
    return sum * (1.0 / nz) * (2 * M_PI / np);
}

static void check_sampler(double alpha, double theta_o_deg, uint64_t seed)
{
    material m = metal(alpha, AL_ETA, AL_K);
    vec3 wo = dir_at(theta_o_deg * M_PI / 180.0, 0.4);
    static double observed[CELLS], expected[CELLS];
    memset(observed, 0, sizeof observed);
    expected_shares(alpha, wo, expected);
    for (int i = 0; i < CELLS; i++) expected[i] *= SAMPLES;
    stats_acc weight = stats_acc_make();
    rng g = rng_seeded(seed, (uint64_t)(alpha * 1000 + theta_o_deg));
    for (int i = 0; i < SAMPLES; i++) {
        vec3 wi = vec3_make(0, 0, 0);
        float pdf = -1.0f;
        rgb f = microfacet_sample_f(&m, wo, rng_uniform2(&g), &wi, &pdf);
        assert_implemented();
        if (!(pdf > 0.0f) || !(wi.z > 0.0f)) {
            if (!rgb_is_black(f) && pdf > 0.0f)
                PL_FAIL("wrong: microfacet_sample_f returned f (%g, %g, %g) with pdf %g for wi.z = %g below the surface: "
                        "return black with pdf 0 there (handout/part7.md, 7.6)", (double)f.r, (double)f.g, (double)f.b,
                        (double)pdf, (double)wi.z);
            observed[CELLS - 1]++;
            stats_acc_add(&weight, 0.0);
            continue;
        }
        observed[cell_of(wi)]++;
        float own_pdf = microfacet_pdf(&m, wo, wi);
        rgb own_f = microfacet_f(&m, wo, wi);
        if (!near(pdf, own_pdf, 1e-3, 1e-6) || !near(f.g, own_f.g, 1e-3, 1e-6))
            PL_FAIL("wrong: microfacet_sample_f's pdf %g and f %g for its wi (wi.z %.4f) are not microfacet_pdf's %g and "
                    "microfacet_f's %g there (handout/part7.md, 7.6)", (double)pdf, (double)f.g, (double)wi.z,
                    (double)own_pdf, (double)own_f.g);
        /* The weight by the closed forms, not by the candidate's f and pdf (checked above against its
         * own tasks 7.4 and 7.5): the furnace judges the directions 7.6 draws, and a mistake in 7.1-7.5
         * costs their own points, not 7.6's. */
        double ref = ref_pdf(alpha, wo, wi);
        stats_acc_add(&weight, ref > 0.0 ? ref_f(&m, wo, wi, 1, false) * wi.z / ref : 0.0);
    }
    stats_result r = stats_chi2_test(observed, expected, CELLS, 5.0, PART7_CHECK_ALPHA);
    if (r.reject)
        PL_FAIL("wrong: microfacet_sample_f's directions (alpha %g, wo at %g degrees) do not follow its pdf D(h) cos(theta_h) "
                "/ (4 dot(wo, h)): chi-square %.1f on %.0f degrees of freedom, p = %.3g < alpha %.3g; samples lost below "
                "the surface %.0f, expected %.0f (handout/part7.md, 7.6: theta_h = atan(sqrt(-alpha^2 log(1 - u))))",
                alpha, theta_o_deg, r.stat, r.dof, r.p, PART7_CHECK_ALPHA, observed[CELLS - 1], expected[CELLS - 1]);
    char what[256];
    snprintf(what, sizeof what, "the mean weight f cos / pdf (the closed forms' f and pdf) at microfacet_sample_f's "
             "directions (alpha %g, wo at %g degrees, green) against the albedo, the integral of f cos (task 7.6, "
             "handout/part7.md)", alpha, theta_o_deg);
    assert_mean_matches(&weight, albedo(&m, wo, 1), PART7_CHECK_ALPHA, what);
}

static void test_microfacet_sample_f__follows_its_pdf_and_keeps_energy(void **state)
{
    (void)state;
    uint64_t seed = SEED;
    mc_print_seed("microfacet_sample_f", seed);
    check_sampler(0.2, 30.0, seed);
    check_sampler(0.5, 60.0, seed);
    check_sampler(0.9, 10.0, seed);
}

int microfacet_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_beckmann_d__matches_the_closed_form, test_setup),
        cmocka_unit_test_setup(test_beckmann_d__projected_area_is_one, test_setup),
        cmocka_unit_test_setup(test_fresnel_conductor__matches_the_closed_form, test_setup),
        cmocka_unit_test_setup(test_microfacet_g__matches_smith, test_setup),
        cmocka_unit_test_setup(test_microfacet_f__matches_the_closed_form_and_is_reciprocal, test_setup),
        cmocka_unit_test_setup(test_microfacet_pdf__matches_the_closed_form, test_setup),
        cmocka_unit_test_setup(test_microfacet_sample_f__follows_its_pdf_and_keeps_energy, test_setup),
    };
    return cmocka_run_group_tests_name("part7: microfacet conductors, task by task (tasks 7.1-7.6)", tests, NULL, NULL);
}
