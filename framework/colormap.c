/* False-colour maps: numbers shown as colour for the teaching pictures (sample-rate maps here; the
 * BVH heat map in heatmap.c uses the same ramp). */
#include "colormap.h"
#include "image.h"
#include <stdlib.h>

void colormap_rate(float t, uint8_t out[3])
{
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    float r, g, b;
    if (t < 0.5f) {  /* blue -> green */
        float k = t * 2.0f;
        r = 0.0f, g = k, b = 1.0f - k;
    } else {         /* green -> red */
        float k = (t - 0.5f) * 2.0f;
        r = k, g = 1.0f - k, b = 0.0f;
    }
    out[0] = (uint8_t)(r * 255.0f + 0.5f);
    out[1] = (uint8_t)(g * 255.0f + 0.5f);
    out[2] = (uint8_t)(b * 255.0f + 0.5f);
}

/* The sample-rate map: each pixel's share of the -s budget (1: every sample was taken), as a PNG. */
pl_status rate_map_encode(FILE *f, const void *user, pl_diag *diag)
{
    const rate_map *m = user;
    size_t n = (size_t)m->width * (size_t)m->height;
    uint8_t *bytes = malloc(n * 3);
    if (!bytes) return pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d rate map", m->width, m->height);
    for (size_t i = 0; i < n; i++) colormap_rate((float)m->samples[i] / (float)m->spp, bytes + 3 * i);
    pl_status s = image_encode_png_rgb8(f, bytes, m->width, m->height, diag);
    free(bytes);
    return s;
}
