/* Float images and their files. Pixels are linear rgb, stored top row first (row 0 = top), as
 * image files are. Writers go to a temporary file in the same folder and rename it into place,
 * so a killed render never leaves a half-written image.
 * Parts may not call: any function declared here but the static inline ones (the grader refuses them). */
#ifndef PL_IMAGE_H
#define PL_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "vec.h"
#include "status.h"
#include "file.h"

typedef struct {
    int width, height;
    rgb *pixels;  /* width * height, row-major, top row first; owned */
} image;

pl_status image_alloc(image *img, int width, int height);  /* black; PL_ERR_NOMEM on failure */
void image_free(image *img);                                /* NULL-safe */
static inline rgb image_get(const image *img, int x, int y) { return img->pixels[(long)y * img->width + x]; }
static inline void image_set(image *img, int x, int y, rgb c) { img->pixels[(long)y * img->width + x] = c; }

/* The formats an image file may have, by its name as CS184's -f decides: .png tone-mapped for
 * people, .hdr linear (Radiance RGBE), .exr the film (exr.h). image_format_of is the one place a
 * file's name decides its format: the output plan asks it once per render (output.h), and the
 * writers and readers here ask it for the name they were given. */
typedef enum { IMAGE_FORMAT_NONE, IMAGE_FORMAT_PNG, IMAGE_FORMAT_HDR, IMAGE_FORMAT_EXR } image_format;
image_format image_format_of(const char *path);

/* CS184's tone curve: clamp((v * sqrt(2))^(1/2.2), 0, 1) per channel, then 8 bits. */
uint8_t tonemap_channel(float v);

/* Encoders: the file's bytes to an open FILE (the output set's temporaries). img is an image *
 * (void * so they fit output_encode_fn). */
pl_status image_encode_png(FILE *f, const void *img, pl_diag *diag);   /* CS184's tone curve */
pl_status image_encode_hdr(FILE *f, const void *img, pl_diag *diag);   /* linear */
pl_status image_encode_png_rgb8(FILE *f, const uint8_t *rgb8, int width, int height, pl_diag *diag);

/* PNG through CS184's tone curve. */
pl_status image_write_png(const image *img, const char *path, pl_diag *diag);
/* Radiance HDR (RGBE), linear values. */
pl_status image_write_hdr(const image *img, const char *path, pl_diag *diag);
/* By its format (image_format_of): .png or .hdr; anything else is PL_ERR_INVALID. */
pl_status image_write(const image *img, const char *path, pl_diag *diag);
/* 8-bit RGB, 3 bytes a pixel, top row first, written as-is (rate maps, heat maps, diffs). */
pl_status image_write_png_rgb8(const uint8_t *rgb8, int width, int height, const char *path, pl_diag *diag);
/* Reads a .hdr (linear values) or a .png (8-bit values / 255, no inverse tone curve). */
pl_status image_read(const char *path, image *out, pl_diag *diag);

#endif
