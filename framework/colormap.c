/* False-colour maps. */
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

pl_status rate_map_write(const char *path, const int *samples, int width, int height, int spp, pl_diag *diag)
{
    size_t n = (size_t)width * (size_t)height;
    uint8_t *bytes = malloc(n * 3);
    if (!bytes) return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) colormap_rate((float)samples[i] / (float)spp, bytes + 3 * i);
    pl_status s = image_write_png_rgb8(bytes, width, height, path, diag);
    free(bytes);
    return s;
}
