/* Samplers and their pdf twins. Each maps [0,1)^2 to a distribution; the pdf of the same
 * distribution sits right below it so the two are read (and changed) together. */
#include "sampler.h"
#include <math.h>

vec3 sample_uniform_hemisphere(vec2 u)
{
    /* z = cos(theta) is uniform in [0,1] for a uniform hemisphere (Archimedes' hat-box theorem). */
    float z = u.x;
    float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
    float phi = 2.0f * PL_PI * u.y;
    return vec3_make(r * cosf(phi), r * sinf(phi), z);
}
float sample_uniform_hemisphere_pdf(vec3 w) { return w.z >= 0.0f ? PL_INV_2PI : 0.0f; }

vec3 sample_cosine_hemisphere(vec2 u)
{
    /* Malley's method: project a uniform disk point up onto the hemisphere. */
    vec2 d = sample_uniform_disk(u);
    float z = sqrtf(fmaxf(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return vec3_make(d.x, d.y, z);
}
float sample_cosine_hemisphere_pdf(vec3 w) { return w.z > 0.0f ? w.z * PL_INV_PI : 0.0f; }

/* The hemisphere's construction with z over [-1, 1]: the whole sphere, density 1 / (4 pi). */
vec3 sample_uniform_sphere(vec2 u)
{
    float z = 1.0f - 2.0f * u.x;
    float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
    float phi = 2.0f * PL_PI * u.y;
    return vec3_make(r * cosf(phi), r * sinf(phi), z);
}
float sample_uniform_sphere_pdf(vec3 w) { (void)w; return 0.25f * PL_INV_PI; }

vec2 sample_uniform_disk(vec2 u)
{
    /* Shirley-Chiu concentric map: keeps strata compact, unlike r = sqrt(u). */
    float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return vec2_make(0.0f, 0.0f);
    float r, phi;
    if (fabsf(a) > fabsf(b)) {
        r = a;
        phi = (PL_PI / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (PL_PI / 2.0f) - (PL_PI / 4.0f) * (a / b);
    }
    return vec2_make(r * cosf(phi), r * sinf(phi));
}
float sample_uniform_disk_pdf(vec2 p) { return (p.x * p.x + p.y * p.y <= 1.0f) ? PL_INV_PI : 0.0f; }

vec2 sample_uniform_triangle(vec2 u)
{
    /* Fold the unit square onto the lower-left triangle. */
    if (u.x + u.y > 1.0f) return vec2_make(1.0f - u.x, 1.0f - u.y);
    return u;
}
