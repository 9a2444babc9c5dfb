/* The outputs of one render: planned and checked before loading, written as one unit after.
 *
 * A render can take minutes, so everything that could make its outputs fail is checked first: the
 * extensions, the folders, the image's size against memory and the PNG encoder, and that no output
 * overwrites an input or another output. Writing is all or nothing: every file goes to a temporary
 * beside its final name and is renamed into place only when all of them are complete, so an
 * interrupted or failed write never leaves a half image beside a sidecar that describes it.
 * The last section is the film stream, the grader's pipe format (output.h says why it exists). */
#include "output.h"
#include "exr.h"
#include "file.h"
#include "parallel.h"
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* The flag that named each output, for messages ("-f (its rate map) out_rate.png: ..."). */
static const char *const flag_of[OUTPUT_KINDS] = {"-f", "-f (its rate map)", "--heatmap", "-f (its sidecar)"};
_Static_assert(FILE_MAX_TEMPS >= OUTPUT_KINDS, "a render's temporaries must all fit the cleanup table");

/* ---- planning: names, folders and sizes, before the scene is loaded ------------------------- */

/* "out.png" -> "out.json", "out.png" + "_rate" -> "out_rate.png": swaps or inserts before the extension. */
static char *with_suffix(const char *path, const char *suffix, const char *extension)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    size_t stem = (dot && (!slash || dot > slash)) ? (size_t)(dot - path) : strlen(path);
    size_t n = stem + strlen(suffix) + strlen(extension) + 1;
    char *out = malloc(n);
    if (out) snprintf(out, n, "%.*s%s%s", (int)stem, path, suffix, extension);
    return out;
}

/* Where a path leads: its folder resolved (symlinks, "..") plus its own name, so two spellings of
 * one file compare equal even before it exists. Empty when the folder does not exist. */
static void canonical(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    char folder[PATH_MAX], resolved[PATH_MAX];
    snprintf(folder, sizeof folder, "%.*s", slash ? (int)(slash - path) + 1 : 1, slash ? path : ".");
    out[0] = '\0';
    if (!realpath(folder, resolved)) return;
    const char *name = slash ? slash + 1 : path;
    /* An existing symlink is followed too: writing through it would replace its target. */
    char full[PATH_MAX * 2], target[PATH_MAX];
    snprintf(full, sizeof full, "%s/%s", resolved, name);
    if (realpath(full, target)) snprintf(out, size, "%s", target);
    else snprintf(out, size, "%s", full);
}

/* The folder holding path must exist and take new files. */
static pl_status check_folder(const char *flag, const char *path, pl_diag *diag)
{
    const char *slash = strrchr(path, '/');
    char folder[PATH_MAX];
    snprintf(folder, sizeof folder, "%.*s", slash ? (int)(slash - path) + 1 : 1, slash ? path : ".");
    if (access(folder, W_OK | X_OK) != 0)
        return pl_fail(diag, PL_ERR_INVALID, "%s %s: cannot write into '%s': %s", flag, path, folder, strerror(errno));
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return pl_fail(diag, PL_ERR_INVALID, "%s %s: is a directory; expected a file name", flag, path);
    return PL_OK;
}

/* stb's PNG writer indexes with int: a row of w*3+1 bytes times h rows must fit. */
static bool png_size_ok(int w, int h) { return ((long long)w * 3 + 1) * (long long)h < INT_MAX; }

/* What a render holds per pixel while it runs (image, samples taken, encoders' copies), against
 * the machine's memory: a size that cannot fit is refused before loading, not after rendering. */
#define BYTES_PER_PIXEL 64

/* Every output: a folder that takes it, not a directory, no other output's file, and not the file
 * `input` (NULL: none; called once per input) names. */
static pl_status check_paths(const output_set *set, const char *input, const char *input_flag, pl_diag *diag)
{
    char here[OUTPUT_KINDS][PATH_MAX * 2], in[PATH_MAX * 2];
    if (input) canonical(input, in, sizeof in);
    for (int k = 0; k < OUTPUT_KINDS; k++) {
        if (!set->path[k]) continue;
        pl_status st = check_folder(flag_of[k], set->path[k], diag);
        if (st) return st;
        canonical(set->path[k], here[k], sizeof here[k]);
        for (int j = 0; j < k; j++)
            if (set->path[j] && !strcmp(here[j], here[k]))
                return pl_fail(diag, PL_ERR_INVALID, "%s %s and %s %s name the same file", flag_of[j], set->path[j],
                               flag_of[k], set->path[k]);
        if (input && !strcmp(in, here[k]))
            return pl_fail(diag, PL_ERR_INVALID, "%s %s would overwrite %s (%s): choose another output name",
                           flag_of[k], set->path[k], input_flag, input);
    }
    return PL_OK;
}

pl_status output_plan(output_set *set, const options *o, pl_diag *diag)
{
    memset(set, 0, sizeof *set);
    /* Memory first: a size that would swap the machine is refused whatever the outputs are. */
    long long pixels = (long long)o->width * o->height;
    long long memory = (long long)sysconf(_SC_PHYS_PAGES) * sysconf(_SC_PAGE_SIZE);
    if (memory > 0 && pixels * BYTES_PER_PIXEL > memory / 2)
        return pl_fail(diag, PL_ERR_INVALID, "-r %d %d: %lld pixels need about %lld MB, more than half of this "
                       "machine's memory", o->width, o->height, pixels, pixels * BYTES_PER_PIXEL >> 20);
    if (o->output) {
        /* The format -f writes, decided here once: tone-mapped PNG, linear Radiance HDR, or EXR with the film. */
        if ((set->format = image_format_of(o->output)) == IMAGE_FORMAT_NONE)
            return pl_fail(diag, PL_ERR_INVALID, "-f %s: expected a file name ending in .png, .hdr or .exr", o->output);
        set->path[OUTPUT_IMAGE] = strdup(o->output);
        set->path[OUTPUT_RATE_MAP] = with_suffix(o->output, "_rate", ".png");
        set->path[OUTPUT_SIDECAR] = with_suffix(o->output, "", ".json");
    }
    if (o->heatmap) {
        if (image_format_of(o->heatmap) != IMAGE_FORMAT_PNG)
            return pl_fail(diag, PL_ERR_INVALID, "--heatmap %s: expected a file name ending in .png", o->heatmap);
        set->path[OUTPUT_HEATMAP] = strdup(o->heatmap);
    }
    bool png = set->format == IMAGE_FORMAT_PNG;
    if ((o->output || o->heatmap) && !png_size_ok(o->width, o->height + 64))
        return pl_fail(diag, PL_ERR_INVALID, "-r %d %d: too large for a PNG file (the encoder's limit is about "
                       "715 million pixels)%s", o->width, o->height, png ? "" : "; the rate map is a PNG");

    /* Every output against every input: "-f scene.dae" would otherwise destroy the scene. */
    const char *inputs[2] = {o->scene_path, o->camera_file};
    const char *input_flag[2] = {"the scene", "the camera file (-c)"};
    for (int i = 0; i < 2; i++) {
        pl_status st = check_paths(set, inputs[i], input_flag[i], diag);
        if (st) return st;
    }
    /* A NULL where a path was planned is a failed strdup or with_suffix, checked once here. */
    for (int k = 0; k < OUTPUT_KINDS; k++)
        if (set->path[k] == NULL && ((k != OUTPUT_HEATMAP && o->output) || (k == OUTPUT_HEATMAP && o->heatmap)))
            return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    return PL_OK;
}

/* --merge: one image from several EXR films; none of them may be the output. */
pl_status output_plan_merge(output_set *set, const char *output, const char *const *inputs, int count, pl_diag *diag)
{
    memset(set, 0, sizeof *set);
    if ((set->format = image_format_of(output)) == IMAGE_FORMAT_NONE)
        return pl_fail(diag, PL_ERR_INVALID, "-f %s: expected a file name ending in .png, .hdr or .exr", output);
    if (!(set->path[OUTPUT_IMAGE] = strdup(output))) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    pl_status st = check_paths(set, NULL, NULL, diag);
    for (int i = 0; i < count && !st; i++) st = check_paths(set, inputs[i], "an input of the merge", diag);
    return st;
}

/* ---- writing: the files encoded side by side, then all committed together ------------------- */

/* Binds an encoder and its data to a planned output (an unbound output is not written). */
void output_bind(output_set *set, output_kind k, output_encode_fn encode, const void *user)
{
    set->encode[k] = encode;
    set->user[k] = user;
}

void output_bind_image(output_set *set, const image *img, const void *film_exr)
{
    if (set->format == IMAGE_FORMAT_EXR) output_bind(set, OUTPUT_IMAGE, exr_encode, film_exr);
    else output_bind(set, OUTPUT_IMAGE, set->format == IMAGE_FORMAT_HDR ? image_encode_hdr : image_encode_png, img);
}

/* Encoding is the slow part (PNG deflate): the files are encoded side by side, one thread each. */
typedef struct {
    output_set *set;
    output_kind kind;
    file_temp temp;
    pl_diag diag;
    pl_status status;
} encode_job;

static void encode_one(void *arg, int i)
{
    encode_job *j = (encode_job *)arg + i;
    j->status = file_temp_create(j->set->path[j->kind], &j->temp, &j->diag);
    if (!j->status && (j->status = j->set->encode[j->kind](j->temp.f, j->set->user[j->kind], &j->diag))) {
        /* Encoders know bytes, not names ("could not encode or write a 800x600 PNG"): add the file's. */
        const char *path = j->set->path[j->kind];
        if (strncmp(j->diag.error, path, strlen(path)) != 0) {
            char why[PL_DIAG_MSG_MAX];
            snprintf(why, sizeof why, "%s", j->diag.error);
            pl_fail(&j->diag, j->status, "%s: %s", path, why);
        }
    }
    if (!j->status) j->status = file_temp_close(&j->temp, &j->diag);
}

/* Writes the bound outputs from first to last: encoded in parallel (parallel_for_threads, a thread a
 * file), each into its temporary; the first failure (in the kinds' order, so the message does not
 * depend on thread timing) wins. */
pl_status output_write(output_set *set, output_kind first, output_kind last, pl_diag *diag)
{
    encode_job jobs[OUTPUT_KINDS];
    int count = 0;
    for (int k = first; k <= (int)last; k++)
        if (set->path[k] && set->encode[k])
            jobs[count++] = (encode_job){set, (output_kind)k, {NULL, NULL, NULL, -1}, pl_diag_default(), PL_OK};
    parallel_for_threads(count, count, encode_one, jobs);
    pl_status st = PL_OK;
    for (int i = 0; i < count && !st; i++)
        if (jobs[i].status) {
            st = jobs[i].status;
            pl_fail(diag, st, "%s", jobs[i].diag.error);
        }
    /* All or nothing: rename only when every file is complete, in the kinds' order: the sidecar last. */
    for (int i = 0; i < count; i++) {
        if (st) file_temp_discard(&jobs[i].temp);
        else if ((st = file_temp_commit(&jobs[i].temp, diag)))
            for (int j = i + 1; j < count; j++) file_temp_discard(&jobs[j].temp);
    }
    return st;
}

void output_free(output_set *set)
{
    for (int k = 0; k < OUTPUT_KINDS; k++) free(set->path[k]);
    memset(set, 0, sizeof *set);
}

/* ---- the film stream ------------------------------------------------------------------------- */

/* The grader's pipe format (--film-fd): the render sends its film, the grader writes the EXR. All
 * integers little-endian, whatever the machine:
 *   "PLFILM1\n", width and height (4 bytes each), rays, node visits, primitive tests, samples (8
 *   bytes each), then per pixel OUTPUT_FILM_PIXEL_BYTES: 4 sums and 4 sums of squares of 16 bytes
 *   (the film's fixed-point 128-bit accumulators), the sample count and the bad-sample count (4
 *   each), and "PLFILM.\n" to end. The end marker and the exact length let the receiver refuse a
 *   stream cut short or padded, which a render killed mid-write would otherwise pass off as a film. */

static const char film_magic[8] = {'P', 'L', 'F', 'I', 'L', 'M', '1', '\n'};
static const char film_end[8] = {'P', 'L', 'F', 'I', 'L', 'M', '.', '\n'};
#define FILM_HEADER_BYTES (8 + 2 * 4 + 4 * 8)

/* Little-endian bytes of an unsigned value, lowest first, and back. */
static void put_le(unsigned char *p, film_sum v, int bytes)
{
    for (int i = 0; i < bytes; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static film_sum get_le(const unsigned char *p, int bytes)
{
    film_sum v = 0;
    for (int i = bytes - 1; i >= 0; i--) v = v << 8 | p[i];
    return v;
}

static void pixel_bytes(const film_pixel *px, unsigned char *p)
{
    for (int c = 0; c < 4; c++) put_le(p + 16 * c, px->sum[c], 16), put_le(p + 64 + 16 * c, px->sum_sq[c], 16);
    put_le(p + 128, px->n, 4);
    put_le(p + 132, px->bad, 4);
}

/* write(2) until everything is sent: a pipe takes what fits in its buffer and returns short. */
static bool write_all(int fd, const unsigned char *p, size_t len)
{
    while (len > 0) {
        ssize_t n = write(fd, p, len);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        len -= (size_t)n;
    }
    return true;
}

pl_status output_film_send(int fd, const film *f, const output_film_counts *c, pl_diag *diag)
{
    unsigned char head[FILM_HEADER_BYTES], buf[OUTPUT_FILM_PIXEL_BYTES * 64];
    memcpy(head, film_magic, 8);
    put_le(head + 8, (film_sum)(uint32_t)f->width, 4);
    put_le(head + 12, (film_sum)(uint32_t)f->height, 4);
    uint64_t counts[4] = {c->rays, c->node_visits, c->prim_tests, c->samples};
    for (int i = 0; i < 4; i++) put_le(head + 16 + 8 * i, counts[i], 8);
    bool ok = write_all(fd, head, sizeof head);
    long pixels = (long)f->width * f->height;
    for (long i = 0; ok && i < pixels; i += 64) {
        long batch = pixels - i < 64 ? pixels - i : 64;
        for (long k = 0; k < batch; k++) pixel_bytes(&f->pixels[i + k], buf + OUTPUT_FILM_PIXEL_BYTES * k);
        ok = write_all(fd, buf, (size_t)(OUTPUT_FILM_PIXEL_BYTES * batch));
    }
    ok = ok && write_all(fd, (const unsigned char *)film_end, 8);
    return ok ? PL_OK : pl_fail(diag, PL_ERR_IO, "--film-fd %d: cannot send the film: %s", fd, strerror(errno));
}

/* The grader's side: every length and the end marker checked before a byte is believed; the
 * counts come back as sent (they are the candidate's word: grading/README.md says what bounds them).
 * A refusal says what was wrong and what the case expects in the grader's words, never a number
 * from the stream: the render is student code, and a header's two sizes echoed back would carry
 * 8 bytes of whatever it read (a hidden scene, its own memory) out to the student. */
pl_status output_film_receive(const void *data, size_t len, int width, int height, film *out,
                              output_film_counts *c, pl_diag *diag)
{
    const unsigned char *p = data;
    size_t pixels = (size_t)width * (size_t)height, expected = FILM_HEADER_BYTES + pixels * OUTPUT_FILM_PIXEL_BYTES + 8;
    if (len < FILM_HEADER_BYTES || memcmp(p, film_magic, 8))
        return pl_fail(diag, PL_ERR_PARSE, "the render sent no film (what it sent is not a film stream)");
    int w = (int)(uint32_t)get_le(p + 8, 4), h = (int)(uint32_t)get_le(p + 12, 4);
    if (w != width || h != height)
        return pl_fail(diag, PL_ERR_PARSE, "the film's size is not the case's: the case renders %dx%d", width, height);
    if (len != expected || memcmp(p + len - 8, film_end, 8))
        return pl_fail(diag, PL_ERR_PARSE, "the film stream is not the length of a %dx%d film (%zu bytes) or does "
                       "not end with the film's end marker", width, height, expected);
    uint64_t *counts[4] = {&c->rays, &c->node_visits, &c->prim_tests, &c->samples};
    for (int i = 0; i < 4; i++) *counts[i] = (uint64_t)get_le(p + 16 + 8 * i, 8);
    if (film_alloc(out, width, height) != PL_OK)
        return pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d film", width, height);
    for (size_t i = 0; i < pixels; i++) {
        const unsigned char *q = p + FILM_HEADER_BYTES + i * OUTPUT_FILM_PIXEL_BYTES;
        film_pixel *px = &out->pixels[i];
        for (int k = 0; k < 4; k++) px->sum[k] = get_le(q + 16 * k, 16), px->sum_sq[k] = get_le(q + 64 + 16 * k, 16);
        px->n = (uint32_t)get_le(q + 128, 4);
        px->bad = (uint32_t)get_le(q + 132, 4);
    }
    return PL_OK;
}
