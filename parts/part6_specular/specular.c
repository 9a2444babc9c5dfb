/* Part 6, tasks 6.1 to 6.5: mirror and glass. Handout: handout/part6.md. */
#include "part6.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 6 | TASK 6.1 | reflect ======================================================
 * The mirror direction (handout/part6.md, section 6.1).
 * In:  wo, a unit direction in the local frame (+z the normal), on either side of the surface.
 * Out: wo reflected about the normal: the same angle to it, on the same side, the opposite
 *      azimuth; unit length.
 * Test: make test-part6
 * ====================================================================================== */
vec3 reflect(vec3 wo)
{
    /* BEGIN SOLUTION */
    /* About +z: the tangent part turns round, the normal part stays. */
    return vec3_make(-wo.x, -wo.y, wo.z);
    /* END SOLUTION */
    /* STUB: return PL_TODO_VEC3("6.1", "reflect"); */
}

/* === PART 6 | TASK 6.2 | mirror_sample_f ==============================================
 * A perfect mirror, CS184's <mirror> (handout/part6.md, section 6.2).
 * In:  m (m->reflectance), wo in the local frame (wo.z > 0: the frame faces the viewer).
 * Out: *wi = reflect(wo); *pdf = 1 (the only direction there is); returns
 *      f = m->reflectance / |cos_theta(*wi)|.
 * Why the division: the path multiplies by f |cos| / pdf, and a mirror returns the light of its
 *      one direction tinted by its reflectance, with no cosine: the cosine must cancel.
 * Test: make test-part6
 * ====================================================================================== */
rgb mirror_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    *wi = reflect(wo);
    *pdf = 1.0f;
    return rgb_scale(m->reflectance, 1.0f / abs_cos_theta(*wi));
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 0.0f, 1.0f); *pdf = 1.0f; return PL_TODO_RGB("6.2", "mirror_sample_f"); */
}

/* === PART 6 | TASK 6.3 | refract ======================================================
 * Snell's law (handout/part6.md, section 6.3).
 * In:  wo, unit, local frame with +z the OUTWARD normal: wo.z > 0 arrives from outside (index 1)
 *      and enters, wo.z < 0 arrives from inside (index ior) and leaves; ior > 0.
 * Out: true and *wi, the refracted direction: on the other side of the surface (the sign of
 *      wi.z opposite to wo.z), in the plane of wo and the normal with the opposite azimuth, with
 *      sin(theta_i) = eta sin(theta_o), eta = (index on wo's side) / (index on the other side);
 *      unit length. False under total internal reflection (eta sin(theta_o) >= 1), *wi untouched.
 * Must: not eta = ior entering (that bends light away from the normal as it enters glass).
 * Test: make test-part6
 * ====================================================================================== */
bool refract(vec3 wo, float ior, vec3 *wi)
{
    /* BEGIN SOLUTION */
    bool entering = wo.z > 0.0f;
    float eta = entering ? 1.0f / ior : ior;
    /* sin^2 of the refracted angle, from sin^2(theta_o) = 1 - cos^2. */
    float sin2_i = eta * eta * fmaxf(0.0f, 1.0f - wo.z * wo.z);
    if (sin2_i >= 1.0f)
        return false;
    float cos_i = sqrtf(1.0f - sin2_i);
    *wi = vec3_make(-eta * wo.x, -eta * wo.y, entering ? -cos_i : cos_i);
    return true;
    /* END SOLUTION */
    /* STUB: (void)wo, (void)ior, (void)wi; return PL_TODO_FALSE("6.3", "refract"); */
}

/* === PART 6 | TASK 6.4 | refraction_sample_f ==========================================
 * CS184's <refraction>: glass that only transmits (handout/part6.md, section 6.4).
 * In:  m (m->transmittance, m->ior), wo in the local frame, +z outward (as for refract).
 * Out: under total internal reflection: black, *pdf = 0. Otherwise *wi = the refracted direction
 *      (refract), *pdf = 1, and f = m->transmittance * eta^2 / |cos_theta(*wi)| with eta as in
 *      refract: radiance is squeezed into a narrower cone as it enters a denser medium, so it
 *      grows by 1/eta^2 on the way in and shrinks by eta^2 on the way out (handout/part6.md, 6.4,
 *      says why, and which other conventions the tests accept).
 * Test: make test-part6
 * ====================================================================================== */
rgb refraction_sample_f(const material *m, vec3 wo, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    if (!refract(wo, m->ior, wi)) {
        *pdf = 0.0f;
        return rgb_gray(0.0f);
    }
    float eta = wo.z > 0.0f ? 1.0f / m->ior : m->ior;
    *pdf = 1.0f;
    return rgb_scale(m->transmittance, eta * eta / abs_cos_theta(*wi));
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 0.0f, -1.0f); *pdf = 1.0f; return PL_TODO_RGB("6.4", "refraction_sample_f"); */
}

/* === PART 6 | TASK 6.5 | glass_sample_f ===============================================
 * CS184's <glass>: reflection or refraction, chosen at random (handout/part6.md, section 6.5).
 * In:  m (reflectance, transmittance, ior), wo (local, +z outward), u uniform in [0,1)^2.
 * Out: under total internal reflection, the mirror's sample (tinted by m->reflectance). Otherwise
 *      Schlick's reflectance R = R0 + (1 - R0) (1 - |cos_theta(wo)|)^5,
 *      R0 = ((1 - ior) / (1 + ior))^2, and: with probability R (u.x < R) the mirror's sample with
 *      f and *pdf times R; else the refraction's sample with f and *pdf times 1 - R.
 * Must: the reflected fraction of many samples is R; each sample's weight f |cos| / pdf is
 *       m->reflectance or m->transmittance (times the radiance scale): never R or 1 - R.
 * Test: make test-part6
 * ====================================================================================== */
rgb glass_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    vec3 refracted;
    if (!refract(wo, m->ior, &refracted))
        return mirror_sample_f(m, wo, wi, pdf);  /* total internal reflection: all of it reflects */
    float r0 = (1.0f - m->ior) / (1.0f + m->ior);
    r0 *= r0;
    float c = 1.0f - abs_cos_theta(wo);
    float R = r0 + (1.0f - r0) * c * c * c * c * c;
    /* Each branch's f and pdf are scaled by its probability: its weight f |cos| / pdf stays that of
     * the branch, and the two together add up to the glass's BSDF. */
    bool reflects = u.x < R;
    float p = reflects ? R : 1.0f - R;
    rgb f = reflects ? mirror_sample_f(m, wo, wi, pdf) : refraction_sample_f(m, wo, wi, pdf);
    *pdf *= p;
    return rgb_scale(f, p);
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 0.0f, 1.0f); *pdf = 1.0f; return PL_TODO_RGB("6.5", "glass_sample_f"); */
}
