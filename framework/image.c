/* Float images and their files (stb_image_write for PNG and Radiance HDR, stb_image to read).
 * Every writer encodes to memory, then file_write_atomic puts the bytes in place all at once. */
#include "image.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include <stb_image.h>
#include <stb_image_write.h>

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

/* stb_image_write streams encoded bytes through this callback into a growing buffer. */
typedef struct { unsigned char *data; size_t len, cap; bool failed; } byte_buffer;

static void buffer_append(void *context, void *data, int size)
{
    byte_buffer *b = context;
    if (b->failed) return;
    if (b->len + (size_t)size > b->cap) {
        size_t cap = b->cap ? b->cap * 2 : 65536;
        while (cap < b->len + (size_t)size) cap *= 2;
        unsigned char *grown = realloc(b->data, cap);
        if (!grown) {
            b->failed = true;
            return;
        }
        b->data = grown;
        b->cap = cap;
    }
    memcpy(b->data + b->len, data, (size_t)size);
    b->len += (size_t)size;
}

static pl_status buffer_commit(byte_buffer *b, int encoded, const char *path, pl_diag *diag)
{
    pl_status s;
    if (!encoded || b->failed)
        s = pl_fail(diag, PL_ERR_NOMEM, "%s: could not encode the image", path);
    else
        s = file_write_atomic(path, b->data, b->len, diag);
    free(b->data);
    return s;
}

pl_status image_write_png_rgb8(const uint8_t *rgb8, int width, int height, const char *path, pl_diag *diag)
{
    byte_buffer b = {0};
    int ok = stbi_write_png_to_func(buffer_append, &b, width, height, 3, rgb8, width * 3);
    return buffer_commit(&b, ok, path, diag);
}

pl_status image_write_png(const image *img, const char *path, pl_diag *diag)
{
    size_t n = (size_t)img->width * (size_t)img->height;
    uint8_t *bytes = malloc(n * 3);
    if (!bytes) return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) {
        bytes[3 * i + 0] = tonemap_channel(img->pixels[i].r);
        bytes[3 * i + 1] = tonemap_channel(img->pixels[i].g);
        bytes[3 * i + 2] = tonemap_channel(img->pixels[i].b);
    }
    pl_status s = image_write_png_rgb8(bytes, img->width, img->height, path, diag);
    free(bytes);
    return s;
}

pl_status image_write_hdr(const image *img, const char *path, pl_diag *diag)
{
    byte_buffer b = {0};
    /* rgb is three packed floats, exactly the layout stbi_write_hdr expects. */
    int ok = stbi_write_hdr_to_func(buffer_append, &b, img->width, img->height, 3, (const float *)img->pixels);
    return buffer_commit(&b, ok, path, diag);
}

static bool has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n > e && strcasecmp(path + n - e, ext) == 0;
}

pl_status image_write(const image *img, const char *path, pl_diag *diag)
{
    if (has_extension(path, ".png")) return image_write_png(img, path, diag);
    if (has_extension(path, ".hdr")) return image_write_hdr(img, path, diag);
    return pl_fail(diag, PL_ERR_INVALID, "%s: expected an output name ending in .png or .hdr", path);
}

pl_status image_read(const char *path, image *out, pl_diag *diag)
{
    int w, h, channels;
    memset(out, 0, sizeof *out);
    if (has_extension(path, ".hdr")) {
        float *data = stbi_loadf(path, &w, &h, &channels, 3);
        if (!data) return pl_fail(diag, PL_ERR_IO, "%s: cannot read image: %s", path, stbi_failure_reason());
        pl_status s = image_alloc(out, w, h);
        if (s == PL_OK) memcpy(out->pixels, data, (size_t)w * h * sizeof(rgb));
        stbi_image_free(data);
        return s == PL_OK ? PL_OK : pl_fail(diag, s, "%s: out of memory", path);
    }
    unsigned char *data = stbi_load(path, &w, &h, &channels, 3);
    if (!data) return pl_fail(diag, PL_ERR_IO, "%s: cannot read image: %s", path, stbi_failure_reason());
    pl_status s = image_alloc(out, w, h);
    if (s == PL_OK)
        for (size_t i = 0; i < (size_t)w * h; i++)
            out->pixels[i] = rgb_make(data[3 * i] / 255.0f, data[3 * i + 1] / 255.0f, data[3 * i + 2] / 255.0f);
    stbi_image_free(data);
    return s == PL_OK ? PL_OK : pl_fail(diag, s, "%s: out of memory", path);
}
