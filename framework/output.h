/* The outputs of one render, as one unit: all of them appear together, or none does.
 *
 * Before anything is loaded, output_plan derives every file the render will write from the
 * options (image, rate map, sidecar; the heat map) and checks them all: a supported extension, not
 * a directory, no two the same file, none the same file as an input (`-f sc.png` derives sc.json,
 * which may be the scene), a writable folder, and a size the encoders and memory can take. A bad
 * name costs a second, not a render.
 *
 * After the render, output_write encodes each file into its own exclusive temporary beside it,
 * and only when every one succeeded renames them into place, the sidecar last (so a sidecar always
 * describes images that exist). On any failure (a full disk, an encoder error) every temporary is
 * removed and no final name changes.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_OUTPUT_H
#define PL_OUTPUT_H

#include <stdint.h>
#include <stdio.h>
#include "film.h"
#include "image.h"
#include "options.h"
#include "status.h"

/* Writes one file's bytes to f; user is what output_bind was given. */
typedef pl_status (*output_encode_fn)(FILE *f, const void *user, pl_diag *diag);

/* In the order output_write renames them: the sidecar last. */
typedef enum { OUTPUT_IMAGE, OUTPUT_RATE_MAP, OUTPUT_HEATMAP, OUTPUT_SIDECAR, OUTPUT_KINDS } output_kind;

typedef struct {
    char *path[OUTPUT_KINDS];              /* NULL: not written by this render (owned) */
    output_encode_fn encode[OUTPUT_KINDS];
    const void *user[OUTPUT_KINDS];
    image_format format;                   /* the image's, decided once by output_plan (image.h) */
} output_set;

/* Derives and checks every output path of o (see above). Exit-2 errors name the flag and path. */
pl_status output_plan(output_set *set, const options *o, pl_diag *diag);
/* The plan of `--merge -f output IN...`: output is the image alone, with the same checks (extension,
 * not a directory, a folder that takes it, none of the inputs), made before any input is read. */
pl_status output_plan_merge(output_set *set, const char *output, const char *const *inputs, int count, pl_diag *diag);
/* Says how output kind k is encoded (before output_write). */
void output_bind(output_set *set, output_kind k, output_encode_fn encode, const void *user);
/* Binds the image by the format the plan decided: the film (an exr_image, exr.h) for an EXR, the
 * image of the means (tone-mapped PNG or linear HDR) otherwise. */
void output_bind_image(output_set *set, const image *img, const void *film_exr);
/* Writes the kinds in [first, last] as one unit: all renamed into place, sidecar last, or none. */
pl_status output_write(output_set *set, output_kind first, output_kind last, pl_diag *diag);
void output_free(output_set *set);

/* ---- the film stream: a render's film handed to the grader through a pipe, never a file ----------
 * `--film-fd N` sends the film to descriptor N (the grader's pipe) and writes no file, so the grader
 * never parses a file the candidate's process wrote, and writes the EXR itself. Fixed layout, every
 * integer little-endian whatever the machine:
 *   "PLFILM1\n", int32 width, int32 height,
 *   uint64 rays, node_visits, prim_tests, camera samples (the framework's counters: render_stats),
 *   width * height pixels, top row first, each sum[0..3] and sum_sq[0..3] (film.h, 16 bytes each),
 *   then uint32 n and uint32 bad (136 bytes a pixel), and "PLFILM.\n" to close it.
 * A stream that is cut, longer, or of another size is refused whole by output_film_receive. */
#define OUTPUT_FILM_PIXEL_BYTES 136
typedef struct {
    uint64_t rays, node_visits, prim_tests, samples;
} output_film_counts;

/* Writes the stream of f to fd (all of it, retrying short writes). */
pl_status output_film_send(int fd, const film *f, const output_film_counts *c, pl_diag *diag);
/* Reads a stream from memory: out (allocated here; film_free it) must be width x height. Errors say
 * what was wrong and what the case expects, never a number the stream holds ("the film's size is
 * not the case's: the case renders 128x96"): the stream is the candidate's, its message the student's. */
pl_status output_film_receive(const void *data, size_t len, int width, int height, film *out,
                              output_film_counts *c, pl_diag *diag);

#endif
