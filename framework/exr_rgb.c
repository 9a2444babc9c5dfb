/* Any RGB image as OpenEXR (exr.h, its second half): environment maps, which come from anywhere
 * (a sky tool, an HDRI library), read in every compression OpenEXR decodes, half or float, and
 * written as R, G, B floats. The film's own files, which only pathlab writes, are exr.c's. */
#include "exr.h"
#include "exr_io.h"
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The channels an RGB image has, in the order its texels interleave them. */
static const char channel_letter[3] = {'R', 'G', 'B'};

/* Encodes an exr_rgb_image as R, G, B floats, one scanline chunk at a time (ZIP: lossless, and the same
 * image gives the same bytes). The channels are read straight from the interleaved texels. */
pl_status exr_encode_rgb(FILE *file, const void *user, pl_diag *diag)
{
    const exr_rgb_image *img = user;
    int fd;
    exr_context_t x = NULL;
    int part = 0;
    exr_result_t r = exrio_start_write(file, &fd, "image.exr", &x);
    if (r == EXR_ERR_SUCCESS) r = exr_add_part(x, "image", EXR_STORAGE_SCANLINE, &part);
    if (r == EXR_ERR_SUCCESS) r = exr_initialize_required_attr_simple(x, part, img->width, img->height, EXR_COMPRESSION_ZIP);
    for (int c = 0; c < 3 && r == EXR_ERR_SUCCESS; c++) {
        char name[2] = {channel_letter[c], 0};
        if (exr_add_channel(x, part, name, EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1) < 0) r = EXR_ERR_INVALID_ARGUMENT;
    }
    if (r == EXR_ERR_SUCCESS) r = exr_write_header(x);
    int32_t lines = 1;
    if (r == EXR_ERR_SUCCESS) r = exr_get_scanlines_per_chunk(x, part, &lines);
    for (int y = 0; y < img->height && r == EXR_ERR_SUCCESS; y += lines) {
        exr_chunk_info_t cinfo;
        exr_encode_pipeline_t enc;
        if ((r = exr_write_scanline_chunk_info(x, part, y, &cinfo)) != EXR_ERR_SUCCESS) break;
        if ((r = exr_encoding_initialize(x, part, &cinfo, &enc)) != EXR_ERR_SUCCESS) break;
        for (int i = 0; i < enc.channel_count; i++) {
            int c = enc.channels[i].channel_name[0] == 'R' ? 0 : enc.channels[i].channel_name[0] == 'G' ? 1 : 2;
            enc.channels[i].encode_from_ptr = (const uint8_t *)(img->texels + 3 * (size_t)y * img->width + c);
            enc.channels[i].user_pixel_stride = 12;
            enc.channels[i].user_line_stride = 12 * img->width;
            enc.channels[i].user_bytes_per_element = 4;
            enc.channels[i].user_data_type = EXR_PIXEL_FLOAT;
        }
        r = exr_encoding_choose_default_routines(x, part, &enc);
        if (r == EXR_ERR_SUCCESS) r = exr_encoding_run(x, part, &enc);
        exr_encoding_destroy(x, &enc);
    }
    exr_result_t fin = x ? exr_finish(&x) : EXR_ERR_SUCCESS;
    if (r == EXR_ERR_SUCCESS) r = fin;
    return r == EXR_ERR_SUCCESS ? PL_OK : exrio_fail(diag, "writing EXR", r);
}

/* The R, G and B channels of an RGB image's header: each present, half or float, not subsampled.
 * Any other channel (A, a depth, a layer) is left undecoded. */
static pl_status find_rgb_channels(exr_context_t x, const char *path, pl_diag *diag)
{
    const exr_attr_chlist_t *chl = NULL;
    if (exr_get_channels(x, 0, &chl) != EXR_ERR_SUCCESS || !chl)
        return pl_fail(diag, PL_ERR_PARSE, "%s: channels: expected R, G and B", path);
    for (int c = 0; c < 3; c++) {
        const exr_attr_chlist_entry_t *found = NULL;
        for (int i = 0; i < chl->num_channels; i++)
            if (chl->entries[i].name.str && chl->entries[i].name.length == 1 && chl->entries[i].name.str[0] == channel_letter[c])
                found = &chl->entries[i];
        if (!found)
            return pl_fail(diag, PL_ERR_PARSE, "%s: channels: expected R, G and B; there is no %c (a luminance-only "
                           "or layered image must be converted to RGB first)", path, channel_letter[c]);
        if ((found->pixel_type != EXR_PIXEL_HALF && found->pixel_type != EXR_PIXEL_FLOAT) || found->x_sampling != 1 ||
            found->y_sampling != 1)
            return pl_fail(diag, PL_ERR_PARSE, "%s: channel %c: expected half or float values at every pixel "
                           "(no subsampling)", path, channel_letter[c]);
    }
    return PL_OK;
}

/* Decodes the chunk at row y (of the data window, from 0) into the interleaved texels. */
static pl_status read_rgb_chunk(exr_context_t x, const char *path, int y, int first_row, int width, int height,
                                int lines, float *texels, pl_diag *diag)
{
    exr_chunk_info_t cinfo;
    exr_result_t r = exr_read_scanline_chunk_info(x, 0, first_row + y, &cinfo);
    int rows = height - y < lines ? height - y : lines;
    if (r == EXR_ERR_SUCCESS && (cinfo.start_y != first_row + y || cinfo.height != rows || cinfo.width != width))
        return pl_fail(diag, PL_ERR_PARSE, "%s: the chunk at row %d: expected %d rows of %d pixels", path, y, rows, width);
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    if (r == EXR_ERR_SUCCESS && (r = exr_decoding_initialize(x, 0, &cinfo, &dec)) == EXR_ERR_SUCCESS) {
        for (int i = 0; i < dec.channel_count; i++) {
            const char *name = dec.channels[i].channel_name;
            int c = !strcmp(name, "R") ? 0 : !strcmp(name, "G") ? 1 : !strcmp(name, "B") ? 2 : -1;
            /* A NULL destination tells the decoder to skip the channel. */
            dec.channels[i].decode_to_ptr = c < 0 ? NULL : (uint8_t *)(texels + 3 * (size_t)y * width + c);
            dec.channels[i].user_pixel_stride = 12;
            dec.channels[i].user_line_stride = 12 * width;
            dec.channels[i].user_bytes_per_element = 4;
            dec.channels[i].user_data_type = EXR_PIXEL_FLOAT;
        }
        r = exr_decoding_choose_default_routines(x, 0, &dec);
        if (r == EXR_ERR_SUCCESS) r = exr_decoding_run(x, 0, &dec);
    }
    exr_decoding_destroy(x, &dec);
    static const char *const compression_name[] = {"none", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB"};
    exr_compression_t comp = EXR_COMPRESSION_LAST_TYPE;
    /* OpenEXR's C library (3.1) does not decode DWAA and DWAB, which Blender's and many HDRI sites'
     * maps use: say how to re-save the file rather than pass on "please use C++ library". */
    if (r == EXR_ERR_FEATURE_NOT_IMPLEMENTED && exr_get_compression(x, 0, &comp) == EXR_ERR_SUCCESS &&
        comp < EXR_COMPRESSION_LAST_TYPE)
        return pl_fail(diag, PL_ERR_PARSE, "%s: compression %s: OpenEXR's C library cannot decode it; save the map "
                       "with another, e.g. oiiotool IN.exr --compression zip -o OUT.exr (Debian's openimageio-tools)",
                       path, compression_name[comp]);
    return r == EXR_ERR_SUCCESS ? PL_OK : pl_fail(diag, PL_ERR_PARSE, "%s: the chunk at row %d: %s", path, y,
                                                  exr_get_default_error_message(r));
}

/* Every texel is a radiance: finite (the first that is not is named) and not negative. Maps that were
 * filtered or lossily compressed hold tiny negative values (Blender's CC0 maps reach -4.5e-6): those
 * read as 0, and one warning says how many and the least. */
static pl_status check_rgb_values(const char *path, float *texels, int width, int height, pl_diag *diag)
{
    size_t negative = 0;
    float least = 0.0f;
    for (size_t k = 0; k < 3 * (size_t)width * height; k++) {
        if (!isfinite(texels[k]))
            return pl_fail(diag, PL_ERR_PARSE, "%s: pixel (%zu, %zu), channel %c: expected a finite radiance, found %g",
                           path, k / 3 % width, k / 3 / width, channel_letter[k % 3], (double)texels[k]);
        if (texels[k] < 0.0f) {
            negative++;
            least = fminf(least, texels[k]);
            texels[k] = 0.0f;
        }
    }
    if (negative) pl_warn(diag, "%s: %zu values below 0 (the least %g) read as 0: a radiance is never negative", path,
                          negative, (double)least);
    return PL_OK;
}

pl_status exr_read_rgb(const char *path, int max_side, long max_pixels, exr_rgb_image *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = exrio_quiet_errors;
    exr_context_t x = NULL;
    exr_result_t r = exr_start_read(&x, path, &init);
    pl_status s = r == EXR_ERR_SUCCESS ? PL_OK : pl_fail(diag, PL_ERR_IO, "%s: cannot read as OpenEXR: %s", path,
                                                         exr_get_default_error_message(r));
    int parts = 0;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_attr_box2i_t data;
    if (s == PL_OK && (exr_get_count(x, &parts) != EXR_ERR_SUCCESS || parts != 1 ||
                       exr_get_storage(x, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE))
        s = pl_fail(diag, PL_ERR_PARSE, "%s: expected a single-part scanline image (a tiled or multi-part file "
                    "converts with: oiiotool IN.exr --scanline -o OUT.exr)", path);
    if (s == PL_OK && exr_get_data_window(x, 0, &data) != EXR_ERR_SUCCESS)
        s = pl_fail(diag, PL_ERR_PARSE, "%s: dataWindow: missing", path);
    int64_t w = s == PL_OK ? (int64_t)data.max.x - data.min.x + 1 : 0, h = s == PL_OK ? (int64_t)data.max.y - data.min.y + 1 : 0;
    if (s == PL_OK && (w < 1 || h < 1 || w > max_side || h > max_side || w * h > max_pixels))
        s = pl_fail(diag, PL_ERR_PARSE, "%s: dataWindow: %" PRId64 "x%" PRId64 " pixels, expected at most %d a side and "
                    "%ld in all", path, w, h, max_side, max_pixels);
    if (s == PL_OK) s = find_rgb_channels(x, path, diag);
    int32_t lines = 0;
    if (s == PL_OK && (exr_get_scanlines_per_chunk(x, 0, &lines) != EXR_ERR_SUCCESS || lines < 1 || lines > 256))
        s = pl_fail(diag, PL_ERR_PARSE, "%s: expected scanline chunks of 1 to 256 rows", path);
    /* Zeroed: whatever a decoder leaves unwritten reads as 0, never as old heap contents. */
    float *texels = s == PL_OK ? calloc(3 * (size_t)w * (size_t)h, sizeof *texels) : NULL;
    if (s == PL_OK && !texels) s = pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory for %" PRId64 "x%" PRId64 " pixels", path, w, h);
    for (int y = 0; s == PL_OK && y < h; y += lines) s = read_rgb_chunk(x, path, y, data.min.y, (int)w, (int)h, lines, texels, diag);
    if (x) exr_finish(&x);
    if (s == PL_OK) s = check_rgb_values(path, texels, (int)w, (int)h, diag);
    if (s != PL_OK) {
        free(texels);
        return s;
    }
    out->width = (int)w, out->height = (int)h, out->texels = texels;
    return PL_OK;
}
