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
 * pathlab.samples ("A:B of N") and pathlab.render_key (what must match for a merge).
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_EXR_H
#define PL_EXR_H

#include <stdio.h>
#include <stdint.h>
#include "film.h"
#include "status.h"

#define EXR_TEXT_MAX 2048
/* The films a reader accepts (checked from the header, before any pixel is allocated): -r's limit a
 * side, and 2^21 pixels in all (1920x1080 fits; a film takes 144 bytes a pixel, so 302 MB, and a
 * merge holds two); -s's limit of samples. */
#define EXR_MAX_SIDE (1 << 15)
#define EXR_MAX_PIXELS (1L << 21)
#define EXR_MAX_SAMPLES (1 << 24)

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

/* Reads a file exr_encode wrote, and only such a file: one scanline part, ZIP, exactly the channels
 * above with their types and no subsampling, a size within the caps, every pathlab.* attribute in
 * the form the writer gives it, every chunk decoding to exactly its rows, and every pixel one a
 * render of its sample range could give (film_check: B - A samples a pixel, or 1..N for an adaptive
 * render). The film is allocated here (film_free it). Errors name the file and the field. */
pl_status exr_read(const char *path, film *out, exr_info *info, pl_diag *diag);

/* The same checks of the header alone (nothing allocated for pixels): the provenance and size. */
pl_status exr_read_info(const char *path, exr_info *info, int *width, int *height, pl_diag *diag);

/* Whether the render was adaptive (-a in its command): its pixels hold from 1 to N samples. */
bool exr_info_adaptive(const exr_info *info);

/* ---- any RGB image: environment maps (envmap.h) ----------------------------------------------
 * Unlike a film, such an image comes from anywhere (a sky tool, an HDRI library): every
 * compression OpenEXR decodes, half or float, R G B of any single-part scanline file, other
 * channels ignored. Texels are interleaved R G B floats, row 0 the top of the data window. */
typedef struct {
    int width, height;
    float *texels;  /* 3 * width * height floats (owned by whoever read or made it) */
} exr_rgb_image;

/* Writes user (an exr_rgb_image) as R, G, B floats, ZIP: the output module's encoder type. */
pl_status exr_encode_rgb(FILE *f, const void *user, pl_diag *diag);

/* Reads path's R, G and B as floats (out->texels allocated here; free it). Refused, naming the file and
 * what was expected: a tiled or multi-part file, a missing or subsampled R, G or B, more than
 * max_side texels a side or max_pixels in all (checked before anything is allocated), and any value
 * that is not finite (named by its position and channel); values below 0 read as 0, with a warning. */
pl_status exr_read_rgb(const char *path, int max_side, long max_pixels, exr_rgb_image *out, pl_diag *diag);

#endif
