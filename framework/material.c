/* The BSDF of a material, whatever its kind (material.h says why it exists): the one place that
 * chooses whose code shades a material. Diffuse materials, and every kind the course has no part
 * for, shade as part 3's diffuse BSDF; part 6's mirror and glass and part 7's microfacet metal,
 * where the course has those parts, shade as those parts say. */
#include "material.h"
#include "../parts/part3_direct/part3.h"
#ifdef PL_HAS_PART6  /* mirror and glass, in a course that teaches them (the Makefile: parts/part6_*) */
#include "../parts/part6_specular/part6.h"
#endif
#ifdef PL_HAS_PART7  /* microfacet metals, likewise (parts/part7_*) */
#include "../parts/part7_microfacet/part7.h"
#endif

bool material_kind_shaded(material_kind k)
{
#ifdef PL_HAS_PART6
    if (k == MATERIAL_MIRROR || k == MATERIAL_GLASS || k == MATERIAL_REFRACTION) return true;
#endif
#ifdef PL_HAS_PART7
    if (k == MATERIAL_MICROFACET) return true;
#endif
    return k == MATERIAL_DIFFUSE;
}

bool material_is_delta(const material *m)
{
    return (m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS || m->kind == MATERIAL_REFRACTION) &&
           material_kind_shaded(m->kind);
}

bool material_has_inside(const material *m)
{
    return (m->kind == MATERIAL_GLASS || m->kind == MATERIAL_REFRACTION) && material_kind_shaded(m->kind);
}

#ifdef PL_HAS_PART7
/* Part 7's microfacet metal (the course shades it). */
static bool microfacet(const material *m) { return m->kind == MATERIAL_MICROFACET; }
#endif

/* Every kind but diffuse, kept out of line and marked rarely taken, so that the three functions
 * below stay small enough for link-time optimisation to inline into parts 3 and 4 (declared inline
 * for that: without, the dispatch cost a -m 5 render of the bunny 3.3% more instructions, with it
 * 2.5%; bench/RESULTS.md). A delta BSDF is 0 for every pair of directions a caller can name
 * (material.h). */
#if defined(__GNUC__)
#define PL_RARE __attribute__((noinline, cold))
#else
#define PL_RARE
#endif
/* External, not static: C forbids an inline function with external linkage (the three below) to
 * refer to one with internal linkage, and clang says so. */
rgb material_other_f(const material *m, vec3 wo, vec3 wi);
float material_other_pdf(const material *m, vec3 wo, vec3 wi);
rgb material_other_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf);

PL_RARE rgb material_other_f(const material *m, vec3 wo, vec3 wi)
{
#ifdef PL_HAS_PART7
    if (microfacet(m)) return microfacet_f(m, wo, wi);
#endif
    return material_is_delta(m) ? rgb_gray(0.0f) : bsdf_f(m, wo, wi);
}

PL_RARE float material_other_pdf(const material *m, vec3 wo, vec3 wi)
{
#ifdef PL_HAS_PART7
    if (microfacet(m)) return microfacet_pdf(m, wo, wi);
#endif
    return material_is_delta(m) ? 0.0f : bsdf_pdf(m, wo, wi);
}

PL_RARE rgb material_other_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
#ifdef PL_HAS_PART7
    if (microfacet(m)) return microfacet_sample_f(m, wo, u, wi, pdf);
#endif
#ifdef PL_HAS_PART6
    switch (m->kind) {
    case MATERIAL_MIRROR: return mirror_sample_f(m, wo, wi, pdf);
    case MATERIAL_REFRACTION: return refraction_sample_f(m, wo, wi, pdf);
    case MATERIAL_GLASS: return glass_sample_f(m, wo, u, wi, pdf);
    default: break;
    }
#endif
    return bsdf_sample_f(m, wo, u, wi, pdf);
}

/* A course without parts 6 and 7 shades every kind as diffuse: no dispatch at all, and its renders
 * cost what they did before the other kinds existed. */
#if defined(PL_HAS_PART6) || defined(PL_HAS_PART7)
#define OTHER_KINDS(m) ((m)->kind != MATERIAL_DIFFUSE)
#else
#define OTHER_KINDS(m) false
#endif

inline rgb material_f(const material *m, vec3 wo, vec3 wi)
{
    return OTHER_KINDS(m) ? material_other_f(m, wo, wi) : bsdf_f(m, wo, wi);
}

inline float material_pdf(const material *m, vec3 wo, vec3 wi)
{
    return OTHER_KINDS(m) ? material_other_pdf(m, wo, wi) : bsdf_pdf(m, wo, wi);
}

inline rgb material_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    return OTHER_KINDS(m) ? material_other_sample_f(m, wo, u, wi, pdf) : bsdf_sample_f(m, wo, u, wi, pdf);
}
