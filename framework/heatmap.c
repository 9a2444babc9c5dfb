/* BVH heat map: how many BVH nodes each pixel's centre ray visits, as a false-colour PNG with a
 * legend strip underneath. A good tree is dark blue almost everywhere; red patches show where
 * rays wade through many boxes (long thin triangles, overlapping leaves, a poor split). */
#include "heatmap.h"
#include "counters.h"
#include "render.h"
#include "colormap.h"
#include "../parts/part1_raygen/part1.h"  /* call sites of the parts (framework/README.md) */
#include "../parts/part2_bvh/part2.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- The legend: a colour bar and three numbers, drawn with a 3x5 digit font ---------------- */

#define LEGEND_HEIGHT 36   /* pixels below the image */
#define HEATMAP_SCALE 200  /* node visits at full red, the same for every scene */
#define FONT_SCALE 2       /* each font pixel drawn as a 2x2 block */

/* Rows of the digits 0-9, 3 bits wide (bit 2 = left column), top row first. */
static const uint8_t DIGIT_FONT[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};

static void put_pixel(uint8_t *rgb8, int width, int height, int x, int y, const uint8_t c[3])
{
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    memcpy(rgb8 + 3 * ((size_t)y * width + x), c, 3);
}

/* Draws the decimal number v with its left edge at x (or centred on x, or right-aligned to x). */
static void draw_number(uint8_t *rgb8, int width, int height, int x, int y, unsigned v, int align)
{
    char text[16];
    int len = snprintf(text, sizeof text, "%u", v);
    int glyph_w = 4 * FONT_SCALE;  /* 3 columns plus one of spacing */
    int left = align < 0 ? x : align == 0 ? x - len * glyph_w / 2 : x - len * glyph_w;
    static const uint8_t white[3] = {255, 255, 255};
    for (int i = 0; i < len; i++)
        for (int row = 0; row < 5 * FONT_SCALE; row++)
            for (int col = 0; col < 3 * FONT_SCALE; col++)
                if (DIGIT_FONT[text[i] - '0'][row / FONT_SCALE] & (4 >> (col / FONT_SCALE)))
                    put_pixel(rgb8, width, height, left + i * glyph_w + col, y + row, white);
}

/* Colour bar from 0 (blue) to scale (red) across the strip under the image, labelled at both
 * ends and the middle. */
static void draw_legend(uint8_t *rgb8, int width, int height, int top, unsigned scale)
{
    int margin = 8, bar_h = 10;
    for (int x = margin; x < width - margin; x++) {
        uint8_t c[3];
        colormap_rate((float)(x - margin) / (float)(width - 2 * margin - 1), c);
        for (int y = top + 4; y < top + 4 + bar_h; y++) put_pixel(rgb8, width, height, x, y, c);
    }
    int text_y = top + 4 + bar_h + 4;
    draw_number(rgb8, width, height, margin, text_y, 0, -1);
    draw_number(rgb8, width, height, width / 2, text_y, scale / 2, 0);
    draw_number(rgb8, width, height, width - margin, text_y, scale, 1);
}

pl_status heatmap_render(const struct render_ctx *ctx, const char *path, heatmap *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    if (!ctx->accel->use_bvh)
        return pl_fail(diag, PL_ERR_INVALID,
                       "%s: the heat map needs part 2's BVH (it is not implemented yet, or --no-bvh was given)", path);
    int w = ctx->width, h = ctx->height;
    unsigned *visits = malloc((size_t)w * h * sizeof *visits);
    uint8_t *rgb8 = calloc((size_t)w * (h + LEGEND_HEIGHT), 3);
    if (!visits || !rgb8) {
        free(visits);
        free(rgb8);
        return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory for a %dx%d heat map", path, w, h);
    }

    /* One ray through each pixel centre; pixel (x, y) counts from the bottom, rows from the top. */
    unsigned most = 0;
    (void)counters_take();
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            ray r = camera_generate_ray(&ctx->camera, (x + 0.5f) / w, (y + 0.5f) / h);
            hit hi;
            bvh_intersect(&ctx->accel->bvh, ctx->scene, &r, &hi);
            uint64_t n = counters_take().node_visits;
            unsigned v = n > UINT32_MAX ? UINT32_MAX : (unsigned)n;
            visits[(size_t)(h - 1 - y) * w + x] = v;
            if (v > most) most = v;
        }
    }
    if (most == 0) {
        free(visits);
        free(rgb8);
        return pl_fail(diag, PL_ERR_INVALID,
                       "%s: bvh_intersect visited no nodes: call bvh_visit for every node you enter (task 2.3)", path);
    }

    /* One scale for every scene and every BVH, so two heat maps compare colour for colour (a
     * per-scene scale made a poor tree on a small scene look as cool as a good one on the bunny).
     * A good SAH tree stays well under it; more visits saturate red. */
    unsigned scale = HEATMAP_SCALE;
    for (size_t i = 0; i < (size_t)w * h; i++) colormap_rate((float)visits[i] / (float)scale, rgb8 + 3 * i);
    draw_legend(rgb8, w, h + LEGEND_HEIGHT, h, scale);
    free(visits);
    *out = (heatmap){rgb8, w, h + LEGEND_HEIGHT};
    return PL_OK;
}

pl_status heatmap_encode(FILE *f, const void *user, pl_diag *diag)
{
    const heatmap *map = user;
    return image_encode_png_rgb8(f, map->rgb8, map->width, map->height, diag);
}

void heatmap_free(heatmap *map)
{
    if (!map) return;
    free(map->rgb8);
    memset(map, 0, sizeof *map);
}

pl_status render_heatmap(const struct render_ctx *ctx, const char *path, pl_diag *diag)
{
    heatmap map;
    pl_status st = heatmap_render(ctx, path, &map, diag);
    if (st == PL_OK) st = image_write_png_rgb8(map.rgb8, map.width, map.height, path, diag);
    heatmap_free(&map);
    return st;
}
