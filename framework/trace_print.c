/* --trace-pixel's printer: one line of the tree as text, or one event of the JSON document
 * (framework/trace.schema.json), and the helpers every trace module shares (trace_internal.h).
 * Test machinery: not part of any assignment. */
#include "trace_internal.h"
#include "envmap.h"
#include <math.h>
#include <stdarg.h>
#include <string.h>

/* ---- JSON values ------------------------------------------------------------------------------ */

/* JSON has no NaN or infinity: such a value is written as the string "nan", "inf" or "-inf". */
json_t *trace_jnum(double v)
{
    return isfinite(v) ? json_real(v) : json_string(isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
}
/* Vectors and colours as three-element arrays. */
static json_t *jv3(float a, float b, float c) { return json_pack("[ooo]", trace_jnum(a), trace_jnum(b), trace_jnum(c)); }
json_t *trace_jvec(vec3 v) { return jv3(v.x, v.y, v.z); }
json_t *trace_jrgb(rgb c) { return jv3(c.r, c.g, c.b); }
/* A position in the file's coordinates: the scene stores them relative to its origin (scene.h). */
json_t *trace_jpoint(const trace_log *t, vec3 v)
{
    return json_pack("[ooo]", trace_jnum(FILE_AT(t, v.x, 0)), trace_jnum(FILE_AT(t, v.y, 1)),
                     trace_jnum(FILE_AT(t, v.z, 2)));
}

/* ---- lines and marks -------------------------------------------------------------------------- */

/* A sample outside --trace-sample's range still runs every hook (its checks must see the same
 * path), but prints nothing: its fields are dropped here, in one place. */
void trace_emit(trace_log *t, const char *kind, json_t *fields, const char *fmt, ...)
{
    if (!t->recording) {
        json_decref(fields);
        return;
    }
    char line[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    /* Text indents two spaces a level; JSON keeps the level as a number and the text beside it. */
    int level = t->depth + 1;
    if (!t->doc) {
        fprintf(t->out, "%*s%s\n", 2 * level, "", line);
        json_decref(fields);
        return;
    }
    json_t *e = fields ? fields : json_object();
    json_object_set_new(e, "kind", json_string(kind));
    json_object_set_new(e, "level", json_integer(level));
    json_object_set_new(e, "text", json_string(line));
    /* Between samples (a batch check of -a) there is no sample's list: the document's own takes it. */
    json_array_append_new(t->events ? t->events : t->checks, e);
}

/* Only marks of printed samples count: --trace-sample narrows what the summary's count covers too. */
void trace_mark(trace_log *t, const char *fmt, ...)
{
    char line[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (t->recording) t->marks++;
    trace_emit(t, "mark", NULL, "!! %s", line);
}

/* Radiance is never negative, NaN or infinite: such a value is marked where it first appears. */
static bool rgb_bad(rgb c) { return !rgb_is_finite(c) || c.r < 0.0f || c.g < 0.0f || c.b < 0.0f; }

void trace_check_radiance(trace_log *t, const char *what, rgb c)
{
    if (rgb_bad(c)) trace_mark(t, "%s is " V3 ": radiance must be finite and not negative", what, RGB(c));
}

/* ---- what every module asks ------------------------------------------------------------------- */

/* Calls nested deeper than MAX_NEST are not framed: the innermost framed one answers for them. */
trace_frame *trace_top(trace_log *t) { return t->depth ? &t->stack[t->depth - 1] : NULL; }
bool trace_in(trace_log *t, pl_seam_id fn) { return t->depth && trace_top(t)->fn == fn; }

/* Absolute 1e-5 for values near black, relative 1e-3 above: float sums of a few terms in another
 * order stay within both. */
bool trace_rgb_close(rgb a, rgb b)
{
    float d = fmaxf(fabsf(a.r - b.r), fmaxf(fabsf(a.g - b.g), fabsf(a.b - b.b)));
    return d <= 1e-5f + 1e-3f * fmaxf(rgb_max(a), rgb_max(b));
}

/* A hit a broken part filled may name any material: checked before the trace reads one. */
const material *trace_material_at(const trace_log *t, const hit *h)
{
    const scene *s = t->ctx->scene;
    return h->material >= 0 && h->material < s->num_materials ? &s->materials[h->material] : NULL;
}

/* The marks that bound a diffuse f by 1/pi hold for it alone (a glossy metal's f is far above). */
bool trace_shades_diffuse(const material *m)
{
    return m->kind == MATERIAL_DIFFUSE || !material_kind_shaded(m->kind);
}

/* ---- hits and the summary --------------------------------------------------------------------- */

/* A miss says what the ray sees there: a camera ray that leaves the scene sees the environment map
 * (render.c adds it). */
static void describe_miss(trace_log *t, const char *role, const ray *r)
{
    const scene *s = t->ctx->scene;
    bool sees_map = s->env && !strcmp(role, "camera ray");
    rgb Le = sees_map ? envmap_radiance(s->env, r->d) : rgb_gray(0.0f);
    char seen[128] = "";
    if (sees_map) snprintf(seen, sizeof seen, "; sees the environment map: radiance " V3, RGB(Le));
    json_t *ev = json_pack("{s:s, s:o, s:o}", "role", role, "origin", trace_jpoint(t, r->o), "direction", trace_jvec(r->d));
    if (sees_map && ev) json_object_set_new(ev, "environment", trace_jrgb(Le));
    trace_emit(t, "miss", ev, "%s from " V3 " along " V3 ": misses everything%s", role, PXYZ(r->o), XYZ(r->d), seen);
}

void trace_describe_hit(trace_log *t, const char *role, const ray *r, bool found, const hit *h)
{
    const scene *s = t->ctx->scene;
    if (!found) {
        describe_miss(t, role, r);
        return;
    }
    bool tri = h->prim < s->num_triangles;
    bool valid = h->prim >= 0 && h->prim < scene_prim_count(s) && h->material >= 0 && h->material < s->num_materials;
    const material *m = valid ? &s->materials[h->material] : NULL;
    vec3 p = ray_at(r, h->t);
    trace_emit(t, "hit",
               json_pack("{s:s, s:o, s:o, s:i, s:s, s:o, s:o, s:o, s:o, s:o}", "role", role, "origin",
                         trace_jpoint(t, r->o), "direction", trace_jvec(r->d), "primitive", h->prim, "primitive_kind",
                         tri ? "triangle" : "sphere", "distance", trace_jnum(h->t), "point", trace_jpoint(t, p), "normal",
                         trace_jvec(h->n), "reflectance", trace_jrgb(m ? m->albedo : rgb_gray(0)), "emission",
                         trace_jrgb(m ? m->Le : rgb_gray(0))),
               "%s along " V3 " hits %s %d (material \"%s\") at distance %.6g, point " V3 ", normal " V3
               "; reflectance " V3 ", emission " V3,
               role, XYZ(r->d), tri ? "triangle" : "sphere", h->prim, m ? m->name : "?", (double)h->t, PXYZ(p),
               XYZ(h->n), RGB(m ? m->albedo : rgb_gray(0)), RGB(m ? m->Le : rgb_gray(0)));
    float len = vec3_length(h->n);
    if (!(fabsf(len - 1.0f) <= 1e-3f)) trace_mark(t, "the normal at this hit has length %.6g, not 1", (double)len);
    if (!valid) trace_mark(t, "the hit names primitive %d, material %d: not in the scene", h->prim, h->material);
}

/* The pixel's value as the image holds it, from the same film accumulators a render uses. */
void trace_summary(trace_log *t, const film_pixel *px)
{
    rgb mean = film_pixel_rgb(px);
    rgb var = rgb_make((float)film_pixel_variance_of_mean(px, 0), (float)film_pixel_variance_of_mean(px, 1),
                       (float)film_pixel_variance_of_mean(px, 2));
    if (t->doc) {
        json_object_set_new(t->doc, "mean", trace_jrgb(mean));
        json_object_set_new(t->doc, "variance_of_mean", trace_jrgb(var));
        json_object_set_new(t->doc, "sample_count", json_integer(px->n));
        json_object_set_new(t->doc, "bad_samples", json_integer(px->bad));
        json_object_set_new(t->doc, "marks", json_integer(t->marks));
        return;
    }
    fprintf(t->out, "pixel (%d, %d): %u samples, mean %.9g %.9g %.9g (the image's value), variance of the mean %.5g %.5g %.5g\n",
            t->req.x, t->req.y, px->n, RGB(mean), RGB(var));
    if (px->bad) fprintf(t->out, "  %u samples were NaN, infinite or negative: the image counts them as black\n", px->bad);
    fprintf(t->out, "%d line%s marked !! above\n", t->marks, t->marks == 1 ? "" : "s");
}
