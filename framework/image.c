/* Float images and their files (stb_image_write for PNG and Radiance HDR, stb_image to read).
 * Every writer encodes to memory, then file_write_atomic puts the bytes in place all at once. */
#include "image.h"
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include <stb_image.h>
#include "../third_party/lodepng/lodepng.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <zlib.h>

/* stb_image_write's own deflate is most of a render's write time (~80 ms for an 800x600 PNG);
 * zlib at level 1 gives files a little larger in a fraction of it. stb takes a zlib-style
 * compressor through STBIW_ZLIB_COMPRESS, so its PNG writer is compiled here, static to this file,
 * with zlib plugged in. */
static unsigned char *zlib_compress(unsigned char *data, int data_len, int *out_len, int quality)
{
    (void)quality;
    uLongf size = compressBound((uLong)data_len);
    unsigned char *out = malloc(size);
    if (!out || compress2(out, &size, data, (uLong)data_len, 1) != Z_OK) {
        free(out);
        return NULL;
    }
    *out_len = (int)size;
    return out;
}
#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#pragma GCC diagnostic pop

/* ---- memory and the tone curve ------------------------------------------------------------------ */

pl_status image_alloc(image *img, int width, int height)
{
    img->width = width;
    img->height = height;
    img->pixels = calloc((size_t)width * (size_t)height, sizeof(rgb));
    return img->pixels ? PL_OK : PL_ERR_NOMEM;
}

void image_free(image *img)
{
    if (!img) return;
    free(img->pixels);
    img->pixels = NULL;
    img->width = img->height = 0;
}

uint8_t tonemap_channel(float v)
{
    /* CS184's curve: (v * sqrt(2))^(1/2.2), clamped; NaN maps to 0. */
    float t = powf(fmaxf(v, 0.0f) * 1.41421356f, 1.0f / 2.2f);
    if (!(t > 0.0f)) return 0;
    if (t >= 1.0f) return 255;
    return (uint8_t)(t * 255.0f + 0.5f);
}

/* stb_image_write streams encoded bytes through this callback straight into the output file. */
typedef struct { FILE *f; bool failed; } file_sink;

static void sink_write(void *context, void *data, int size)
{
    file_sink *s = context;
    if (!s->failed && fwrite(data, 1, (size_t)size, s->f) != (size_t)size) s->failed = true;
}

pl_status image_encode_png_rgb8(FILE *f, const uint8_t *rgb8, int width, int height, pl_diag *diag)
{
    /* stb tries all five PNG filters on every row to pick one: most of its time. "Up" alone gives
     * files within a few percent on renders, both smooth and noisy. (stb keeps the choice in a
     * variable of its own, static to this file; every call sets the same value.) */
    stbi_write_force_png_filter = 2;
    file_sink s = {f, false};
    int ok = stbi_write_png_to_func(sink_write, &s, width, height, 3, rgb8, width * 3);
    if (!ok || s.failed) return pl_fail(diag, PL_ERR_IO, "could not encode or write a %dx%d PNG", width, height);
    return PL_OK;
}

/* Path-based writers: one file through a temporary and a rename. */
typedef pl_status (*encoder)(FILE *f, const void *user, pl_diag *diag);

static pl_status write_one(const char *path, encoder encode, const void *user, pl_diag *diag)
{
    file_temp t;
    pl_status st = file_temp_create(path, &t, diag);
    if (st) return st;
    if ((st = encode(t.f, user, diag))) {
        char why[PL_DIAG_MSG_MAX];
        snprintf(why, sizeof why, "%s", diag ? diag->error : "");
        file_temp_discard(&t);
        return pl_fail(diag, st, "%s: %s", path, why);
    }
    return file_temp_commit(&t, diag);
}

typedef struct { const uint8_t *rgb8; int width, height; } rgb8_image;

static pl_status encode_rgb8(FILE *f, const void *user, pl_diag *diag)
{
    const rgb8_image *im = user;
    return image_encode_png_rgb8(f, im->rgb8, im->width, im->height, diag);
}

pl_status image_write_png_rgb8(const uint8_t *rgb8, int width, int height, const char *path, pl_diag *diag)
{
    rgb8_image im = {rgb8, width, height};
    return write_one(path, encode_rgb8, &im, diag);
}

/* The tone curve as 255 thresholds: threshold[k - 1] is the smallest float that tonemap_channel
 * maps to k or more (found by bisecting float bit patterns, which order like the floats they encode
 * when non-negative). Eight comparisons then replace a powf per channel, with the same result:
 * the curve is monotonic. Computed once. */
static float tone_threshold[255];
static uint8_t tone_bucket[0x7f81];  /* the value at the smallest float with these top 16 bits */
static pthread_once_t tone_once = PTHREAD_ONCE_INIT;

static uint8_t tonemap_search(float v)
{
    int k = 0;  /* the number of thresholds <= v */
    for (int step = 128; step > 0; step /= 2)
        if (k + step <= 255 && tone_threshold[k + step - 1] <= v) k += step;
    return (uint8_t)k;
}

static void tone_thresholds_init(void)
{
    for (int k = 1; k <= 255; k++) {
        uint32_t lo = 0, hi = 0x7f800000u;  /* +0 .. +inf */
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            float v;
            memcpy(&v, &mid, sizeof v);
            if (tonemap_channel(v) >= k) hi = mid;
            else lo = mid + 1;
        }
        memcpy(&tone_threshold[k - 1], &lo, sizeof lo);
    }
    for (uint32_t top = 0; top <= 0x7f80; top++) {
        uint32_t bits = top << 16;
        float v;
        memcpy(&v, &bits, sizeof v);
        tone_bucket[top] = tonemap_search(v);
    }
}

/* A float's top 16 bits pick its bucket; thresholds are more than a bucket apart (1.0086 against
 * 1 + 1/128 relative), so at most a step or two finishes the count. */
static uint8_t tonemap_fast(float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    if (bits >> 31 || bits > 0x7f800000u) return 0;  /* negative (and -0) or NaN */
    int k = tone_bucket[bits >> 16];
    while (k < 255 && tone_threshold[k] <= v) k++;
    return (uint8_t)k;
}

pl_status image_encode_png(FILE *f, const void *img_, pl_diag *diag)
{
    const image *img = img_;
    size_t n = (size_t)img->width * (size_t)img->height;
    uint8_t *bytes = malloc(n * 3);
    if (!bytes) return pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d PNG", img->width, img->height);
    pthread_once(&tone_once, tone_thresholds_init);
    for (size_t i = 0; i < n; i++) {
        bytes[3 * i + 0] = tonemap_fast(img->pixels[i].r);
        bytes[3 * i + 1] = tonemap_fast(img->pixels[i].g);
        bytes[3 * i + 2] = tonemap_fast(img->pixels[i].b);
    }
    pl_status s = image_encode_png_rgb8(f, bytes, img->width, img->height, diag);
    free(bytes);
    return s;
}

pl_status image_encode_hdr(FILE *f, const void *img_, pl_diag *diag)
{
    const image *img = img_;
    file_sink s = {f, false};
    /* rgb is three packed floats, exactly the layout stbi_write_hdr expects. */
    int ok = stbi_write_hdr_to_func(sink_write, &s, img->width, img->height, 3, (const float *)img->pixels);
    if (!ok || s.failed) return pl_fail(diag, PL_ERR_IO, "could not encode or write a %dx%d HDR", img->width, img->height);
    return PL_OK;
}

pl_status image_write_png(const image *img, const char *path, pl_diag *diag)
{
    return write_one(path, image_encode_png, img, diag);
}

pl_status image_write_hdr(const image *img, const char *path, pl_diag *diag)
{
    return write_one(path, image_encode_hdr, img, diag);
}

image_format image_format_of(const char *path)
{
    return file_has_extension(path, ".png")   ? IMAGE_FORMAT_PNG
           : file_has_extension(path, ".hdr") ? IMAGE_FORMAT_HDR
           : file_has_extension(path, ".exr") ? IMAGE_FORMAT_EXR
                                              : IMAGE_FORMAT_NONE;
}

pl_status image_write(const image *img, const char *path, pl_diag *diag)
{
    image_format format = image_format_of(path);
    if (format == IMAGE_FORMAT_PNG) return image_write_png(img, path, diag);
    if (format == IMAGE_FORMAT_HDR) return image_write_hdr(img, path, diag);
    return pl_fail(diag, PL_ERR_INVALID, "%s: expected an output name ending in .png or .hdr", path);
}

/* ---- reading back (tests, tools, the grader's previews) -------------------------------------------- */

pl_status image_read(const char *path, image *out, pl_diag *diag)
{
    int w, h, channels;
    memset(out, 0, sizeof *out);
    if (image_format_of(path) == IMAGE_FORMAT_HDR) {
        float *data = stbi_loadf(path, &w, &h, &channels, 3);
        if (!data) return pl_fail(diag, PL_ERR_IO, "%s: cannot read image: %s", path, stbi_failure_reason());
        pl_status s = image_alloc(out, w, h);
        if (s == PL_OK) memcpy(out->pixels, data, (size_t)w * h * sizeof(rgb));
        stbi_image_free(data);
        return s == PL_OK ? PL_OK : pl_fail(diag, s, "%s: out of memory", path);
    }
    /* PNG through LodePNG (third_party/lodepng): 8-bit RGB, whatever the file's own format. */
    unsigned char *data = NULL;
    unsigned uw, uh;
    unsigned err = lodepng_decode24_file(&data, &uw, &uh, path);
    if (err) return pl_fail(diag, PL_ERR_IO, "%s: cannot read image: %s", path, lodepng_error_text(err));
    pl_status s = uw > 0 && uh > 0 && uw <= 1u << 15 && uh <= 1u << 15 ? image_alloc(out, (int)uw, (int)uh) : PL_ERR_INVALID;
    if (s == PL_OK)
        for (size_t i = 0; i < (size_t)uw * uh; i++)
            out->pixels[i] = rgb_make(data[3 * i] / 255.0f, data[3 * i + 1] / 255.0f, data[3 * i + 2] / 255.0f);
    free(data);
    return s == PL_OK ? PL_OK : pl_fail(diag, s, "%s: %s", path, s == PL_ERR_NOMEM ? "out of memory" : "image too large");
}
