/* False-colour maps for teaching pictures (sample-rate maps, BVH heat maps). */
#ifndef PL_COLORMAP_H
#define PL_COLORMAP_H

#include <stdint.h>
#include "status.h"

/* CS184's rate colours: t = 0 blue, 0.5 green, 1 red, linear blends between; t is clamped. */
void colormap_rate(float t, uint8_t out[3]);

/* Writes the sample-rate PNG: each pixel coloured by samples[i] / spp (top row first). */
pl_status rate_map_write(const char *path, const int *samples, int width, int height, int spp, pl_diag *diag);

#endif
