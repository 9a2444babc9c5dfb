/* Sample ranges: provenance and the exact merge (range.h).
 *
 * A long reference render is cut into ranges of samples (--samples A:B), rendered anywhere (the
 * Slurm array of course/references), and merged into the film one render would have made. Exactly:
 * the film's accumulators are fixed-point integers (film.h), so addition is associative and the
 * merge of any tiling equals the single render bit for bit. The danger is merging pieces of two
 * different renders, so each EXR carries its provenance (command, seed, version, size, a key hashing
 * the scene and camera files' contents), and the merge refuses pieces that disagree on any of it
 * or that do not tile 0..N exactly once. */
#include "range.h"
#include "file.h"
#include "image.h"
#include "output.h"
#include "version.h"
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_INPUT_BYTES ((size_t)1 << 30)  /* a scene, camera or map file hashed into the key */

/* ---- provenance: what makes two ranges pieces of one render ---------------------------------- */

/* 64-bit FNV-1a: a content hash for the render key (not for security: a key guards against
 * mistakes, not against forgery). */
static uint64_t fnv1a(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

/* Folds a whole file into the key (the scene's contents, not its name: a renamed copy is the same
 * render, an edited file is another). */
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
        {o->hemisphere, " -H"}, {o->normals, " --normals"}, {o->framing == FRAMING_CS184, " --cs184-camera"},
        {o->framing == FRAMING_LITERAL, " --camera literal"},
        {o->linear_scan, " --no-bvh"}, {o->no_roulette, " --no-rr"}, {o->envmap && o->env_uniform, " --env-uniform"}};
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
        if (flags[i].on && n >= 0 && (size_t)n < size) n += snprintf(out + n, size - (size_t)n, "%s", flags[i].flag);
    if (o->adaptive && n >= 0 && (size_t)n < size)
        snprintf(out + n, size - (size_t)n, " -a %d %g", o->adaptive_batch, o->adaptive_tol);
}

/* The provenance of this render, stamped with this build's version. */
pl_status range_info(const options *o, exr_info *info, pl_diag *diag)
{
    return range_info_as(o, PL_VERSION, info, diag);
}

/* The provenance as a given version would stamp it (the grader recomputes a reference's key this
 * way, from the version the reference names). */
pl_status range_info_as(const options *o, const char *version, exr_info *info, pl_diag *diag)
{
    memset(info, 0, sizeof *info);
    char flags[512];
    image_flags(o, flags, sizeof flags);
    snprintf(info->command, sizeof info->command, "pathtracer %s%s%s%s%s %s", flags, o->envmap ? " -e " : "",
             o->envmap ? o->envmap : "", o->camera_file ? " -c " : "", o->camera_file ? o->camera_file : "", o->scene_path);
    snprintf(info->version, sizeof info->version, "%s", version);
    uint64_t h = 0xcbf29ce484222325ull;  /* FNV-1a's offset basis */
    h = fnv1a(h, version, strlen(version) + 1);
    h = fnv1a(h, flags, strlen(flags) + 1);
    pl_status s = hash_file(&h, o->scene_path, "scene", diag);
    if (s == PL_OK && o->camera_file) s = hash_file(&h, o->camera_file, "camera settings", diag);
    if (s == PL_OK && o->envmap) s = hash_file(&h, o->envmap, "environment map", diag);
    if (s != PL_OK) return s;
    snprintf(info->render_key, sizeof info->render_key, "%016" PRIx64, h);
    info->seed = o->seed;
    info->sample_total = o->spp;
    info->sample_begin = o->sample_end ? o->sample_begin : 0;
    info->sample_end = o->sample_end ? o->sample_end : o->spp;
    return PL_OK;
}

/* ---- the merge ------------------------------------------------------------------------------- */

/* One input of the merge: its file, its provenance, its size. */
typedef struct {
    const char *path;
    exr_info info;
    int width, height;
} range_input;

/* qsort order: by first sample, so a tiling reads 0:a, a:b, ..., y:N. */
static int by_begin(const void *a, const void *b)
{
    const range_input *x = a, *y = b;
    return (x->info.sample_begin > y->info.sample_begin) - (x->info.sample_begin < y->info.sample_begin);
}

/* The first provenance field in which b differs from a, as "field: A vs B" in out; false when none.
 * The render key comes last: it hashes the others, so a field named first says more; a key that
 * alone differs means the scene or camera file's contents did. */
static bool first_difference(const range_input *a, const range_input *b, char *out, size_t size)
{
    static const char *const names[6] = {"command", "seed", "version", "size", "sample total",
                                         "render key (the scene or camera file's contents)"};
    char fa[6][EXR_TEXT_MAX], fb[6][EXR_TEXT_MAX];
    const range_input *in[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        char (*f)[EXR_TEXT_MAX] = k ? fb : fa;
        const exr_info *i = &in[k]->info;
        snprintf(f[0], EXR_TEXT_MAX, "%s", i->command);
        snprintf(f[1], EXR_TEXT_MAX, "%" PRIu64, i->seed);
        snprintf(f[2], EXR_TEXT_MAX, "%s", i->version);
        snprintf(f[3], EXR_TEXT_MAX, "%dx%d", in[k]->width, in[k]->height);
        snprintf(f[4], EXR_TEXT_MAX, "%d", i->sample_total);
        snprintf(f[5], EXR_TEXT_MAX, "%s", i->render_key);
    }
    for (int f = 0; f < 6; f++)
        if (strcmp(fa[f], fb[f])) {
            snprintf(out, size, "%s: '%.300s' vs '%.300s'", names[f], fa[f], fb[f]);
            return true;
        }
    return false;
}

/* Checks that the inputs (sorted by first sample) are pieces of one render tiling 0..N. */
static pl_status check_ranges(const range_input *in, int count, pl_diag *diag)
{
    char diff[800];
    for (int i = 1; i < count; i++)
        if (first_difference(&in[0], &in[i], diff, sizeof diff))
            return pl_fail(diag, PL_ERR_INVALID, "%s and %s are not pieces of the same render: their %s", in[0].path,
                           in[i].path, diff);
    int next = 0, total = in[0].info.sample_total;
    for (int i = 0; i < count; i++) {
        const exr_info *b = &in[i].info;
        if (b->sample_begin < next)
            return pl_fail(diag, PL_ERR_INVALID, "%s (samples %d:%d) overlaps %s (samples %d:%d): each sample must be "
                           "merged once", in[i].path, b->sample_begin, b->sample_end, in[i - 1].path,
                           in[i - 1].info.sample_begin, in[i - 1].info.sample_end);
        if (b->sample_begin > next)
            return pl_fail(diag, PL_ERR_INVALID, "samples %d:%d are missing (before %s, which starts at %d): the ranges "
                           "must tile 0:%d", next, b->sample_begin, in[i].path, b->sample_begin, total);
        next = b->sample_end;
    }
    if (next != total)
        return pl_fail(diag, PL_ERR_INVALID, "samples %d:%d are missing (after %s): the ranges must tile 0:%d", next,
                       total, in[count - 1].path, total);
    return PL_OK;
}

/* Adds the films of the checked inputs into total, one file at a time (so a merge holds two films,
 * whatever the number of pieces); each file is read whole and checked again, pixel by pixel. */
static pl_status merge_films(const range_input *in, int count, film *total, pl_diag *diag)
{
    if (film_alloc(total, in[0].width, in[0].height) != PL_OK)
        return pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d film", in[0].width, in[0].height);
    long pixels = (long)total->width * total->height;
    for (int i = 0; i < count; i++) {
        range_input again;
        memset(&again, 0, sizeof again);
        again.path = in[i].path;
        film piece;
        char diff[800];
        pl_status s = exr_read(in[i].path, &piece, &again.info, diag);
        again.width = piece.width, again.height = piece.height;
        if (s == PL_OK && (first_difference(&in[i], &again, diff, sizeof diff) ||
                           again.info.sample_begin != in[i].info.sample_begin || again.info.sample_end != in[i].info.sample_end))
            s = pl_fail(diag, PL_ERR_INVALID, "%s changed while it was merged", in[i].path);
        for (long p = 0; s == PL_OK && p < pixels; p++)
            if (!film_pixel_merge(&total->pixels[p], &piece.pixels[p]))
                s = pl_fail(diag, PL_ERR_INVALID, "%s: pixel %ld: the merged sample count overflows", in[i].path, p);
        film_free(&piece);
        if (s != PL_OK) return s;
    }
    return PL_OK;
}

/* Writes the merged film through the planned output set (an exclusive temporary renamed into place,
 * as a render's files): EXR with the merged provenance, or the image of the means through the
 * encoder a single render uses. */
static pl_status write_merged(output_set *out, const film *total, const exr_info *first, pl_diag *diag)
{
    if (out->format == IMAGE_FORMAT_EXR) {
        exr_info info = *first;
        info.sample_begin = 0;
        info.sample_end = info.sample_total;
        exr_image film_exr = {total, &info};
        output_bind_image(out, NULL, &film_exr);
        return output_write(out, OUTPUT_IMAGE, OUTPUT_IMAGE, diag);
    }
    image img;
    if (image_alloc(&img, total->width, total->height) != PL_OK) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    pl_status s = film_to_image(total, &img, NULL, diag);
    output_bind_image(out, &img, NULL);
    if (s == PL_OK) s = output_write(out, OUTPUT_IMAGE, OUTPUT_IMAGE, diag);
    image_free(&img);
    return s;
}

/* --merge's options, in any order around the inputs: -f OUT (once), -q (accepted: a merge prints
 * only errors), -h; any other option is refused by name. Fills inputs (pointers into argv). */
static pl_status merge_args(int argc, char **argv, const char **out, const char **inputs, int *count, bool *help,
                            pl_diag *diag)
{
    *out = NULL, *count = 0, *help = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--merge") || !strcmp(a, "-q")) continue;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) *help = true;
        else if (!strcmp(a, "-f")) {
            if (*out || i + 1 >= argc) return pl_fail(diag, PL_ERR_INVALID, "-f: expected one output file name");
            *out = argv[++i];
        }
        else if (a[0] == '-' && a[1]) return pl_fail(diag, PL_ERR_INVALID, "%s: not an option of --merge", a);
        else inputs[(*count)++] = a;
    }
    if (*help) return PL_OK;
    if (!*out || image_format_of(*out) == IMAGE_FORMAT_NONE)
        return pl_fail(diag, PL_ERR_INVALID, "expected -f OUT.exr, OUT.png or OUT.hdr");
    return *count >= 1 ? PL_OK : pl_fail(diag, PL_ERR_INVALID, "expected at least one range file (IN.exr)");
}

/* Reads and checks the headers of every input (no pixel yet): provenance, size, tiling. */
static pl_status read_headers(range_input *in, const char **paths, int count, pl_diag *diag)
{
    pl_status s = PL_OK;
    for (int i = 0; i < count && s == PL_OK; i++) {
        in[i].path = paths[i];
        s = exr_read_info(paths[i], &in[i].info, &in[i].width, &in[i].height, diag);
    }
    if (s != PL_OK) return s;
    qsort(in, (size_t)count, sizeof *in, by_begin);
    return check_ranges(in, count, diag);
}

/* --merge: plan the output, read and check every header, then add the films one at a time and
 * write; exit 0, 1 (out of memory, or the output could not be written) or 2 (the command, or an
 * input that is missing, unreadable or not a piece of this render). */
int range_merge_main(int argc, char **argv, const char *prog)
{
    pl_diag diag = pl_diag_default();
    const char *out = NULL, **inputs = calloc((size_t)argc, sizeof *inputs);
    range_input *in = calloc((size_t)argc, sizeof *in);
    int count = 0, code = 2;
    bool help = false;
    output_set plan = {0};
    film total = {0};
    if (!inputs || !in) {
        fprintf(stderr, "%s: out of memory\n", prog);
        code = 1;
    }
    else if (merge_args(argc, argv, &out, inputs, &count, &help, &diag) != PL_OK)
        fprintf(stderr, "%s: --merge: %s\nusage: %s --merge -f OUT.exr|OUT.png|OUT.hdr IN1.exr [IN2.exr ...]\n", prog,
                diag.error, prog);
    else if (help) {
        printf("usage: %s --merge -f OUT.exr|OUT.png|OUT.hdr IN1.exr [IN2.exr ...] (options in any order)\n", prog);
        code = 0;
    }
    /* The output is checked as a render's are, before a byte of any input is read. */
    else if (output_plan_merge(&plan, out, inputs, count, &diag) != PL_OK || read_headers(in, inputs, count, &diag) != PL_OK ||
             merge_films(in, count, &total, &diag) != PL_OK)
        fprintf(stderr, "%s: --merge: %s\n", prog, diag.error);
    else if (write_merged(&plan, &total, &in[0].info, &diag) != PL_OK) {
        fprintf(stderr, "%s: --merge: %s\n", prog, diag.error);
        code = 1;
    }
    else code = 0;
    film_free(&total);
    output_free(&plan);
    free(in);
    free(inputs);
    return code;
}
