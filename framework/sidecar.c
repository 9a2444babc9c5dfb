/* The JSON sidecar, built with jansson (Debian's libjansson): it escapes strings, validates UTF-8
 * and writes numbers exactly, so the file always parses. */
#include "sidecar.h"
#include "version.h"
#include <jansson.h>
#include <stdlib.h>
#include <string.h>

/* A JSON string from bytes that may not be UTF-8 (a path is any bytes on Linux): valid sequences
 * are kept, each invalid byte becomes U+FFFD, so the sidecar stays valid JSON and still readable. */
static json_t *string_lossy(const char *s)
{
    if (!s) return json_null();
    size_t n = strlen(s), out = 0;
    char *clean = malloc(3 * n + 1);
    if (!clean) return NULL;
    for (size_t i = 0; i < n;) {
        unsigned char c = (unsigned char)s[i];
        size_t len = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        bool ok = len > 0 && i + len <= n;
        for (size_t k = 1; ok && k < len; k++) ok = ((unsigned char)s[i + k] & 0xC0) == 0x80;
        /* Overlong forms, surrogates and values past U+10FFFF: json_stringn decides (below). */
        if (ok && json_stringn(s + i, len) == NULL) ok = false;
        if (ok) {
            memcpy(clean + out, s + i, len);
            out += len;
            i += len;
        } else {
            memcpy(clean + out, "\xEF\xBF\xBD", 3);
            out += 3;
            i++;
        }
    }
    json_t *j = json_stringn(clean, out);
    free(clean);
    return j;
}

/* The whole sidecar in one json_pack: the keys read in the order the file lists them (README.md
 * names what a render records). Strings from the user (paths, the command line) go through
 * string_lossy; numbers are the render's own. */
pl_status sidecar_encode(FILE *f, const void *user, pl_diag *diag)
{
    const sidecar_info *info = user;
    const render_ctx *ctx = info->ctx;
    const options *o = ctx->opts;
    const render_stats *r = info->render;
    const scene *s = ctx->scene;
    accel_shape shape = accel_bvh_shape(ctx->accel);
    /* Rays per second over the pixel loop's wall time; 0 for a loop too quick for the clock. */
    double mrays = r->seconds > 0 ? r->rays / r->seconds * 1e-6 : 0.0;
    int w = ctx->x1 - ctx->x0, h = ctx->y1 - ctx->y0;
    json_t *root = json_pack(
        "{s:s, s:o, s:o, s:o, s:I, s:i, s:i,"
        " s:{s:i, s:i, s:i, s:b, s:b, s:b, s:i, s:f, s:b, s:b, s:i},"
        " s:{s:i, s:i, s:i, s:i}, s:{s:s, s:i, s:i, s:i}, s:{s:f, s:f, s:f},"
        " s:I, s:I, s:I, s:f, s:I, s:f, s:i}",
        "program", "pathlab", "version", string_lossy(PL_VERSION), "command_line", string_lossy(o->command_line),
        "scene", string_lossy(o->scene_path), "seed", (json_int_t)o->seed, "width", ctx->width, "height", ctx->height,
        "options", "spp", o->spp, "light_samples", o->light_samples, "max_depth", o->max_depth, "accumulate",
        o->accumulate, "hemisphere", o->hemisphere, "adaptive", o->adaptive, "adaptive_batch", o->adaptive_batch,
        "adaptive_tolerance", (double)o->adaptive_tol, "russian_roulette", !o->no_roulette, "normals", o->normals,
        "threads", o->threads,
        "scene_stats", "triangles", s->num_triangles, "spheres", s->num_spheres, "lights", s->num_lights,
        "materials", s->num_materials,
        "accel", "kind", ctx->accel->use_bvh ? "bvh" : "linear", "nodes", shape.nodes, "leaves", shape.leaves,
        "depth", shape.depth,
        "timings_seconds", "load", info->load_seconds, "build", info->build_seconds, "render", r->seconds,
        "rays_traced", (json_int_t)r->rays, "node_visits", (json_int_t)r->node_visits,
        "primitive_tests", (json_int_t)r->prim_tests, "million_rays_per_second", mrays, "camera_samples", (json_int_t)r->samples,
        "mean_samples_per_pixel", (double)r->samples / ((double)w * h), "bad_pixels", r->bad_pixels);
    /* --crop: the window rendered; the image and the per-pixel counts are the window's. */
    if (root && o->crop) json_object_set_new(root, "crop", json_pack("[iiii]", ctx->x0, ctx->y0, ctx->x1, ctx->y1));
    /* Per-pixel sample counts only when the caller asks: top row first, as the image. */
    if (root && info->samples_per_pixel) {
        json_t *rows = json_array();
        for (int y = 0; y < h && rows; y++) {
            json_t *row = json_array();
            for (int x = 0; x < w && row; x++)
                json_array_append_new(row, json_integer(info->samples_per_pixel[y * w + x]));
            json_array_append_new(rows, row);
        }
        json_object_set_new(root, "samples_per_pixel", rows);
    }
    /* JSON_COMPACT would be smaller; one field per line reads better and costs little. */
    int failed = root ? json_dumpf(root, f, JSON_INDENT(2) | JSON_PRESERVE_ORDER) : -1;
    json_decref(root);
    if (failed || fputc('\n', f) == EOF) return pl_fail(diag, PL_ERR_IO, "could not encode or write the sidecar");
    return PL_OK;
}
