/* OpenEXR files of a film (exr.h), through OpenEXR's C API. */
#include "exr.h"
#include <openexr.h>
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- the channels ---------------------------------------------------------------------------- */

typedef enum { CH_MEAN, CH_VAR, CH_N, CH_BAD, CH_SUM, CH_SQ } channel_kind;

typedef struct {
    char name[32];
    channel_kind kind;
    int c;     /* film channel: 0..2 rgb, 3 luminance */
    int word;  /* CH_SUM, CH_SQ: which 32-bit word of the 128-bit sum, 0 = least significant */
} channel;

#define NUM_CHANNELS (3 + 4 + 2 + 2 * 4 * 4)
static const char channel_letter[4] = {'R', 'G', 'B', 'Y'};

/* Fills the table of every channel; the order does not matter (channels are found by name). */
static void channel_table(channel *t)
{
    int k = 0;
    for (int c = 0; c < 3; c++) t[k++] = (channel){{channel_letter[c], 0}, CH_MEAN, c, 0};
    for (int c = 0; c < 4; c++) {
        t[k] = (channel){"", CH_VAR, c, 0};
        snprintf(t[k++].name, sizeof t->name, "var.%c", channel_letter[c]);
    }
    t[k++] = (channel){"n", CH_N, 0, 0};
    t[k++] = (channel){"bad", CH_BAD, 0, 0};
    for (int sq = 0; sq < 2; sq++)
        for (int c = 0; c < 4; c++)
            for (int w = 0; w < 4; w++) {
                t[k] = (channel){"", sq ? CH_SQ : CH_SUM, c, w};
                snprintf(t[k++].name, sizeof t->name, "acc.%s.%c.%d", sq ? "sq" : "sum", channel_letter[c], w);
            }
}

static const channel *channel_find(const channel *t, const char *name)
{
    for (int k = 0; k < NUM_CHANNELS; k++)
        if (!strcmp(t[k].name, name)) return &t[k];
    return NULL;
}

static bool channel_is_float(const channel *ch) { return ch->kind == CH_MEAN || ch->kind == CH_VAR; }

/* The 32 bits channel ch stores for pixel p. */
static uint32_t channel_bits(const film_pixel *p, const channel *ch)
{
    float v;
    switch (ch->kind) {
    case CH_MEAN: v = (float)film_pixel_mean(p, ch->c); break;
    case CH_VAR: v = (float)film_pixel_variance_of_mean(p, ch->c); break;
    case CH_N: return p->n;
    case CH_BAD: return p->bad;
    case CH_SUM: return (uint32_t)(p->sum[ch->c] >> (32 * ch->word));
    default: return (uint32_t)(p->sum_sq[ch->c] >> (32 * ch->word));
    }
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    return bits;
}

/* Puts the 32 bits of an accumulator channel back into pixel p (the means and variances are
 * recomputed from the sums, never read back). */
static void channel_store(film_pixel *p, const channel *ch, uint32_t bits)
{
    film_sum word = (film_sum)bits << (32 * ch->word);
    if (ch->kind == CH_N) p->n = bits;
    else if (ch->kind == CH_BAD) p->bad = bits;
    else if (ch->kind == CH_SUM) p->sum[ch->c] |= word;
    else if (ch->kind == CH_SQ) p->sum_sq[ch->c] |= word;
}

/* ---- writing --------------------------------------------------------------------------------- */

/* OpenEXR's write callback: the stream is the FILE's descriptor, written at explicit offsets. */
static int64_t write_at(exr_const_context_t ctxt, void *user, const void *buf, uint64_t size, uint64_t offset,
                        exr_stream_error_func_ptr_t error_cb)
{
    int fd = *(const int *)user;
    const char *p = buf;
    uint64_t done = 0;
    while (done < size) {
        ssize_t n = pwrite(fd, p + done, size - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_cb(ctxt, EXR_ERR_WRITE_IO, "pwrite: %s", strerror(errno));
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static void quiet_errors(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt, (void)code, (void)msg;  /* reported through the result codes instead */
}

static pl_status exr_fail(pl_diag *diag, const char *what, exr_result_t r)
{
    return pl_fail(diag, PL_ERR_IO, "%s: OpenEXR: %s", what, exr_get_default_error_message(r));
}

static exr_result_t set_attributes(exr_context_t x, const exr_info *info)
{
    char seed[32], samples[64];
    snprintf(seed, sizeof seed, "%" PRIu64, info->seed);
    snprintf(samples, sizeof samples, "%d:%d of %d", info->sample_begin, info->sample_end, info->sample_total);
    exr_result_t r = exr_attr_set_string(x, 0, "pathlab.command", info->command);
    if (r == EXR_ERR_SUCCESS) r = exr_attr_set_string(x, 0, "pathlab.seed", seed);
    if (r == EXR_ERR_SUCCESS) r = exr_attr_set_string(x, 0, "pathlab.version", info->version);
    if (r == EXR_ERR_SUCCESS) r = exr_attr_set_string(x, 0, "pathlab.samples", samples);
    if (r == EXR_ERR_SUCCESS) r = exr_attr_set_string(x, 0, "pathlab.render_key", info->render_key);
    return r;
}

/* Encodes the scanline chunk starting at image row y0 (lines rows) from the film. */
static exr_result_t write_chunk(exr_context_t x, const film *f, const channel *table, int y0, uint32_t *buf)
{
    exr_chunk_info_t cinfo;
    exr_encode_pipeline_t enc;
    exr_result_t r = exr_write_scanline_chunk_info(x, 0, y0, &cinfo);
    if (r != EXR_ERR_SUCCESS) return r;
    r = exr_encoding_initialize(x, 0, &cinfo, &enc);
    if (r != EXR_ERR_SUCCESS) return r;
    size_t plane = (size_t)cinfo.height * (size_t)f->width;
    for (int i = 0; i < enc.channel_count && r == EXR_ERR_SUCCESS; i++) {
        const channel *ch = channel_find(table, enc.channels[i].channel_name);
        uint32_t *dst = buf + (size_t)i * plane;
        for (int row = 0; row < cinfo.height; row++)
            for (int col = 0; col < f->width; col++)
                dst[(size_t)row * f->width + col] = channel_bits(&f->pixels[(size_t)(y0 + row) * f->width + col], ch);
        enc.channels[i].encode_from_ptr = (const uint8_t *)dst;
        enc.channels[i].user_pixel_stride = 4;
        enc.channels[i].user_line_stride = 4 * f->width;
        enc.channels[i].user_bytes_per_element = 4;
        enc.channels[i].user_data_type = enc.channels[i].data_type;
    }
    if (r == EXR_ERR_SUCCESS) r = exr_encoding_choose_default_routines(x, 0, &enc);
    if (r == EXR_ERR_SUCCESS) r = exr_encoding_run(x, 0, &enc);
    exr_encoding_destroy(x, &enc);
    return r;
}

pl_status exr_encode(FILE *file, const void *user, pl_diag *diag)
{
    const exr_image *img = user;
    const film *f = img->film;
    int fd = fileno(file);
    channel table[NUM_CHANNELS];
    channel_table(table);

    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &fd;
    init.write_fn = write_at;
    init.error_handler_fn = quiet_errors;
    exr_context_t x = NULL;
    int part = 0;
    fflush(file);  /* anything buffered in f goes first; OpenEXR writes at offsets from 0 */
    exr_result_t r = exr_start_write(&x, "film.exr", EXR_WRITE_FILE_DIRECTLY, &init);
    if (r == EXR_ERR_SUCCESS) r = exr_add_part(x, "film", EXR_STORAGE_SCANLINE, &part);
    /* ZIP (zlib) is lossless and deterministic: the same film gives the same bytes. */
    if (r == EXR_ERR_SUCCESS) r = exr_initialize_required_attr_simple(x, part, f->width, f->height, EXR_COMPRESSION_ZIP);
    for (int k = 0; k < NUM_CHANNELS && r == EXR_ERR_SUCCESS; k++)
        r = exr_add_channel(x, part, table[k].name, channel_is_float(&table[k]) ? EXR_PIXEL_FLOAT : EXR_PIXEL_UINT,
                            channel_is_float(&table[k]) ? EXR_PERCEPTUALLY_LOGARITHMIC : EXR_PERCEPTUALLY_LINEAR, 1, 1) < 0
                ? EXR_ERR_INVALID_ARGUMENT : EXR_ERR_SUCCESS;
    if (r == EXR_ERR_SUCCESS) r = set_attributes(x, img->info);
    if (r == EXR_ERR_SUCCESS) r = exr_write_header(x);
    int32_t lines = 1;
    if (r == EXR_ERR_SUCCESS) r = exr_get_scanlines_per_chunk(x, part, &lines);
    uint32_t *buf = r == EXR_ERR_SUCCESS ? malloc((size_t)NUM_CHANNELS * lines * f->width * sizeof *buf) : NULL;
    if (r == EXR_ERR_SUCCESS && !buf) r = EXR_ERR_OUT_OF_MEMORY;
    for (int y = 0; y < f->height && r == EXR_ERR_SUCCESS; y += lines) r = write_chunk(x, f, table, y, buf);
    free(buf);
    exr_result_t fin = x ? exr_finish(&x) : EXR_ERR_SUCCESS;
    if (r == EXR_ERR_SUCCESS) r = fin;
    return r == EXR_ERR_SUCCESS ? PL_OK : exr_fail(diag, "writing EXR", r);
}

/* ---- reading --------------------------------------------------------------------------------- */

static pl_status read_attribute(exr_context_t x, const char *path, const char *name, char *out, size_t size, pl_diag *diag)
{
    int32_t len = 0;
    const char *s = NULL;
    if (exr_attr_get_string(x, 0, name, &len, &s) != EXR_ERR_SUCCESS || !s)
        return pl_fail(diag, PL_ERR_PARSE, "%s: expected the header attribute %s (not a pathlab range file?)", path, name);
    if ((size_t)len >= size) return pl_fail(diag, PL_ERR_PARSE, "%s: header attribute %s is too long", path, name);
    memcpy(out, s, (size_t)len);
    out[len] = '\0';
    return PL_OK;
}

static pl_status read_info(exr_context_t x, const char *path, exr_info *info, pl_diag *diag)
{
    char seed[32], samples[64];
    pl_status s = read_attribute(x, path, "pathlab.command", info->command, sizeof info->command, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.version", info->version, sizeof info->version, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.render_key", info->render_key, sizeof info->render_key, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.seed", seed, sizeof seed, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.samples", samples, sizeof samples, diag);
    if (s != PL_OK) return s;
    char end;
    if (sscanf(seed, "%" SCNu64 "%c", &info->seed, &end) != 1 ||
        sscanf(samples, "%d:%d of %d%c", &info->sample_begin, &info->sample_end, &info->sample_total, &end) != 3 ||
        info->sample_begin < 0 || info->sample_begin >= info->sample_end || info->sample_end > info->sample_total)
        return pl_fail(diag, PL_ERR_PARSE, "%s: header attributes pathlab.seed '%s' / pathlab.samples '%s': "
                       "expected a seed and 'A:B of N' with 0 <= A < B <= N", path, seed, samples);
    return PL_OK;
}

static exr_result_t read_chunk(exr_context_t x, film *f, const channel *table, int y0, uint32_t *buf, int *found)
{
    exr_chunk_info_t cinfo;
    exr_decode_pipeline_t dec;
    exr_result_t r = exr_read_scanline_chunk_info(x, 0, y0, &cinfo);
    if (r != EXR_ERR_SUCCESS) return r;
    r = exr_decoding_initialize(x, 0, &cinfo, &dec);
    if (r != EXR_ERR_SUCCESS) return r;
    size_t plane = (size_t)cinfo.height * (size_t)f->width;
    for (int i = 0; i < dec.channel_count; i++) {
        dec.channels[i].decode_to_ptr = (uint8_t *)(buf + (size_t)i * plane);
        dec.channels[i].user_pixel_stride = 4;
        dec.channels[i].user_line_stride = 4 * f->width;
        dec.channels[i].user_bytes_per_element = 4;
        dec.channels[i].user_data_type = dec.channels[i].data_type;
    }
    r = exr_decoding_choose_default_routines(x, 0, &dec);
    if (r == EXR_ERR_SUCCESS) r = exr_decoding_run(x, 0, &dec);
    for (int i = 0; i < dec.channel_count && r == EXR_ERR_SUCCESS; i++) {
        const channel *ch = channel_find(table, dec.channels[i].channel_name);
        if (!ch || channel_is_float(ch) || dec.channels[i].data_type != EXR_PIXEL_UINT) continue;
        (*found)++;
        const uint32_t *src = buf + (size_t)i * plane;
        for (size_t k = 0; k < plane; k++) channel_store(&f->pixels[(size_t)y0 * f->width + k], ch, src[k]);
    }
    exr_decoding_destroy(x, &dec);
    return r;
}

pl_status exr_read(const char *path, film *out, exr_info *info, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    channel table[NUM_CHANNELS];
    channel_table(table);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = quiet_errors;
    exr_context_t x = NULL;
    exr_result_t r = exr_start_read(&x, path, &init);
    if (r != EXR_ERR_SUCCESS) {
        pl_status s = pl_fail(diag, PL_ERR_IO, "%s: cannot read as OpenEXR: %s", path, exr_get_default_error_message(r));
        if (x) exr_finish(&x);
        return s;
    }
    exr_attr_box2i_t win;
    int32_t lines = 1;
    pl_status s = read_info(x, path, info, diag);
    if (s == PL_OK && (exr_get_data_window(x, 0, &win) != EXR_ERR_SUCCESS ||
                       exr_get_scanlines_per_chunk(x, 0, &lines) != EXR_ERR_SUCCESS || win.min.x != 0 || win.min.y != 0))
        s = pl_fail(diag, PL_ERR_PARSE, "%s: expected a scanline image with its data window at (0, 0)", path);
    if (s == PL_OK && film_alloc(out, win.max.x + 1, win.max.y + 1) != PL_OK)
        s = pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory for a %dx%d film", path, win.max.x + 1, win.max.y + 1);
    int channels = 0;
    uint32_t *buf = NULL;
    if (s == PL_OK) {
        const exr_attr_chlist_t *chl = NULL;
        exr_get_channels(x, 0, &chl);
        buf = malloc((size_t)(chl ? chl->num_channels : 1) * lines * out->width * sizeof *buf);
        if (!buf) s = pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    }
    int found = 0;
    for (int y = 0; s == PL_OK && y < out->height; y += lines) {
        int before = found;
        r = read_chunk(x, out, table, y, buf, &found);
        if (r != EXR_ERR_SUCCESS) s = exr_fail(diag, path, r);
        channels = found - before;
    }
    free(buf);
    exr_finish(&x);
    if (s == PL_OK && channels != 2 + 2 * 4 * 4)
        s = pl_fail(diag, PL_ERR_PARSE, "%s: expected the %d accumulator channels n, bad, acc.* (uint), found %d",
                    path, 2 + 2 * 4 * 4, channels);
    if (s != PL_OK) film_free(out);
    return s;
}
