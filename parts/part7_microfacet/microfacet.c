/* Part 7, tasks 7.1 to 7.6: microfacet conductors. Handout: handout/part7.md. */
#include "part7.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 7 | TASK 7.1 | beckmann_d ===================================================
 * The Beckmann distribution of microfacet normals (handout/part7.md, section 7.1).
 * In:  alpha > 0, the roughness; h, a unit direction in the local frame (+z the normal).
 * Out: D(h) = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h)) per steradian for
 *      h.z > 0, else 0.
 * Must: the integral of D(h) cos(theta_h) over the hemisphere is 1 (the microfacets' projected
 *       area is the surface's).
 * Test: make test-part7
 * ====================================================================================== */
float beckmann_d(float alpha, vec3 h)
{
    /* BEGIN SOLUTION */
    float c2 = h.z * h.z;
    if (!(h.z > 0.0f)) return 0.0f;
    float tan2 = (1.0f - c2) / c2, a2 = alpha * alpha;
    float e = expf(-tan2 / a2);
    return e > 0.0f ? e / (PL_PI * a2 * c2 * c2) : 0.0f;  /* at grazing h both parts vanish: 0, not 0 / 0 */
    /* END SOLUTION */
    /* STUB: (void)alpha, (void)h; return (float)PL_TODO_FALSE("7.1", "beckmann_d"); */
}

/* === PART 7 | TASK 7.2 | fresnel_conductor ============================================
 * How much a metal reflects (handout/part7.md, section 7.2).
 * In:  cos_i in [0, 1], the cosine of the angle at which light meets the (micro)surface; eta and
 *      k, the conductor's complex index of refraction per channel.
 * Out: per channel, F = (Rs + Rp) / 2 with, for t = eta^2 + k^2 and c = cos_i,
 *        Rs = (t - 2 eta c + c^2) / (t + 2 eta c + c^2),
 *        Rp = (t c^2 - 2 eta c + 1) / (t c^2 + 2 eta c + 1).
 * Must: at normal incidence ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2); 1 at grazing (c = 0).
 * Test: make test-part7
 * ====================================================================================== */
rgb fresnel_conductor(float cos_i, rgb eta, rgb k)
{
    /* BEGIN SOLUTION */
    float e[3] = {eta.r, eta.g, eta.b}, kk[3] = {k.r, k.g, k.b}, F[3];
    float c = cos_i, c2 = c * c;
    for (int i = 0; i < 3; i++) {
        float t = e[i] * e[i] + kk[i] * kk[i];
        float rs = (t - 2.0f * e[i] * c + c2) / (t + 2.0f * e[i] * c + c2);
        float rp = (t * c2 - 2.0f * e[i] * c + 1.0f) / (t * c2 + 2.0f * e[i] * c + 1.0f);
        F[i] = 0.5f * (rs + rp);
    }
    return rgb_make(F[0], F[1], F[2]);
    /* END SOLUTION */
    /* STUB: (void)cos_i, (void)eta, (void)k; return PL_TODO_RGB("7.2", "fresnel_conductor"); */
}

/* BEGIN SOLUTION */
/* Lambda of the Beckmann distribution, by Walter et al.'s rational approximation (task 7.3). */
static float beckmann_lambda(float alpha, vec3 w)
{
    float sin_t = sqrtf(fmaxf(0.0f, 1.0f - w.z * w.z));
    if (sin_t == 0.0f) return 0.0f;                      /* straight up: nothing hides it */
    float a = fabsf(w.z) / (alpha * sin_t);              /* 1 / (alpha tan(theta)) */
    if (a >= 1.6f) return 0.0f;
    return (1.0f - 1.259f * a + 0.396f * a * a) / (3.535f * a + 2.181f * a * a);
}
/* END SOLUTION */

/* === PART 7 | TASK 7.3 | microfacet_g =================================================
 * Smith's shadowing-masking term for Beckmann (handout/part7.md, section 7.3).
 * In:  alpha; wo and wi, unit, above the surface.
 * Out: G = 1 / (1 + Lambda(wo) + Lambda(wi)), where for a direction w at angle theta to the normal
 *      and a = 1 / (alpha tan(theta)): Lambda = 0 for a >= 1.6 (theta = 0 included), else
 *      Lambda = (1 - 1.259 a + 0.396 a^2) / (3.535 a + 2.181 a^2).
 * Test: make test-part7
 * ====================================================================================== */
float microfacet_g(float alpha, vec3 wo, vec3 wi)
{
    /* BEGIN SOLUTION */
    return 1.0f / (1.0f + beckmann_lambda(alpha, wo) + beckmann_lambda(alpha, wi));
    /* END SOLUTION */
    /* STUB: (void)alpha, (void)wo, (void)wi; return (float)PL_TODO_FALSE("7.3", "microfacet_g"); */
}

/* === PART 7 | TASK 7.4 | microfacet_f =================================================
 * The microfacet BSDF (handout/part7.md, section 7.4).
 * In:  m (m->alpha, m->eta, m->k); wo, wi, unit, local frame.
 * Out: 0 unless wo.z > 0 and wi.z > 0; else, with h = normalize(wo + wi) (the half vector: the
 *      microfacet normal that reflects wo into wi),
 *        f = F(dot(wi, h)) G(wo, wi) D(h) / (4 wo.z wi.z).
 * Must: F at the microfacet's angle, dot(wi, h), not at the surface's (wi.z).
 * Test: make test-part7
 * ====================================================================================== */
rgb microfacet_f(const material *m, vec3 wo, vec3 wi)
{
    /* BEGIN SOLUTION */
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return rgb_gray(0.0f);
    vec3 h = vec3_normalize(vec3_add(wo, wi));
    rgb F = fresnel_conductor(fminf(1.0f, vec3_dot(wi, h)), m->eta, m->k);
    float s = microfacet_g(m->alpha, wo, wi) * beckmann_d(m->alpha, h) / (4.0f * wo.z * wi.z);
    return rgb_scale(F, s);
    /* END SOLUTION */
    /* STUB: (void)m, (void)wo, (void)wi; return PL_TODO_RGB("7.4", "microfacet_f"); */
}

/* === PART 7 | TASK 7.5 | microfacet_pdf ===============================================
 * The density of microfacet_sample_f's directions (handout/part7.md, section 7.5).
 * In:  m (m->alpha); wo, wi, unit, local frame.
 * Out: 0 unless wo.z > 0 and wi.z > 0; else pdf(wi) = D(h) cos(theta_h) / (4 dot(wo, h)),
 *      h = normalize(wo + wi): the density of h, times the Jacobian of h -> wi (a reflection
 *      about h turns a solid angle around h into 4 dot(wo, h) times as much around wi).
 * Test: make test-part7
 * ====================================================================================== */
float microfacet_pdf(const material *m, vec3 wo, vec3 wi)
{
    /* BEGIN SOLUTION */
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    vec3 h = vec3_normalize(vec3_add(wo, wi));
    float cos_h = vec3_dot(wo, h);
    if (!(cos_h > 0.0f)) return 0.0f;
    return beckmann_d(m->alpha, h) * h.z / (4.0f * cos_h);
    /* END SOLUTION */
    /* STUB: (void)m, (void)wo, (void)wi; return (float)PL_TODO_FALSE("7.5", "microfacet_pdf"); */
}

/* === PART 7 | TASK 7.6 | microfacet_sample_f =========================================
 * Importance sampling of the Beckmann distribution (handout/part7.md, section 7.6).
 * In:  m; wo (wo.z > 0); u uniform in [0,1)^2.
 * Out: h drawn from D(h) cos(theta_h): theta_h = atan(sqrt(-alpha^2 log(1 - u.x))),
 *      phi_h = 2 pi u.y; *wi = wo reflected about h, -wo + 2 dot(wo, h) h; *pdf =
 *      microfacet_pdf(m, wo, *wi) and f = microfacet_f(m, wo, *wi). Where *wi falls below the
 *      surface: black and *pdf = 0 (the path ends).
 * Test: make test-part7
 * ====================================================================================== */
rgb microfacet_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    float tan2 = -m->alpha * m->alpha * logf(1.0f - u.x);
    float cos_h = 1.0f / sqrtf(1.0f + tan2), sin_h = sqrtf(fmaxf(0.0f, 1.0f - cos_h * cos_h));
    float phi = 2.0f * PL_PI * u.y;
    vec3 h = vec3_make(sin_h * cosf(phi), sin_h * sinf(phi), cos_h);
    *wi = vec3_sub(vec3_scale(h, 2.0f * vec3_dot(wo, h)), wo);
    *pdf = microfacet_pdf(m, wo, *wi);
    if (!(*pdf > 0.0f)) {
        *pdf = 0.0f;
        return rgb_gray(0.0f);
    }
    return microfacet_f(m, wo, *wi);
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 0.0f, 1.0f); *pdf = 1.0f; return PL_TODO_RGB("7.6", "microfacet_sample_f"); */
}
