/* OpenEXR files of a film (exr.h), through OpenEXR's C API.
 *
 * A film is kept whole, not just its image: beside the means (R, G, B, readable by any EXR viewer)
 * and their variances, every pixel's exact accumulators go in as 32-bit words (the 128-bit fixed-
 * point sums and sums of squares, the sample and bad-sample counts). That is what lets --merge add
 * sample ranges exactly (range.c) and the grader compute its statistics from the reference's own
 * sums. The reader accepts only what the writer makes (one layout, these channels, these
 * attributes), because references are read by the grader and may be damaged or forged. */
#include "exr.h"
#include "exr_io.h"
#include "utf8.h"
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the channels ---------------------------------------------------------------------------- */

/* What a channel holds: a float (the mean or the variance of the mean) or a word of an integer. */
typedef enum { CH_MEAN, CH_VAR, CH_N, CH_BAD, CH_SUM, CH_SQ } channel_kind;

typedef struct {
    char name[32];
    channel_kind kind;
    int c;     /* film channel: 0..2 rgb, 3 luminance */
    int word;  /* CH_SUM, CH_SQ: which 32-bit word of the 128-bit sum, 0 = least significant */
} channel;

/* R G B; var.R var.G var.B var.Y; n, bad; acc.sum and acc.sq of R G B Y, four words each. */
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

/* The channel of that name, or NULL (a name the file has and the table does not). */
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

/* The provenance as five string attributes (range.c says what each is for); numbers as decimal
 * text, which the reader parses back strictly. */
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
        /* Every channel is 4 bytes a pixel, float or uint: one plane of rows for this chunk each. */
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

/* The output set's encoder (output.h): writes the film through file's descriptor, one scanline
 * chunk at a time (the buffer holds one chunk of every channel, not the whole image). */
pl_status exr_encode(FILE *file, const void *user, pl_diag *diag)
{
    const exr_image *img = user;
    const film *f = img->film;
    int fd;
    channel table[NUM_CHANNELS];
    channel_table(table);
    exr_context_t x = NULL;
    int part = 0;
    exr_result_t r = exrio_start_write(file, &fd, "film.exr", &x);
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
    return r == EXR_ERR_SUCCESS ? PL_OK : exrio_fail(diag, "writing EXR", r);
}

/* ---- reading: only what exr_encode writes ---------------------------------------------------- */

/* Attribute values and channel names come from the file: shown in a message only as printable ASCII. */
static const char *printable(const char *s, char *out, size_t size)
{
    size_t i = 0;
    for (; s && s[i] && i + 1 < size; i++) out[i] = s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?';
    out[i] = '\0';
    return out;
}

/* A decimal number of at most max, as the writer prints it: digits only (no sign, space or leading
 * zero). Returns the text after it, or NULL. */
static const char *parse_decimal(const char *s, uint64_t max, uint64_t *out)
{
    if (*s < '0' || *s > '9' || (s[0] == '0' && s[1] >= '0' && s[1] <= '9')) return NULL;
    uint64_t v = 0;
    for (; *s >= '0' && *s <= '9'; s++) {
        uint64_t digit = (uint64_t)(*s - '0');
        if (digit > max || v > (max - digit) / 10) return NULL;
        v = v * 10 + digit;
    }
    *out = v;
    return s;
}

/* "A:B of N" with 0 <= A < B <= N <= EXR_MAX_SAMPLES. */
static bool parse_samples(const char *s, exr_info *info)
{
    uint64_t a, b, n;
    if (!(s = parse_decimal(s, EXR_MAX_SAMPLES, &a)) || *s++ != ':' || !(s = parse_decimal(s, EXR_MAX_SAMPLES, &b)) ||
        strncmp(s, " of ", 4) || !(s = parse_decimal(s + 4, EXR_MAX_SAMPLES, &n)) || *s || a >= b || b > n)
        return false;
    info->sample_begin = (int)a, info->sample_end = (int)b, info->sample_total = (int)n;
    return true;
}

/* One string attribute: present, a string, shorter than size, valid UTF-8 with no control byte. */
static pl_status read_attribute(exr_context_t x, const char *path, const char *name, char *out, size_t size, pl_diag *diag)
{
    int32_t len = 0;
    const char *s = NULL;
    if (exr_attr_get_string(x, 0, name, &len, &s) != EXR_ERR_SUCCESS || !s || len < 0)
        return pl_fail(diag, PL_ERR_PARSE, "%s: %s: expected this string attribute in the header (not a pathlab film?)",
                       path, name);
    if ((size_t)len >= size) return pl_fail(diag, PL_ERR_PARSE, "%s: %s: %d bytes, expected under %zu", path, name, len, size);
    bool control = false;
    for (int32_t i = 0; i < len; i++) control = control || (unsigned char)s[i] < 0x20 || s[i] == 0x7f;
    if (control || utf8_valid_prefix(s, (size_t)len) != (size_t)len)
        return pl_fail(diag, PL_ERR_PARSE, "%s: %s: expected UTF-8 text without control characters", path, name);
    memcpy(out, s, (size_t)len);
    out[len] = '\0';
    return PL_OK;
}

/* The five pathlab.* attributes, each parsed to the form the writer gives it. */
static pl_status read_info(exr_context_t x, const char *path, exr_info *info, pl_diag *diag)
{
    char seed[32], samples[64], shown[48];
    memset(info, 0, sizeof *info);
    pl_status s = read_attribute(x, path, "pathlab.command", info->command, sizeof info->command, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.version", info->version, sizeof info->version, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.render_key", info->render_key, sizeof info->render_key, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.seed", seed, sizeof seed, diag);
    if (s == PL_OK) s = read_attribute(x, path, "pathlab.samples", samples, sizeof samples, diag);
    if (s != PL_OK) return s;
    const char *end = parse_decimal(seed, UINT64_MAX, &info->seed);
    if (!end || *end)
        return pl_fail(diag, PL_ERR_PARSE, "%s: pathlab.seed '%s': expected a decimal number from 0 to %" PRIu64, path,
                       printable(seed, shown, sizeof shown), UINT64_MAX);
    if (!parse_samples(samples, info))
        return pl_fail(diag, PL_ERR_PARSE, "%s: pathlab.samples '%s': expected 'A:B of N' with 0 <= A < B <= N <= %d",
                       path, printable(samples, shown, sizeof shown), EXR_MAX_SAMPLES);
    if (strlen(info->render_key) != 16 || strspn(info->render_key, "0123456789abcdef") != 16)
        return pl_fail(diag, PL_ERR_PARSE, "%s: pathlab.render_key '%s': expected 16 lowercase hex digits", path,
                       printable(info->render_key, shown, sizeof shown));
    if (strncmp(info->command, "pathtracer ", 11) || !info->version[0])
        return pl_fail(diag, PL_ERR_PARSE, "%s: pathlab.command / pathlab.version: expected 'pathtracer ...' and a "
                       "version", path);
    return PL_OK;
}

/* The channel list: exactly the channels of channel_table, each with its type and no subsampling
 * (a subsampled channel decodes fewer values than the film has pixels). */
static pl_status check_channels(exr_context_t x, const char *path, const channel *table, pl_diag *diag)
{
    const exr_attr_chlist_t *chl = NULL;
    char shown[40];
    if (exr_get_channels(x, 0, &chl) != EXR_ERR_SUCCESS || !chl || chl->num_channels != NUM_CHANNELS)
        return pl_fail(diag, PL_ERR_PARSE, "%s: channels: expected the %d channels pathlab writes, found %d", path,
                       NUM_CHANNELS, chl ? chl->num_channels : 0);
    bool seen[NUM_CHANNELS] = {false};
    for (int i = 0; i < chl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &chl->entries[i];
        const channel *ch = e->name.str ? channel_find(table, e->name.str) : NULL;
        if (!ch || seen[ch - table])
            return pl_fail(diag, PL_ERR_PARSE, "%s: channel '%s': not one pathlab writes, or listed twice", path,
                           printable(e->name.str, shown, sizeof shown));
        seen[ch - table] = true;
        bool is_float = channel_is_float(ch);
        if (e->pixel_type != (is_float ? EXR_PIXEL_FLOAT : EXR_PIXEL_UINT))
            return pl_fail(diag, PL_ERR_PARSE, "%s: channel %s: expected type %s", path, ch->name, is_float ? "float" : "uint");
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return pl_fail(diag, PL_ERR_PARSE, "%s: channel %s: sampling %dx%d, expected 1x1", path, ch->name,
                           e->x_sampling, e->y_sampling);
    }
    return PL_OK;
}

/* The layout: one scanline part, ZIP, a data window from (0, 0) equal to the display window, within
 * the size cap; checked from the header, before anything is allocated for the pixels. */
static pl_status check_layout(exr_context_t x, const char *path, int *width, int *height, pl_diag *diag)
{
    int parts = 0;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_compression_t compression = EXR_COMPRESSION_LAST_TYPE;
    exr_attr_box2i_t data, display;
    if (exr_get_count(x, &parts) != EXR_ERR_SUCCESS || parts != 1 || exr_get_storage(x, 0, &storage) != EXR_ERR_SUCCESS ||
        storage != EXR_STORAGE_SCANLINE)
        return pl_fail(diag, PL_ERR_PARSE, "%s: expected a single-part scanline image (what pathlab writes)", path);
    if (exr_get_compression(x, 0, &compression) != EXR_ERR_SUCCESS || compression != EXR_COMPRESSION_ZIP)
        return pl_fail(diag, PL_ERR_PARSE, "%s: compression: expected ZIP, the one pathlab writes", path);
    if (exr_get_data_window(x, 0, &data) != EXR_ERR_SUCCESS || exr_get_display_window(x, 0, &display) != EXR_ERR_SUCCESS ||
        data.min.x != 0 || data.min.y != 0 || memcmp(&data, &display, sizeof data))
        return pl_fail(diag, PL_ERR_PARSE, "%s: dataWindow: expected it to start at (0, 0) and equal the displayWindow", path);
    int64_t w = (int64_t)data.max.x + 1, h = (int64_t)data.max.y + 1;
    if (w < 1 || h < 1 || w > EXR_MAX_SIDE || h > EXR_MAX_SIDE || w * h > EXR_MAX_PIXELS)
        return pl_fail(diag, PL_ERR_PARSE, "%s: dataWindow: %" PRId64 "x%" PRId64 " pixels, expected at most %d a side "
                       "and %ld in all (a film holds %zu bytes a pixel)", path, w, h, EXR_MAX_SIDE, EXR_MAX_PIXELS,
                       sizeof(film_pixel));
    *width = (int)w, *height = (int)h;
    return PL_OK;
}

/* Opens path and checks everything but the pixels; *x is then open (exr_finish it) even on failure. */
static pl_status open_checked(const char *path, exr_context_t *x, exr_info *info, int *width, int *height,
                              pl_diag *diag)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = exrio_quiet_errors;
    *x = NULL;
    exr_result_t r = exr_start_read(x, path, &init);
    if (r != EXR_ERR_SUCCESS)
        return pl_fail(diag, PL_ERR_IO, "%s: cannot read as OpenEXR: %s", path, exr_get_default_error_message(r));
    channel table[NUM_CHANNELS];
    channel_table(table);
    pl_status s = check_layout(*x, path, width, height, diag);
    if (s == PL_OK) s = check_channels(*x, path, table, diag);
    if (s == PL_OK) s = read_info(*x, path, info, diag);
    return s;
}

/* The provenance and size only, without decoding a pixel (--merge reads every header first). */
pl_status exr_read_info(const char *path, exr_info *info, int *width, int *height, pl_diag *diag)
{
    exr_context_t x = NULL;
    pl_status s = open_checked(path, &x, info, width, height, diag);
    if (x) exr_finish(&x);
    return s;
}

/* Decodes the chunk starting at row y0 into the film's accumulators, after checking that the chunk
 * is the one expected there and decodes to exactly its rows (the decoded-bytes budget: no chunk
 * may decode to more than its rows of the 41 channels, nor hold more packed than unpacked). */
static pl_status read_chunk(exr_context_t x, const char *path, film *f, const channel *table, int y0, int lines,
                            uint32_t *buf, pl_diag *diag)
{
    exr_chunk_info_t cinfo;
    int rows = f->height - y0 < lines ? f->height - y0 : lines;
    uint64_t expected = (uint64_t)rows * (uint64_t)f->width * NUM_CHANNELS * 4;
    exr_result_t r = exr_read_scanline_chunk_info(x, 0, y0, &cinfo);
    if (r != EXR_ERR_SUCCESS) return pl_fail(diag, PL_ERR_PARSE, "%s: the chunk at row %d: %s", path, y0, exr_get_default_error_message(r));
    if (cinfo.start_y != y0 || cinfo.height != rows || cinfo.width != f->width || cinfo.unpacked_size != expected ||
        cinfo.packed_size == 0 || cinfo.packed_size > expected)
        return pl_fail(diag, PL_ERR_PARSE, "%s: the chunk at row %d: expected %d rows of %" PRIu64 " bytes at most, "
                       "found rows %d.. (%d), %" PRIu64 " bytes packed", path, y0, rows, expected, cinfo.start_y,
                       cinfo.height, cinfo.packed_size);
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    if ((r = exr_decoding_initialize(x, 0, &cinfo, &dec)) == EXR_ERR_SUCCESS) {
        size_t plane = (size_t)rows * (size_t)f->width;
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
            const channel *ch = channel_find(table, dec.channels[i].channel_name);  /* check_channels found each */
            if (!ch || channel_is_float(ch)) continue;
            for (size_t k = 0; k < plane; k++) channel_store(&f->pixels[(size_t)y0 * f->width + k], ch, buf[(size_t)i * plane + k]);
        }
    }
    exr_decoding_destroy(x, &dec);
    return r == EXR_ERR_SUCCESS ? PL_OK : pl_fail(diag, PL_ERR_PARSE, "%s: the chunk at row %d: %s", path, y0,
                                                  exr_get_default_error_message(r));
}

/* An adaptive render takes a different number of samples per pixel: its samples cannot be split. */
bool exr_info_adaptive(const exr_info *info) { return strstr(info->command, " -a ") != NULL; }

/* Decodes every chunk of an open, checked file into out (allocated here). */
static pl_status read_pixels(exr_context_t x, const char *path, film *out, int width, int height, pl_diag *diag)
{
    int32_t lines = 0;
    if (exr_get_scanlines_per_chunk(x, 0, &lines) != EXR_ERR_SUCCESS || lines < 1 || lines > 256)
        return pl_fail(diag, PL_ERR_PARSE, "%s: expected scanline chunks of 1 to 256 rows", path);
    if (film_alloc(out, width, height) != PL_OK)
        return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory for a %dx%d film", path, width, height);
    /* Zeroed: whatever a decoder leaves unwritten reads as 0, never as old heap contents. */
    uint32_t *buf = calloc((size_t)NUM_CHANNELS * (size_t)lines * (size_t)width, sizeof *buf);
    channel table[NUM_CHANNELS];
    channel_table(table);
    pl_status s = buf ? PL_OK : pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    for (int y = 0; s == PL_OK && y < height; y += lines) s = read_chunk(x, path, out, table, y, lines, buf, diag);
    free(buf);
    return s;
}

pl_status exr_read(const char *path, film *out, exr_info *info, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    exr_context_t x = NULL;
    int width = 0, height = 0;
    pl_status s = open_checked(path, &x, info, &width, &height, diag);
    if (s == PL_OK) s = read_pixels(x, path, out, width, height, diag);
    if (x) exr_finish(&x);
    /* Every pixel must be one a render of this range could give: a fixed-rate render takes B - A
     * samples in each pixel; an adaptive one (0:N only) from 1 to N. */
    bool adaptive = exr_info_adaptive(info);
    uint32_t range = s == PL_OK ? (uint32_t)(info->sample_end - info->sample_begin) : 0;
    if (s == PL_OK && adaptive && info->sample_begin != 0)
        s = pl_fail(diag, PL_ERR_PARSE, "%s: pathlab.samples: an adaptive render (-a) covers 0:N, not %d:%d", path,
                    info->sample_begin, info->sample_end);
    if (s == PL_OK) s = film_check(out, adaptive ? 1 : range, range, path, diag);
    if (s != PL_OK) film_free(out);
    return s;
}
