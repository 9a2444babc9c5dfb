/* False-colour maps for teaching pictures (sample-rate maps, BVH heat maps).
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_COLORMAP_H
#define PL_COLORMAP_H

#include <stdint.h>
#include <stdio.h>
#include "status.h"

/* CS184's rate colours: t = 0 blue, 0.5 green, 1 red, linear blends between; t is clamped. */
void colormap_rate(float t, uint8_t out[3]);

/* The sample-rate PNG: each pixel coloured by samples[i] / spp (top row first). */
typedef struct {
    const int *samples;  /* per pixel, top row first; not owned */
    int width, height, spp;
} rate_map;

/* Encodes a rate_map (user) as PNG to f (an output_encode_fn). */
pl_status rate_map_encode(FILE *f, const void *user, pl_diag *diag);

#endif
