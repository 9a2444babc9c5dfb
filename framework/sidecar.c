/* The JSON sidecar. Written by hand (it is flat and small); strings are escaped per RFC 8259. */
#include "sidecar.h"
#include "version.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { char *data; size_t len, cap; bool failed; } text;

static void text_printf(text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void text_printf(text *t, const char *fmt, ...)
{
    if (t->failed) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(t->data ? t->data + t->len : NULL, t->data ? t->cap - t->len : 0, fmt, ap);
        va_end(ap);
        if (n < 0) { t->failed = true; return; }
        if (t->data && t->len + (size_t)n < t->cap) { t->len += (size_t)n; return; }
        size_t cap = t->cap ? t->cap * 2 : 4096;
        while (cap < t->len + (size_t)n + 1) cap *= 2;
        char *grown = realloc(t->data, cap);
        if (!grown) { t->failed = true; return; }
        t->data = grown;
        t->cap = cap;
    }
}

static void text_json_string(text *t, const char *s)
{
    text_printf(t, "\"");
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') text_printf(t, "\\%c", c);
        else if (c < 0x20) text_printf(t, "\\u%04x", c);
        else text_printf(t, "%c", c);
    }
    text_printf(t, "\"");
}

char *path_with_suffix(const char *path, const char *suffix, const char *extension)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    size_t stem = (dot && (!slash || dot > slash)) ? (size_t)(dot - path) : strlen(path);
    size_t n = stem + strlen(suffix) + strlen(extension) + 1;
    char *out = malloc(n);
    if (out) snprintf(out, n, "%.*s%s%s", (int)stem, path, suffix, extension);
    return out;
}

pl_status sidecar_write(const char *path, const render_ctx *ctx, const sidecar_info *info, pl_diag *diag)
{
    const options *o = ctx->opts;
    const render_stats *r = info->render;
    text t = {0};
    text_printf(&t, "{\n  \"program\": \"pathlab\",\n  \"version\": ");
    text_json_string(&t, PL_VERSION);
    text_printf(&t, ",\n  \"command_line\": ");
    text_json_string(&t, o->command_line);
    text_printf(&t, ",\n  \"scene\": ");
    text_json_string(&t, o->scene_path);
    text_printf(&t, ",\n  \"seed\": %llu,\n  \"width\": %d,\n  \"height\": %d,\n", (unsigned long long)o->seed,
                ctx->width, ctx->height);
    text_printf(&t, "  \"options\": {\"spp\": %d, \"light_samples\": %d, \"max_depth\": %d, \"accumulate\": %s, "
                    "\"hemisphere\": %s, \"adaptive\": %s, \"adaptive_batch\": %d, \"adaptive_tolerance\": %g, "
                    "\"russian_roulette\": %s, \"normals\": %s, \"threads\": %d},\n",
                o->spp, o->light_samples, o->max_depth, o->accumulate ? "true" : "false",
                o->hemisphere ? "true" : "false", o->adaptive ? "true" : "false", o->adaptive_batch,
                o->adaptive_tol, o->no_roulette ? "false" : "true", o->normals ? "true" : "false", o->threads);
    const scene *s = ctx->scene;
    text_printf(&t, "  \"scene_stats\": {\"triangles\": %d, \"spheres\": %d, \"lights\": %d, \"materials\": %d},\n",
                s->num_triangles, s->num_spheres, s->num_lights, s->num_materials);
    const accel *a = ctx->accel;
    accel_shape shape = accel_bvh_shape(a);
    text_printf(&t, "  \"accel\": {\"kind\": \"%s\", \"nodes\": %d, \"leaves\": %d, \"depth\": %d},\n",
                a->use_bvh ? "bvh" : "linear", shape.nodes, shape.leaves, shape.depth);
    text_printf(&t, "  \"timings_seconds\": {\"load\": %.6f, \"build\": %.6f, \"render\": %.6f, \"write\": %.6f},\n",
                info->load_seconds, info->build_seconds, r->seconds, info->write_seconds);
    double mrays = r->seconds > 0 ? r->rays / r->seconds * 1e-6 : 0.0;
    text_printf(&t, "  \"rays_traced\": %llu,\n  \"million_rays_per_second\": %.3f,\n", (unsigned long long)r->rays, mrays);
    text_printf(&t, "  \"camera_samples\": %llu,\n  \"mean_samples_per_pixel\": %.4f,\n",
                (unsigned long long)r->samples, (double)r->samples / ((double)ctx->width * ctx->height));
    text_printf(&t, "  \"bad_pixels\": %d", r->bad_pixels);
    if (info->samples_per_pixel) {
        text_printf(&t, ",\n  \"samples_per_pixel\": [\n");
        for (int y = 0; y < ctx->height; y++) {
            text_printf(&t, "    [");
            for (int x = 0; x < ctx->width; x++)
                text_printf(&t, x ? ",%d" : "%d", info->samples_per_pixel[y * ctx->width + x]);
            text_printf(&t, y + 1 < ctx->height ? "],\n" : "]\n");
        }
        text_printf(&t, "  ]");
    }
    text_printf(&t, "\n}\n");
    if (t.failed) {
        free(t.data);
        return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    }
    pl_status st = file_write_atomic(path, t.data, t.len, diag);
    free(t.data);
    return st;
}
