/* OpenEXR files of a film: the image, how much to trust each pixel, and everything needed to merge
 * renders of sample ranges exactly. Written and read through OpenEXR's C API (openexr.h).
 *
 * Channels (EXR stores them sorted by name):
 *   R, G, B            float: the mean radiance (what the PNG shows, before the tone curve)
 *   var.R .. var.Y     float: the variance of that mean per channel and for luminance Y
 *   n, bad             uint:  samples taken, and how many of them were bad (film.h)
 *   acc.sum.R.0 .. acc.sq.Y.3   uint: the fixed-point sums of film.h, each 128-bit sum as four
 *                      32-bit words, least significant first. The merge reads only these and n, bad.
 * Header attributes (strings): pathlab.command (the render's flags, normalised so that every range
 * and thread count of one render gives the same text), pathlab.seed, pathlab.version (PL_VERSION),
 * pathlab.samples ("A:B of N") and pathlab.render_key (what must match for a merge). */
#ifndef PL_EXR_H
#define PL_EXR_H

#include <stdio.h>
#include <stdint.h>
#include "film.h"
#include "status.h"

#define EXR_TEXT_MAX 2048

typedef struct {
    char command[EXR_TEXT_MAX];  /* normalised command line */
    char version[64];
    char render_key[40];         /* 16 hex digits of a 64-bit hash */
    uint64_t seed;
    int sample_begin, sample_end, sample_total;  /* samples A..B-1 of N */
} exr_info;

typedef struct {
    const film *film;
    const exr_info *info;
} exr_image;

/* Writes user (an exr_image) to f through OpenEXR's stream callbacks (pwrite on fileno(f)).
 * The output module's encoder type: pl_status (*)(FILE *f, const void *user, pl_diag *diag). */
pl_status exr_encode(FILE *f, const void *user, pl_diag *diag);

/* Reads a file exr_encode wrote: the film (allocated here; film_free it) from the accumulator
 * channels, and the header attributes. Errors name the file and what was wrong. */
pl_status exr_read(const char *path, film *out, exr_info *info, pl_diag *diag);

#endif
