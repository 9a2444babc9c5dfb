/* Sample ranges: provenance and the exact merge (range.h). */
#include "range.h"
#include "file.h"
#include "image.h"
#include "output.h"
#include "version.h"
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_INPUT_BYTES ((size_t)1 << 30)

/* 64-bit FNV-1a: a content hash for the render key (not for security: a key guards against
 * mistakes, not against forgery). */
static uint64_t fnv1a(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

static pl_status hash_file(uint64_t *h, const char *path, const char *what, pl_diag *diag)
{
    char *data = NULL;
    size_t len = 0;
    pl_status s = file_read_all(path, what, MAX_INPUT_BYTES, &data, &len, diag);
    if (s == PL_OK) *h = fnv1a(*h, data, len);
    free(data);
    return s;
}

/* Every flag that changes the image, in one fixed order, so that two renders of the same image
 * write the same text whatever order their flags came in and whatever -t, -q, -v or -f they had.
 * --no-bvh and --leaf-size stay: a different accelerator may round a hit differently. */
static void image_flags(const options *o, char *out, size_t size)
{
    int n = snprintf(out, size, "-s %d -l %d -m %d -o %d -b %g -d %g -r %d %d --seed %" PRIu64 " --leaf-size %d", o->spp,
                     o->light_samples, o->max_depth, o->accumulate ? 1 : 0, o->lens_radius, o->focal_distance,
                     o->width, o->height, o->seed, o->max_leaf_size);
    const struct { bool on; const char *flag; } flags[] = {
        {o->hemisphere, " -H"}, {o->normals, " --normals"}, {o->cs184_framing, " --cs184-camera"},
        {o->linear_scan, " --no-bvh"}, {o->no_roulette, " --no-rr"}};
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
        if (flags[i].on && n >= 0 && (size_t)n < size) n += snprintf(out + n, size - (size_t)n, "%s", flags[i].flag);
    if (o->adaptive && n >= 0 && (size_t)n < size)
        snprintf(out + n, size - (size_t)n, " -a %d %g", o->adaptive_batch, o->adaptive_tol);
}

pl_status range_info(const options *o, exr_info *info, pl_diag *diag)
{
    memset(info, 0, sizeof *info);
    char flags[512];
    image_flags(o, flags, sizeof flags);
    snprintf(info->command, sizeof info->command, "pathtracer %s%s%s %s", flags, o->camera_file ? " -c " : "",
             o->camera_file ? o->camera_file : "", o->scene_path);
    snprintf(info->version, sizeof info->version, "%s", PL_VERSION);
    uint64_t h = 0xcbf29ce484222325ull;
    h = fnv1a(h, PL_VERSION, sizeof PL_VERSION);
    h = fnv1a(h, flags, strlen(flags) + 1);
    pl_status s = hash_file(&h, o->scene_path, "scene", diag);
    if (s == PL_OK && o->camera_file) s = hash_file(&h, o->camera_file, "camera settings", diag);
    if (s != PL_OK) return s;
    snprintf(info->render_key, sizeof info->render_key, "%016" PRIx64, h);
    info->seed = o->seed;
    info->sample_total = o->spp;
    info->sample_begin = o->sample_end ? o->sample_begin : 0;
    info->sample_end = o->sample_end ? o->sample_end : o->spp;
    return PL_OK;
}

/* ---- the merge ------------------------------------------------------------------------------- */

typedef struct {
    const char *path;
    film film;
    exr_info info;
} range_input;

static int by_begin(const void *a, const void *b)
{
    const range_input *x = a, *y = b;
    return (x->info.sample_begin > y->info.sample_begin) - (x->info.sample_begin < y->info.sample_begin);
}

/* Checks that the inputs (sorted by first sample) are pieces of one render tiling 0..N. */
static pl_status check_ranges(const range_input *in, int count, pl_diag *diag)
{
    const exr_info *a = &in[0].info;
    for (int i = 1; i < count; i++) {
        const exr_info *b = &in[i].info;
        if (strcmp(a->render_key, b->render_key) || a->sample_total != b->sample_total ||
            in[0].film.width != in[i].film.width || in[0].film.height != in[i].film.height)
            return pl_fail(diag, PL_ERR_INVALID, "%s and %s are not pieces of the same render: render key %s vs %s "
                           "(scene, flags, resolution, seed or code version differ)\n  %s: %s, version %s, %d samples\n  %s: %s, version %s, %d samples",
                           in[0].path, in[i].path, a->render_key, b->render_key, in[0].path, a->command, a->version,
                           a->sample_total, in[i].path, b->command, b->version, b->sample_total);
    }
    int next = 0;
    for (int i = 0; i < count; i++) {
        const exr_info *b = &in[i].info;
        if (b->sample_begin < next)
            return pl_fail(diag, PL_ERR_INVALID, "%s (samples %d:%d) overlaps %s (samples %d:%d): each sample must be "
                           "merged once", in[i].path, b->sample_begin, b->sample_end, in[i - 1].path,
                           in[i - 1].info.sample_begin, in[i - 1].info.sample_end);
        if (b->sample_begin > next)
            return pl_fail(diag, PL_ERR_INVALID, "samples %d:%d are missing (before %s, which starts at %d): the ranges "
                           "must tile 0:%d", next, b->sample_begin, in[i].path, b->sample_begin, b->sample_total);
        next = b->sample_end;
    }
    if (next != a->sample_total)
        return pl_fail(diag, PL_ERR_INVALID, "samples %d:%d are missing (after %s): the ranges must tile 0:%d", next,
                       a->sample_total, in[count - 1].path, a->sample_total);
    return PL_OK;
}

/* Sums the checked inputs into in[0].film and writes it through the planned output set (an
 * exclusive temporary renamed into place, as a render's files): EXR with the merged provenance,
 * or the image of the means through the encoder a single render uses. */
static pl_status write_merged(output_set *out, range_input *in, int count, pl_diag *diag)
{
    film *total = &in[0].film;
    long pixels = (long)total->width * total->height;
    for (int i = 1; i < count; i++)
        for (long p = 0; p < pixels; p++) film_pixel_merge(&total->pixels[p], &in[i].film.pixels[p]);
    const char *path = out->path[OUTPUT_IMAGE];
    if (file_has_extension(path, ".exr")) {
        exr_info info = in[0].info;
        info.sample_begin = 0;
        info.sample_end = info.sample_total;
        exr_image img = {total, &info};
        output_bind(out, OUTPUT_IMAGE, exr_encode, &img);
        return output_write(out, OUTPUT_IMAGE, OUTPUT_IMAGE, diag);
    }
    image img;
    if (image_alloc(&img, total->width, total->height) != PL_OK) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    pl_status s = film_to_image(total, &img, NULL, diag);
    output_bind(out, OUTPUT_IMAGE, file_has_extension(path, ".hdr") ? image_encode_hdr : image_encode_png, &img);
    if (s == PL_OK) s = output_write(out, OUTPUT_IMAGE, OUTPUT_IMAGE, diag);
    image_free(&img);
    return s;
}

int range_merge_main(int argc, char **argv, const char *prog)
{
    pl_diag diag = pl_diag_default();
    const char *out = NULL;
    int first_input = 2;
    if (argc >= 4 && !strcmp(argv[2], "-f")) out = argv[3], first_input = 4;
    int count = argc - first_input;
    if (!out || count < 1 || !(file_has_extension(out, ".exr") || file_has_extension(out, ".png") || file_has_extension(out, ".hdr"))) {
        fprintf(stderr, "%s: --merge: expected --merge -f OUT.exr|OUT.png|OUT.hdr IN1.exr [IN2.exr ...]\n", prog);
        return 2;
    }
    /* The output is checked as a render's are, before a byte of any input is read. */
    output_set plan;
    if (output_plan_merge(&plan, out, (const char *const *)argv + first_input, count, &diag) != PL_OK) {
        fprintf(stderr, "%s: --merge: %s\n", prog, diag.error);
        output_free(&plan);
        return 2;
    }
    range_input *in = calloc((size_t)count, sizeof *in);
    if (!in) { fprintf(stderr, "%s: out of memory\n", prog); output_free(&plan); return 1; }
    pl_status s = PL_OK;
    int read = 0;
    for (; read < count && s == PL_OK; read++) {
        in[read].path = argv[first_input + read];
        s = exr_read(in[read].path, &in[read].film, &in[read].info, &diag);
        if (s != PL_OK) read--;
    }
    if (s == PL_OK) {
        qsort(in, (size_t)count, sizeof *in, by_begin);
        s = check_ranges(in, count, &diag);
    }
    int code = s == PL_OK ? 0 : 2;
    if (s == PL_OK && write_merged(&plan, in, count, &diag) != PL_OK) code = 1;
    if (code) fprintf(stderr, "%s: --merge: %s\n", prog, diag.error);
    for (int i = 0; i < read; i++) film_free(&in[i].film);
    free(in);
    output_free(&plan);
    return code;
}
