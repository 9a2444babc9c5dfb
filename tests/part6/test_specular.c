/* Test machinery: not part of any assignment.
 * Part 6, mirror and glass, task by task, on directions drawn all over the sphere (both sides of
 * the surface) and several indices of refraction, each answer against the closed form computed in
 * double here:
 * - reflect (6.1): the mirror direction.
 * - mirror_sample_f (6.2): that direction, and a weight f |cos| / pdf equal to the reflectance.
 * - refract (6.3): Snell's law (side, plane, angle, length), and total internal reflection exactly
 *   where eta sin(theta_o) > 1 (directions within 1e-5 of the critical angle may go either way).
 * - refraction_sample_f (6.4): that direction, a weight of the transmittance times a radiance scale,
 *   and nothing under total internal reflection.
 * - glass_sample_f (6.5): every sample is the mirror's or the refraction's with its weight (a white
 *   glass, absorbing nothing, returns weight 1 for every sample: the white furnace test, exact here
 *   because a delta BSDF's sample carries its whole weight), and the reflected fraction is
 *   Schlick's R, by an exact binomial test (the chi-square test of a sampler against its pdf, for a
 *   pdf of two atoms).
 * Tasks 6.2, 6.4 and 6.5 call earlier ones in the same file (reflect, refract, mirror_sample_f,
 * refraction_sample_f), so no test can give them the course's: a sample that is not the closed form's
 * passes when it is what the candidate's own earlier task gives for the same wo (own_tasks), and a
 * mistake of 6.1 or 6.3 costs that task alone.
 * Only weights f |cos| / pdf are checked, never f or pdf alone: a mirror sample with pdf 1 or any
 * other pdf and the matching f is the same sample. The radiance scale of a refraction may be eta^2
 * (the physics, our convention), 1 / eta^2 (CS184's) or 1 (none): all three render a closed glass
 * object lit from outside alike, and the tests accept whichever a solution uses, as long as it is
 * the same in every call. Under total internal reflection and away from it, the reflected fraction
 * may follow |cos_theta(wo)| (CS184's Schlick, the handout's) or, leaving glass, the cosine of the
 * refracted direction (the textbook's): both are accepted there, each by its own check.
 * alpha: eight statistical checks here (one per direction entering, two per direction leaving),
 * each at PART6_CHECK_ALPHA (family alpha 1e-3 and budget: part6_alpha.h). Seeds are fixed,
 * printed, and changed by PL_TEST_SEED (mc_seed). */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "part6_alpha.h"
#include "../../parts/part6_specular/part6.h"

#define SEED mc_seed(0x5eed6001ull)
#define DIRECTIONS 2000
/* A direction is right when each component is within this of the closed form (unit vectors). */
#define DIR_TOL 2e-5
/* A weight is right within this relative error (float rounding of f, cos and pdf). */
#define WEIGHT_TOL 1e-4
/* Directions this close to the critical angle (in eta^2 sin^2) may refract or not. */
#define CRITICAL_SLACK 1e-5
#define GLASS_SAMPLES 20000

static vec3 unit_dir(rng *g)
{
    vec2 u = rng_uniform2(g);
    float z = 1.0f - 2.0f * u.x, r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = 2.0f * (float)M_PI * u.y;
    return vec3_make(r * cosf(phi), r * sinf(phi), z);
}

static bool close_dir(vec3 a, const double b[3])
{
    return fabs(a.x - b[0]) <= DIR_TOL && fabs(a.y - b[1]) <= DIR_TOL && fabs(a.z - b[2]) <= DIR_TOL;
}

/* A refracted direction: its z is sqrt(1 - sin^2), which float computes to within a few units of
 * 1e-7 in sin^2, so near the critical angle (z -> 0) its error grows as 1e-7 / z. */
static bool close_refracted(vec3 a, const double b[3])
{
    return fabs(a.x - b[0]) <= DIR_TOL && fabs(a.y - b[1]) <= DIR_TOL &&
           fabs(a.z - b[2]) <= DIR_TOL + 1e-6 / fmax(fabs(b[2]), 1e-6);
}

/* eta of refract's contract: the index on wo's side over the other side's. */
static double eta_of(vec3 wo, double ior) { return wo.z > 0.0f ? 1.0 / ior : ior; }

/* eta^2 sin^2(theta_o): above 1, no refracted direction. */
static double sin2_refracted(vec3 wo, double ior)
{
    double eta = eta_of(wo, ior);
    return eta * eta * (1.0 - (double)wo.z * wo.z);
}

/* The refracted direction in double (Snell), for sin2_refracted < 1; at the critical angle and past
 * it, the grazing direction it tends to (never NaN: a direction the tests accept within
 * CRITICAL_SLACK of the critical angle is compared with that limit). */
static void refracted(vec3 wo, double ior, double out[3])
{
    double eta = eta_of(wo, ior), c = sqrt(fmax(0.0, 1.0 - sin2_refracted(wo, ior)));
    out[0] = -eta * wo.x;
    out[1] = -eta * wo.y;
    out[2] = wo.z > 0.0f ? -c : c;
}

static void reflected(vec3 wo, double out[3])
{
    out[0] = -(double)wo.x;
    out[1] = -(double)wo.y;
    out[2] = wo.z;
}

/* f |cos| / pdf of one sample, per channel; NaN channels when pdf is 0 with a non-black f. */
static rgb weight_of(rgb f, vec3 wi, float pdf)
{
    if (!(pdf > 0.0f)) return rgb_is_black(f) ? rgb_gray(0.0f) : rgb_gray(NAN);
    return rgb_scale(f, fabsf(wi.z) / pdf);
}

static bool close_rgb(rgb got, rgb want)
{
    return fabsf(got.r - want.r) <= WEIGHT_TOL * fmaxf(1.0f, want.r) && fabsf(got.g - want.g) <= WEIGHT_TOL * fmaxf(1.0f, want.g) &&
           fabsf(got.b - want.b) <= WEIGHT_TOL * fmaxf(1.0f, want.b);
}

static bool close_vec(vec3 a, vec3 b)
{
    const double c[3] = {b.x, b.y, b.z};
    return close_dir(a, c);
}

/* ---- the candidate's own earlier tasks, to judge a later one with --------------------------------- */
/* Tasks 6.2, 6.4 and 6.5 call 6.1, 6.3, 6.2 and 6.4 in the same file, so no test can hand them the
 * course's versions. A sample that is not the closed form's passes when it is what the candidate's
 * own earlier task gives for the same wo: a mistake of 6.1 or 6.3 costs that task alone, and the
 * later task is judged on how it uses it. Asked once per wo, and only where the closed form fails. */
typedef struct {
    const material *m;
    vec3 wo;
    bool asked;
    bool refracts;      /* refract (6.3) found a direction, */
    vec3 refracted;     /* this one */
    vec3 mirror;        /* glass only: mirror_sample_f's (6.2) direction and weight */
    rgb mirror_w;
    rgb refraction_w;   /* glass only: refraction_sample_f's (6.4) weight */
} own_tasks;

static own_tasks own_tasks_of(const material *m, vec3 wo)
{
    own_tasks o;
    memset(&o, 0, sizeof o);
    o.m = m, o.wo = wo;
    return o;
}

static const own_tasks *ask_own(own_tasks *o)
{
    if (o->asked) return o;
    o->asked = true;
    o->refracts = refract(o->wo, o->m->ior, &o->refracted);
    if (o->m->kind != MATERIAL_GLASS) return o;
    vec3 wi = vec3_make(0, 0, 0);
    float pdf = 0.0f;
    rgb f = mirror_sample_f(o->m, o->wo, &wi, &pdf);
    o->mirror = wi, o->mirror_w = weight_of(f, wi, pdf);
    wi = vec3_make(0, 0, 0), pdf = 0.0f;
    f = refraction_sample_f(o->m, o->wo, &wi, &pdf);
    o->refraction_w = weight_of(f, wi, pdf);
    return o;
}

/* Whether wi is the refraction the candidate's own refract (6.3) gives for o's wo. */
static bool own_refraction(own_tasks *o, vec3 wi) { return ask_own(o)->refracts && close_vec(wi, o->refracted); }

/* ---- 6.1, 6.2: the mirror ------------------------------------------------------------------- */

static void test_reflect__the_mirror_direction(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED, 1);
    for (int i = 0; i < DIRECTIONS; i++) {
        vec3 wo = unit_dir(&g);
        vec3 wi = reflect(wo);
        assert_implemented();
        double want[3];
        reflected(wo, want);
        if (!close_dir(wi, want))
            PL_FAIL("wrong: reflect(%.6f, %.6f, %.6f) is (%.6f, %.6f, %.6f), expected (%.6f, %.6f, %.6f): the reflection "
                    "about the normal +z keeps wo.z and turns the tangent part round (handout/part6.md, 6.1)%s",
                    (double)wo.x, (double)wo.y, (double)wo.z, (double)wi.x, (double)wi.y, (double)wi.z, want[0], want[1],
                    want[2], fabsf(wi.z + wo.z) < 1e-5f && fabsf(wi.x - wo.x) < 1e-5f
                                  ? " (this is (wo.x, wo.y, -wo.z): a reflection about the surface, not the normal; the ray goes through the mirror)" : "");
    }
}

static void test_mirror_sample_f__direction_and_weight(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    m.kind = MATERIAL_MIRROR;
    m.reflectance = rgb_make(0.9f, 0.6f, 0.3f);
    rng g = rng_seeded(SEED, 2);
    for (int i = 0; i < DIRECTIONS; i++) {
        vec3 wo = unit_dir(&g);
        if (wo.z < 0.0f) wo.z = -wo.z;  /* a mirror's frame faces the viewer */
        if (wo.z < 1e-3f) continue;     /* grazing: |cos| too small to divide by in float */
        vec3 wi = vec3_make(0, 0, 0);
        float pdf = 0.0f;
        rgb f = mirror_sample_f(&m, wo, &wi, &pdf);
        assert_implemented();
        double want[3];
        reflected(wo, want);
        if (!close_dir(wi, want) && !close_vec(wi, reflect(wo)))  /* reflect's own answer is 6.1's to judge */
            PL_FAIL("wrong: mirror_sample_f sent wi = (%.6f, %.6f, %.6f) for wo = (%.6f, %.6f, %.6f); a mirror's only "
                    "direction is reflect(wo) = (%.6f, %.6f, %.6f) (handout/part6.md, 6.2)", (double)wi.x, (double)wi.y,
                    (double)wi.z, (double)wo.x, (double)wo.y, (double)wo.z, want[0], want[1], want[2]);
        rgb w = weight_of(f, wi, pdf);
        if (!close_rgb(w, m.reflectance))
            PL_FAIL("wrong: mirror_sample_f's weight f |cos| / pdf is (%g, %g, %g) for wo.z = %g (f (%g, %g, %g), pdf %g), "
                    "expected the reflectance (0.9, 0.6, 0.3): f = reflectance / |cos_theta(wi)| with pdf 1 "
                    "(handout/part6.md, 6.2)%s", (double)w.r, (double)w.g, (double)w.b, (double)wo.z, (double)f.r,
                    (double)f.g, (double)f.b, (double)pdf,
                    fabsf(w.r - 0.9f * wo.z) < 1e-3f ? " (the weight carries a cosine: f must divide by it)" : "");
    }
}

/* ---- 6.3, 6.4: refraction ------------------------------------------------------------------- */

static const float IORS[] = {1.5f, 1.33f, 2.42f, 0.75f};

static void test_refract__snell_and_total_internal_reflection(void **state)
{
    (void)state;
    rng g = rng_seeded(SEED, 3);
    for (size_t k = 0; k < sizeof IORS / sizeof IORS[0]; k++) {
        double ior = IORS[k];
        for (int i = 0; i < DIRECTIONS; i++) {
            vec3 wo = unit_dir(&g), wi = vec3_make(7, 7, 7);
            bool ok = refract(wo, (float)ior, &wi);
            assert_implemented();
            double s2 = sin2_refracted(wo, ior);
            const char *side = wo.z > 0.0f ? "entering (wo.z > 0: from outside)" : "leaving (wo.z < 0: from inside)";
            if (s2 > 1.0 + CRITICAL_SLACK) {
                if (ok)
                    PL_FAIL("wrong: refract(wo = (%.6f, %.6f, %.6f), ior %g) found a direction, %s, but eta sin(theta_o) = "
                            "%.6f > 1: total internal reflection, it must return false (handout/part6.md, 6.3)",
                            (double)wo.x, (double)wo.y, (double)wo.z, ior, side, sqrt(s2));
                continue;
            }
            if (s2 < 1.0 - CRITICAL_SLACK && !ok)
                PL_FAIL("wrong: refract(wo = (%.6f, %.6f, %.6f), ior %g) returned false, %s, but eta sin(theta_o) = %.6f < 1: "
                        "the light refracts (eta = %g: the index on wo's side over the other's; handout/part6.md, 6.3)",
                        (double)wo.x, (double)wo.y, (double)wo.z, ior, side, sqrt(s2), eta_of(wo, ior));
            if (!ok) continue;
            double want[3];
            refracted(wo, ior, want);
            if (close_refracted(wi, want)) continue;
            /* Name the usual mistakes. */
            const char *why = "";
            double inv[3];
            vec3 flipped = wo;
            flipped.z = -wo.z;  /* eta of the other side: the ratio inverted */
            if (sin2_refracted(flipped, ior) < 1.0) {
                refracted(flipped, ior, inv);
                inv[2] = -inv[2];
                if (close_dir(wi, inv)) why = " (this is eta inverted: entering glass, eta = 1 / ior, and light bends towards the normal)";
            }
            if ((wi.z > 0.0f) == (wo.z > 0.0f)) why = " (wi is on wo's side of the surface: a refracted ray crosses it)";
            PL_FAIL("wrong: refract(wo = (%.6f, %.6f, %.6f), ior %g), %s, gave (%.6f, %.6f, %.6f), expected (%.6f, %.6f, %.6f) "
                    "by Snell's law%s (handout/part6.md, 6.3)", (double)wo.x, (double)wo.y, (double)wo.z, ior, side,
                    (double)wi.x, (double)wi.y, (double)wi.z, want[0], want[1], want[2], why);
        }
    }
}

/* The radiance scale conventions the tests accept (the header says why), by name. */
static const char *scale_name(int convention)
{
    static const char *names[] = {"eta^2 (the physics)", "1 / eta^2 (CS184's)", "1 (no scale)"};
    return names[convention];
}

/* The convention w / t matches for a refraction from wo (-1: none); t the transmittance. */
static int scale_convention(rgb w, rgb t, double eta)
{
    double scales[] = {eta * eta, 1.0 / (eta * eta), 1.0};
    for (int c = 0; c < 3; c++)
        if (close_rgb(w, rgb_scale(t, (float)scales[c]))) return c;
    return -1;
}

/* The weight of a refraction: the transmittance times one scale convention, the same in every call
 * (*convention, once one was seen); for a glass also what its own refraction_sample_f (6.4) weighs. */
static void check_refraction_weight(const char *fn, own_tasks *o, rgb w, rgb t, int *convention)
{
    double eta = eta_of(o->wo, o->m->ior);
    int c = scale_convention(w, t, eta);
    if (c < 0 && o->m->kind == MATERIAL_GLASS && close_rgb(w, ask_own(o)->refraction_w)) return;
    if (c < 0)
        PL_FAIL("wrong: %s's weight f |cos| / pdf of a refraction is (%g, %g, %g) for wo.z = %g (eta %g); expected the "
                "transmittance (%g, %g, %g) times eta^2 = %g (or CS184's 1 / eta^2 = %g, or 1): never times 1 - R or a "
                "cosine (handout/part6.md, 6.4)", fn, (double)w.r, (double)w.g, (double)w.b, (double)o->wo.z, eta,
                (double)t.r, (double)t.g, (double)t.b, eta * eta, 1.0 / (eta * eta));
    if (*convention >= 0 && c != *convention && fabs(eta - 1.0) > 1e-3)
        PL_FAIL("wrong: %s scales refracted radiance by %s here (wo.z = %g) but by %s before: any one convention is "
                "accepted, but the same in every call (handout/part6.md, 6.4)", fn, scale_name(c), (double)o->wo.z,
                scale_name(*convention));
    if (fabs(eta - 1.0) > 1e-3) *convention = c;
}

/* Checks one refracted sample: the direction (Snell's, or the candidate's own refract's) and its
 * weight. */
static void check_refracted(const char *fn, own_tasks *o, vec3 wi, rgb w, rgb t, int *convention)
{
    vec3 wo = o->wo;
    double ior = o->m->ior, s2 = sin2_refracted(wo, ior), want[3];
    /* Under total internal reflection there is no refracted direction to compare with: the only
     * right sample is the mirror's (the callers match it first), or its own refract's. */
    if (s2 >= 1.0 && !own_refraction(o, wi))
        PL_FAIL("wrong: %s gave wi = (%.6f, %.6f, %.6f) (weight (%g, %g, %g)) for wo = (%.6f, %.6f, %.6f) from inside "
                "(ior %g), past the critical angle: eta sin(theta_o) = %.4f > 1, total internal reflection. No light "
                "refracts there; all of it reflects: return the mirror's sample, wi = reflect(wo) = (%.6f, %.6f, "
                "%.6f) (task 6.5, handout/part6.md)", fn, (double)wi.x, (double)wi.y, (double)wi.z, (double)w.r,
                (double)w.g, (double)w.b, (double)wo.x, (double)wo.y, (double)wo.z, ior, sqrt(s2), -(double)wo.x,
                -(double)wo.y, (double)wo.z);
    refracted(wo, ior, want);
    if (s2 < 1.0 && !close_refracted(wi, want) && !own_refraction(o, wi))
        PL_FAIL("wrong: %s refracted wo = (%.6f, %.6f, %.6f) (ior %g) into (%.6f, %.6f, %.6f), expected (%.6f, %.6f, %.6f) "
                "(refract, handout/part6.md, 6.3)", fn, (double)wo.x, (double)wo.y, (double)wo.z, ior, (double)wi.x,
                (double)wi.y, (double)wi.z, want[0], want[1], want[2]);
    check_refraction_weight(fn, o, w, t, convention);
}

static void test_refraction_sample_f__direction_weight_and_tir(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    m.kind = MATERIAL_REFRACTION;
    m.transmittance = rgb_make(0.3f, 0.6f, 0.9f);
    m.ior = 1.5f;
    int convention = -1;
    rng g = rng_seeded(SEED, 4);
    for (int i = 0; i < DIRECTIONS; i++) {
        vec3 wo = unit_dir(&g), wi = vec3_make(0, 0, 1);
        float pdf = 0.0f;
        rgb f = refraction_sample_f(&m, wo, &wi, &pdf);
        assert_implemented();
        double s2 = sin2_refracted(wo, m.ior);
        rgb w = weight_of(f, wi, pdf);
        own_tasks own = own_tasks_of(&m, wo);
        if (s2 > 1.0 + CRITICAL_SLACK) {
            if (rgb_is_black(w)) continue;
            if (!own_refraction(&own, wi))  /* else it followed its own refract (6.3): judged below */
                PL_FAIL("wrong: refraction_sample_f returned weight (%g, %g, %g) for wo = (%.6f, %.6f, %.6f) from inside, "
                        "past the critical angle (eta sin = %.4f > 1): under total internal reflection it returns black "
                        "(handout/part6.md, 6.4)", (double)w.r, (double)w.g, (double)w.b, (double)wo.x, (double)wo.y,
                        (double)wo.z, sqrt(s2));
        }
        else if (s2 > 1.0 - CRITICAL_SLACK || fabs(wo.z) < 1e-3) continue;  /* at the critical angle, or grazing */
        /* Black where its own refract (6.3) finds no direction: 6.4's part done right. */
        if (rgb_is_black(w) && !ask_own(&own)->refracts) continue;
        check_refracted("refraction_sample_f", &own, wi, w, m.transmittance, &convention);
    }
}

/* ---- 6.5: glass ------------------------------------------------------------------------------ */

static double schlick(double cos_theta, double ior)
{
    double r0 = (1.0 - ior) / (1.0 + ior);
    r0 *= r0;
    return r0 + (1.0 - r0) * pow(1.0 - fabs(cos_theta), 5.0);
}

/* One sample of a glass for o's wo, weight w: a reflection (the mirror's direction, or the
 * solution's own mirror_sample_f's) with the reflectance's weight (or its own mirror_sample_f's),
 * else a refraction (check_refracted: none under total internal reflection). Returns whether it
 * reflected. */
static bool check_glass_sample(const char *fn, own_tasks *o, vec3 wi, rgb f, float pdf, int *convention)
{
    const material *m = o->m;
    vec3 wo = o->wo;
    rgb w = weight_of(f, wi, pdf);
    double mirror[3], snell[3], s2 = sin2_refracted(wo, m->ior);
    reflected(wo, mirror);
    refracted(wo, m->ior, snell);
    bool snells = s2 < 1.0 && close_refracted(wi, snell);
    bool at_mirror = close_dir(wi, mirror) || (!snells && close_vec(wi, ask_own(o)->mirror));
    if (at_mirror && (close_rgb(w, m->reflectance) || close_rgb(w, ask_own(o)->mirror_w))) return true;
    /* A refraction, or at the mirror's direction its own refract's (6.3) refraction (a refract that
     * leaves wi on wo's side gives it head-on) with a refraction's weight. */
    if (!at_mirror || own_refraction(o, wi)) {
        check_refracted(fn, o, wi, w, m->transmittance, convention);
        return false;
    }
    PL_FAIL("wrong: %s reflected wo = (%.6f, %.6f, %.6f) with weight f |cos| / pdf = (%g, %g, %g) (f (%g, %g, %g), pdf "
            "%g), expected the reflectance (%g, %g, %g): scale f and pdf both by R, so that R cancels (task 6.5, "
            "handout/part6.md)", fn, (double)wo.x, (double)wo.y, (double)wo.z, (double)w.r, (double)w.g, (double)w.b,
            (double)f.r, (double)f.g, (double)f.b, (double)pdf, (double)m->reflectance.r, (double)m->reflectance.g,
            (double)m->reflectance.b);
    return true;
}

/* GLASS_SAMPLES samples of glass_sample_f for one wo (angle from the normal, degrees; above 90 from
 * inside): each the mirror's or the refraction's with its weight; the reflected fraction Schlick's. */
static void check_glass_direction(const material *m, double degrees, int *convention, uint64_t seed)
{
    double th = degrees * M_PI / 180.0;
    vec3 wo = vec3_make((float)(sin(th) * 0.6), (float)(sin(th) * 0.8), (float)cos(th));
    double s2 = sin2_refracted(wo, m->ior);
    own_tasks own = own_tasks_of(m, wo);
    long reflected_n = 0;
    rng g = rng_seeded(seed, (uint64_t)(degrees * 10));
    for (int i = 0; i < GLASS_SAMPLES; i++) {
        vec3 wi = vec3_make(0, 0, 0);
        float pdf = 0.0f;
        rgb f = glass_sample_f(m, wo, rng_uniform2(&g), &wi, &pdf);
        assert_implemented();
        reflected_n += check_glass_sample("glass_sample_f", &own, wi, f, pdf, convention);
    }
    if (s2 > 1.0) return;  /* total internal reflection: every sample was a reflection, checked above */
    /* The reflected fraction: Schlick's R with |cos_theta(wo)|, or leaving glass the refracted cosine
     * (one check each). */
    double R = schlick(wo.z, m->ior), alpha = PART6_CHECK_ALPHA;
    double p = stats_binomial_p2(reflected_n, GLASS_SAMPLES, R);
    if (wo.z < 0.0f) {
        double alpha_t = PART6_CHECK_ALPHA, R_t = schlick(sqrt(1.0 - s2), m->ior);
        if (stats_binomial_p2(reflected_n, GLASS_SAMPLES, R_t) >= alpha_t) return;
    }
    /* Where its own refract (6.3) finds no direction, reflecting every sample is right by it. */
    if (p >= alpha || !ask_own(&own)->refracts) return;
    double r0 = pow((1.0 - m->ior) / (1.0 + m->ior), 2.0);
    PL_FAIL("wrong: glass_sample_f reflected %ld of %d samples at %g degrees %s: a fraction of %.4f, but Schlick's R = "
            "R0 + (1 - R0)(1 - |cos_theta(wo)|)^5 = %.4f with R0 = ((1 - ior) / (1 + ior))^2 = %.4f (exact binomial "
            "test, p = %.3g < alpha %.3g; handout/part6.md, 6.5)%s", reflected_n, GLASS_SAMPLES,
            wo.z > 0.0f ? degrees : 180.0 - degrees, wo.z > 0.0f ? "entering" : "leaving",
            (double)reflected_n / GLASS_SAMPLES, R, r0, p, alpha,
            fabs((double)reflected_n / GLASS_SAMPLES - (1.0 - R)) < 0.01 ? " (the two branches are swapped)" : "");
}

static void test_glass_sample_f__branches_weights_and_schlick(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    m.kind = MATERIAL_GLASS;
    m.reflectance = rgb_make(0.9f, 0.8f, 0.7f);
    m.transmittance = rgb_make(0.5f, 0.7f, 0.95f);
    m.ior = 1.5f;
    uint64_t seed = SEED;
    mc_print_seed("glass_sample_f", seed);
    int convention = -1;
    /* Entering at 0, 30, 60 and 80 degrees; leaving at 20 and 35 (the critical angle is 41.8), and
     * at 50 and 70, past it. */
    const double degrees[] = {0, 30, 60, 80, 160, 145, 130, 110};
    for (size_t i = 0; i < sizeof degrees / sizeof degrees[0]; i++) check_glass_direction(&m, degrees[i], &convention, seed);
}

/* A white glass (reflectance and transmittance 1) absorbs nothing: every sample's weight is 1, once
 * the radiance scale of a refraction is taken out. */
static void test_glass_sample_f__white_furnace(void **state)
{
    (void)state;
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    m.kind = MATERIAL_GLASS;
    m.reflectance = m.transmittance = rgb_gray(1.0f);
    m.ior = 1.33f;
    int convention = -1;
    rng g = rng_seeded(SEED, 6);
    for (int i = 0; i < DIRECTIONS; i++) {
        vec3 wo = unit_dir(&g), wi = vec3_make(0, 0, 0);
        if (fabs(wo.z) < 1e-3 || fabs(sin2_refracted(wo, m.ior) - 1.0) < CRITICAL_SLACK) continue;
        float pdf = 0.0f;
        rgb f = glass_sample_f(&m, wo, rng_uniform2(&g), &wi, &pdf);
        assert_implemented();
        own_tasks own = own_tasks_of(&m, wo);
        check_glass_sample("glass_sample_f (a white glass, absorbing nothing)", &own, wi, f, pdf, &convention);
    }
}

int specular_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_reflect__the_mirror_direction, test_setup),
        cmocka_unit_test_setup(test_mirror_sample_f__direction_and_weight, test_setup),
        cmocka_unit_test_setup(test_refract__snell_and_total_internal_reflection, test_setup),
        cmocka_unit_test_setup(test_refraction_sample_f__direction_weight_and_tir, test_setup),
        cmocka_unit_test_setup(test_glass_sample_f__branches_weights_and_schlick, test_setup),
        cmocka_unit_test_setup(test_glass_sample_f__white_furnace, test_setup),
    };
    return cmocka_run_group_tests_name("part6: mirror and glass, task by task (tasks 6.1-6.5)", tests, NULL, NULL);
}
