/* The BSDF of a material, whatever its kind (material.h says why it exists). Every kind shades as
 * part 3's diffuse BSDF for now; a part that shades a kind of its own is called from here, on
 * m->kind, and from nowhere else. */
#include "material.h"
#include "../parts/part3_direct/part3.h"

rgb material_f(const material *m, vec3 wo, vec3 wi)
{
    return bsdf_f(m, wo, wi);
}

float material_pdf(const material *m, vec3 wo, vec3 wi)
{
    return bsdf_pdf(m, wo, wi);
}

rgb material_sample_f(const material *m, vec3 wo, vec2 u, vec3 *wi, float *pdf)
{
    return bsdf_sample_f(m, wo, u, wi, pdf);
}
