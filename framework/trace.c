/* --trace-pixel: the seam hooks, the replay of what the parts compute between them, and the
 * printed tree (text or JSON). framework/trace.h explains the approach.
 *
 * How to read this file: render.c calls trace_enter and trace_leave around every part function it
 * calls, and the framework functions the parts call (intersection, shadow rays, light samples, the
 * random generator) report to trace_intersect, trace_occluded, trace_light and trace_rng. From
 * those reports this file prints one line per event, nested by the calls, and recomputes what a
 * correct part would have returned from the same numbers (the light samples' sum, the path's
 * throughput, the roulette's verdict): a line marked !! is a place where the two disagree. The
 * trace runs the very render code on one pixel, so it shows what the render computed, not a model. */
#include "trace.h"
#include "envmap.h"
#include "accel.h"
#include "frame.h"
#include "material.h"
#include "sampler.h"
#include "todo.h"
#include "../parts/part3_direct/part3.h"  /* replayed part functions (framework/README.md) */
#include "../parts/part4_global/part4.h"
#include <jansson.h>
#include <math.h>
#include <stdarg.h>
#include <string.h>

_Thread_local struct trace_log *pl_trace;

#define MAX_NEST 16  /* part calls nested at once (a recursive part 4 nests one per bounce); deeper ones go unframed */

/* Set while the trace itself calls a part function: its draws are no part of the render's. */
static _Thread_local bool replaying;

/* The seam's names and tasks, from its one list (framework/seam.h), for the lines "name (task 3.5):". */
static const char *const seam_names[] = {
#define PL_SEAM_NAME(name, extra) #name,
    PL_SEAM_PART_FUNCTIONS(PL_SEAM_NAME)
    PL_SEAM_FRAMEWORK_FUNCTIONS(PL_SEAM_NAME)
#undef PL_SEAM_NAME
};
static const char *const seam_tasks[] = {
#define PL_SEAM_TASK(name, task) task,
    PL_SEAM_PART_FUNCTIONS(PL_SEAM_TASK)
#undef PL_SEAM_TASK
};

/* A part function the framework called and that has not returned yet. */
typedef struct {
    pl_seam_id fn;
    const render_ctx *ctx;  /* as passed (part 4 may pass its own copy with other options) */
    ray r;
    hit h;
    int todo_before;        /* pl_todo_count() at the call: a stub shows as a rise */
} trace_frame;

/* The replay of one at_least_one_bounce_radiance call: the path as f cos / pdf and the roulette
 * say it should go, compared with what the part returns. */
typedef struct {
    bool active;
    int bounce;             /* the vertex the path is at: 1 at h, one more for each bounce ray (a part
                               may skip a vertex's direct light, -o 0: the count is the rays') */
    rgb beta;               /* throughput of the vertex being lit */
    rgb expected;           /* the sum of what each bounce added */
    ray cur;                /* the ray that reached the vertex, and its hit */
    hit at;
    int draws;              /* random numbers drawn at this vertex since it was reached or its direct
                               light returned: the BSDF sample's two, then the roulette's */
    float value[4];         /* their values (the BSDF sample's replay reads the first two) */
    bool gambled;           /* roulette could have ended the path somewhere: the sum is not checked */
} trace_path;

/* The replay of one direct_importance call: the light samples' contributions. */
typedef struct {
    rgb visible;            /* sum of contributions the framework finds unoccluded */
    rgb hidden;             /* sum of those that hit something nearer than the light */
} trace_direct;

/* Everything one trace keeps: the request, the output (text, or the JSON document being built), the
 * stack of part calls under way, and the replays of the path and the direct light in progress. */
typedef struct trace_log {
    const render_ctx *ctx;
    trace_request req;
    FILE *out;
    bool recording;         /* the current sample is one to print */
    int sample;
    json_t *doc, *samples, *events, *checks;  /* JSON mode only */
    trace_frame stack[MAX_NEST];
    int depth;
    trace_path path;
    trace_direct direct;
    int marks;
    int stubs_marked;       /* pl_todo_count() when the last stub was marked */
    const char *camera_ray_by;  /* who made the sample's camera ray, for its mark: part 1, or part 9's lens */
} trace_log;

/* ---- output: one line of the tree, as text or as a JSON event ------------------------------- */

/* JSON has no NaN or infinity: such a value is written as the string "nan", "inf" or "-inf". */
static json_t *jnum(double v)
{
    return isfinite(v) ? json_real(v) : json_string(isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
}
/* Vectors and colours as three-element arrays. */
static json_t *jv3(float a, float b, float c) { return json_pack("[ooo]", jnum(a), jnum(b), jnum(c)); }
static json_t *jvec(vec3 v) { return jv3(v.x, v.y, v.z); }
/* A position in the file's coordinates: the scene stores them relative to its origin (scene.h). */
#define FILE_AT(t, coord, axis) ((double)(coord) + (t)->ctx->scene->origin[axis])
#define PXYZ(v) FILE_AT(t, (v).x, 0), FILE_AT(t, (v).y, 1), FILE_AT(t, (v).z, 2)
static json_t *jpoint(const trace_log *t, vec3 v)
{
    return json_pack("[ooo]", jnum(FILE_AT(t, v.x, 0)), jnum(FILE_AT(t, v.y, 1)), jnum(FILE_AT(t, v.z, 2)));
}
static json_t *jrgb(rgb c) { return jv3(c.r, c.g, c.b); }

/* Prints one line at the current nesting; fields (owned, may be NULL) go into its JSON event. */
static void emit(trace_log *t, const char *kind, json_t *fields, const char *fmt, ...)
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
    json_array_append_new(t->events ? t->events : t->checks, e);
}

/* Text form of a vector or colour: five significant digits, enough to compare by eye. */
#define V3 "(%.5g, %.5g, %.5g)"
#define XYZ(v) (double)(v).x, (double)(v).y, (double)(v).z
#define RGB(c) (double)(c).r, (double)(c).g, (double)(c).b

/* An invariant broken or a replay that disagrees: one line saying what is wrong. */
static void mark(trace_log *t, const char *fmt, ...)
{
    char line[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (t->recording) t->marks++;
    emit(t, "mark", NULL, "!! %s", line);
}

/* Radiance is never negative, NaN or infinite: such a value is marked where it first appears. */
static bool rgb_bad(rgb c) { return !rgb_is_finite(c) || c.r < 0.0f || c.g < 0.0f || c.b < 0.0f; }

static void check_radiance(trace_log *t, const char *what, rgb c)
{
    if (rgb_bad(c)) mark(t, "%s is " V3 ": radiance must be finite and not negative", what, RGB(c));
}

/* Whether m shades as part 3's diffuse BSDF (diffuse, or a kind the course has no part for): the
 * marks that bound a diffuse f by 1/pi hold for it alone (a glossy metal's f is far above). */
static bool shades_diffuse(const material *m)
{
    return m->kind == MATERIAL_DIFFUSE || !material_kind_shaded(m->kind);
}

/* Within float rounding of each other (sums in another order differ in the last bits). */
static bool rgb_close(rgb a, rgb b)
{
    float d = fmaxf(fabsf(a.r - b.r), fmaxf(fabsf(a.g - b.g), fabsf(a.b - b.b)));
    return d <= 1e-5f + 1e-3f * fmaxf(rgb_max(a), rgb_max(b));
}

/* The innermost part call under way, and whether it is fn. */
static trace_frame *top(trace_log *t) { return t->depth ? &t->stack[t->depth - 1] : NULL; }
static bool in(trace_log *t, pl_seam_id fn) { return t->depth && top(t)->fn == fn; }

/* ---- the pixel loop and the wrapped part functions (render.c calls these) ------------------- */

/* A camera sample starts: printed when it is in --trace-sample's range (all of them by default). */
void trace_sample_begin(int sample, vec2 u)
{
    trace_log *t = pl_trace;
    t->sample = sample;
    t->recording = sample >= t->req.first && (t->req.last < 0 || sample <= t->req.last);
    if (!t->recording) return;
    if (t->doc) {
        t->events = json_array();
        json_array_append_new(t->samples, json_pack("{s:i, s:o, s:o}", "index", sample, "u",
                                                     json_pack("[ff]", (double)u.x, (double)u.y), "events", t->events));
    }
    t->depth = -1;  /* the sample's own line sits one level above its events */
    emit(t, "sample", NULL, "sample %d: offset in the pixel u = (%.5g, %.5g)", sample, (double)u.x, (double)u.y);
    t->depth = 0;
}

void trace_sample_end(rgb L)
{
    trace_log *t = pl_trace;
    t->depth = 0;
    check_radiance(t, "the sample's value", L);
    emit(t, "value", json_pack("{s:o}", "value", jrgb(L)), "sample %d's value: " V3, t->sample, RGB(L));
    if (t->doc && t->events) {
        json_object_set_new(json_array_get(t->samples, json_array_size(t->samples) - 1), "value", jrgb(L));
        t->events = NULL;
    }
    t->recording = false;
}

/* The framework is about to call part function fn: a line naming it and its task, a frame on the
 * stack, and the replays it starts (a path for part 4, a sum of light samples for task 3.5). */
void trace_enter(pl_seam_id fn, const render_ctx *ctx, const ray *r, const hit *h)
{
    trace_log *t = pl_trace;
    if (fn == PL_SEAM_one_bounce_radiance && t->path.active && in(t, PL_SEAM_at_least_one_bounce_radiance)) {
        emit(t, "bounce", json_pack("{s:i, s:o}", "bounce", t->path.bounce, "throughput", jrgb(t->path.beta)),
             "bounce %d: direct light at this vertex, throughput " V3, t->path.bounce, RGB(t->path.beta));
    }
    else if (fn != PL_SEAM_one_bounce_radiance)
        emit(t, "call", json_pack("{s:s, s:s}", "function", seam_names[fn], "task", seam_tasks[fn]),
             "%s (task %s):", seam_names[fn], seam_tasks[fn]);
    else if (!material_is_delta(&ctx->scene->materials[h->material]))
        emit(t, "call", json_pack("{s:s}", "function", seam_names[fn]),
             "one_bounce_radiance (the framework's: -H picks direct_hemisphere, else direct_importance):");
    else
        emit(t, "call", json_pack("{s:s}", "function", seam_names[fn]),
             "one_bounce_radiance (the framework's: at a mirror or glass it follows material_sample_f's direction "
             "and adds the light that ray meets):");
    if (t->depth >= MAX_NEST) return;
    trace_frame *f = &t->stack[t->depth++];
    *f = (trace_frame){fn, ctx, *r, *h, pl_todo_count()};
    if (fn == PL_SEAM_at_least_one_bounce_radiance)
        t->path = (trace_path){.active = true, .bounce = 1, .beta = rgb_gray(1.0f), .cur = *r, .at = *h};
    if (fn == PL_SEAM_direct_importance || fn == PL_SEAM_direct_hemisphere)
        t->direct = (trace_direct){rgb_gray(0.0f), rgb_gray(0.0f)};
}

/* Once per stub call, at the innermost wrapped call it happened in. */
static void stub_mark(trace_log *t, const trace_frame *f)
{
    int now = pl_todo_count();
    if (now > f->todo_before && now > t->stubs_marked && pl_todo_last())
        mark(t, "stub: %s is not implemented yet (its placeholder answer is used)", pl_todo_last());
    if (now > t->stubs_marked) t->stubs_marked = now;
}

/* What direct_importance returned against the sum of its light samples the trace saw: a shadowed
 * sample still counted is named as such, any other difference as the two sums. */
static void direct_check(trace_log *t, rgb L)
{
    trace_direct *d = &t->direct;
    if (rgb_close(L, d->visible)) return;
    if (!rgb_is_black(d->hidden) && rgb_close(L, rgb_add(d->visible, d->hidden)))
        mark(t, "a light sample hits something nearer than the light and is still counted");
    else
        mark(t, "the light samples add up to " V3 " but direct_importance returned " V3, RGB(d->visible), RGB(L));
}

static void path_end(trace_log *t, rgb L);

/* Part function fn returned L: the checks of its replay, its line, and (for one bounce of a path)
 * what the bounce adds to the path's expected sum. */
rgb trace_leave(pl_seam_id fn, rgb L)
{
    trace_log *t = pl_trace;
    if (t->depth == 0) return L;
    trace_frame *f = top(t);
    stub_mark(t, f);
    if (fn == PL_SEAM_at_least_one_bounce_radiance) path_end(t, L);
    if (fn == PL_SEAM_direct_importance && pl_todo_count() == f->todo_before) direct_check(t, L);
    if (fn == PL_SEAM_direct_hemisphere && pl_todo_count() == f->todo_before && !rgb_close(L, t->direct.visible))
        mark(t, "the hemisphere samples add up to " V3 " (each Le f cos / pdf / N, the uniform pdf 1/(2 pi), N = "
             "num_lights x the light samples) but direct_hemisphere returned " V3 ": a direction from another "
             "sampler must be divided by that sampler's pdf, and the sum by N", RGB(t->direct.visible), RGB(L));
    check_radiance(t, seam_names[fn], L);
    if (fn != PL_SEAM_one_bounce_radiance)  /* it returns what direct_* returned, shown already */
        emit(t, "return", json_pack("{s:s, s:o}", "function", seam_names[fn], "value", jrgb(L)), "%s returns " V3,
         seam_names[fn], RGB(L));
    t->depth--;
    if (fn == PL_SEAM_one_bounce_radiance && t->path.active && in(t, PL_SEAM_at_least_one_bounce_radiance)) {
        trace_path *p = &t->path;
        rgb added = rgb_mul(p->beta, L);
        const options *o = t->stack[t->depth - 1].ctx->opts;
        bool kept = o->accumulate || p->bounce == o->max_depth;
        if (kept) p->expected = rgb_add(p->expected, added);
        emit(t, "added", json_pack("{s:i, s:o, s:b}", "bounce", p->bounce, "added", jrgb(added), "kept", kept),
             "bounce %d adds throughput x direct = " V3 "%s", p->bounce, RGB(added), kept ? "" : " (not kept: -o 0)");
        p->draws = 0;
    }
    return L;
}

ray trace_camera_ray(ray r)
{
    trace_log *t = pl_trace;
    emit(t, "camera_ray", json_pack("{s:o, s:o, s:o, s:o}", "origin", jpoint(t, r.o), "direction", jvec(r.d), "min_t",
                                    jnum(r.min_t), "max_t", jnum(r.max_t)),
         "camera ray from " V3 " along " V3 ", t in [%.5g, %.5g]", PXYZ(r.o), XYZ(r.d), (double)r.min_t, (double)r.max_t);
    if (!(r.max_t > r.min_t))
        mark(t, "the camera ray spans no distance: %s is a stub or broken",
             t->camera_ray_by ? t->camera_ray_by : "pixel_sample_ray or camera_generate_ray");
    t->camera_ray_by = NULL;
    return r;
}

/* Part 9's lens ray beside the two facts that make it right, each recomputed here: it starts on the
 * lens (the disc of radius R around the camera's position, in the camera's own X and Y) and passes
 * through the pinhole ray's point on the plane of focus (D ahead along the view axis). The
 * tolerances are float rounding's, scaled to the camera's distance from the scene's origin. */
ray trace_lens_ray(const camera *c, ray pinhole, vec2 u, ray r)
{
    trace_log *t = pl_trace;
    /* A pinhole ray that spans no distance is part 1's doing, a lens ray that does not part 9's: the
     * camera ray's mark (trace_camera_ray, next) names the one that made it. */
    if (!(pinhole.max_t > pinhole.min_t)) return r;
    if (!(r.max_t > r.min_t)) {
        t->camera_ray_by = "thin_lens_ray (task 9.2)";
        return r;
    }
    vec3 forward = mat4_dir(c->camera_to_world, vec3_make(0.0f, 0.0f, -1.0f));
    vec3 focus = ray_at(&pinhole, c->focal_distance / vec3_dot(pinhole.d, forward));
    vec3 offset = vec3_sub(r.o, c->position), to_focus = vec3_sub(focus, r.o);
    float off_plane = vec3_dot(offset, forward);
    float from_centre = vec3_length(vec3_sub(offset, vec3_scale(forward, off_plane)));
    float miss = vec3_length(vec3_sub(to_focus, vec3_scale(r.d, vec3_dot(to_focus, r.d))));
    float scale = 1.0f + vec3_length(c->position);
    bool through = miss <= 1e-4f * (vec3_length(to_focus) + scale);  /* within rounding: the text says so */
    char passes[64] = "passes through that point";
    if (!through) snprintf(passes, sizeof passes, "passes %.3g from that point", (double)miss);
    emit(t, "lens_ray",
         json_pack("{s:o, s:o, s:o, s:o, s:o}", "focus", jpoint(t, focus), "lens_radius", jnum(c->lens_radius),
                   "from_lens_centre", jnum(from_centre), "off_lens_plane", jnum(off_plane), "focus_miss", jnum(miss)),
         "thin lens (task 9.2), u = (%.5g, %.5g): the pinhole ray meets the plane of focus (%.5g ahead) at " V3
         "; the lens ray starts %.5g from the lens's centre (radius %.5g) and %s",
         (double)u.x, (double)u.y, (double)c->focal_distance, PXYZ(focus), (double)from_centre, (double)c->lens_radius,
         passes);
    if (!(fabsf(off_plane) <= 1e-5f * scale) || !(from_centre <= c->lens_radius * (1.0f + 1e-4f) + 1e-6f * scale))
        mark(t, "the lens ray starts off the lens: %.5g along the view axis and %.5g from the lens's centre (radius "
                "%.5g); the lens is the disc of radius -b in the camera's own X and Y", (double)off_plane,
             (double)from_centre, (double)c->lens_radius);
    if (!through)
        mark(t, "the lens ray misses the pinhole ray's point on the plane of focus by %.3g: that point would not be "
                "sharp", (double)miss);
    return r;
}

/* CS184's stopping rule, recomputed so the check shows its numbers beside the part's verdict. */
bool trace_converged(int n, double s1, double s2, float tol, bool verdict)
{
    trace_log *t = pl_trace;
    double mean = s1 / n, var = n > 1 ? fmax(0.0, (s2 - s1 * s1 / n) / (n - 1)) : 0.0;
    double half = 1.96 * sqrt(var / n), bound = tol * mean;
    bool was = t->recording;
    json_t *saved = t->events;
    t->recording = true;
    t->events = NULL;
    t->depth = -1;
    emit(t, "batch_check", json_pack("{s:i, s:f, s:f, s:f, s:b}", "samples", n, "mean", mean, "half_width", half,
                                     "tolerance", bound, "stop", verdict),
         "batch check after %d samples: mean luminance %.6g, half-width %.6g, tolerance %.6g -> %s", n, mean, half,
         bound, verdict ? "stop" : "go on");
    if (verdict != (half <= bound) && n > 1)
        mark(t, "adaptive_converged says %s, but I = %.6g %s T * mean = %.6g", verdict ? "stop" : "go on", half,
             half <= bound ? "<=" : ">", bound);
    t->depth = 0;
    t->recording = was;
    t->events = saved;
    return verdict;
}

/* ---- framework functions the parts call ----------------------------------------------------- */

/* A ray's hit or miss, in words: which primitive and material, the distance, point and normal. */
static void describe_hit(trace_log *t, const char *role, const ray *r, bool found, const hit *h)
{
    const scene *s = t->ctx->scene;
    if (!found) {
        /* A camera ray that leaves the scene sees the environment map (render.c adds it). */
        bool sees_map = s->env && !strcmp(role, "camera ray");
        rgb Le = sees_map ? envmap_radiance(s->env, r->d) : rgb_gray(0.0f);
        char seen[128] = "";
        if (sees_map) snprintf(seen, sizeof seen, "; sees the environment map: radiance " V3, RGB(Le));
        json_t *ev = json_pack("{s:s, s:o, s:o}", "role", role, "origin", jpoint(t, r->o), "direction", jvec(r->d));
        if (sees_map && ev) json_object_set_new(ev, "environment", jrgb(Le));
        emit(t, "miss", ev, "%s from " V3 " along " V3 ": misses everything%s", role, PXYZ(r->o), XYZ(r->d), seen);
        return;
    }
    bool tri = h->prim < s->num_triangles;
    bool valid = h->prim >= 0 && h->prim < scene_prim_count(s) && h->material >= 0 && h->material < s->num_materials;
    const material *m = valid ? &s->materials[h->material] : NULL;
    vec3 p = ray_at(r, h->t);
    emit(t, "hit",
         json_pack("{s:s, s:o, s:o, s:i, s:s, s:o, s:o, s:o, s:o, s:o}", "role", role, "origin", jpoint(t, r->o), "direction",
                   jvec(r->d), "primitive", h->prim, "primitive_kind", tri ? "triangle" : "sphere", "distance",
                   jnum(h->t), "point", jpoint(t, p), "normal", jvec(h->n), "reflectance",
                   jrgb(m ? m->albedo : rgb_gray(0)), "emission", jrgb(m ? m->Le : rgb_gray(0))),
         "%s along " V3 " hits %s %d (material \"%s\") at distance %.6g, point " V3 ", normal " V3
         "; reflectance " V3 ", emission " V3,
         role, XYZ(r->d), tri ? "triangle" : "sphere", h->prim, m ? m->name : "?", (double)h->t, PXYZ(p), XYZ(h->n),
         RGB(m ? m->albedo : rgb_gray(0)), RGB(m ? m->Le : rgb_gray(0)));
    float len = vec3_length(h->n);
    if (!(fabsf(len - 1.0f) <= 1e-3f)) mark(t, "the normal at this hit has length %.6g, not 1", (double)len);
    if (!valid) mark(t, "the hit names primitive %d, material %d: not in the scene", h->prim, h->material);
}

static void bounce_ray(trace_log *t, const ray *r);

/* A ray a part traces (render_intersect), named by the call it comes from: a camera ray, a bounce
 * ray of part 4's path, a hemisphere ray of task 3.4. */
bool trace_intersect(const render_ctx *ctx, ray *r, hit *h)
{
    trace_log *t = pl_trace;
    const char *role = "camera ray";
    if (in(t, PL_SEAM_at_least_one_bounce_radiance) && t->path.active) {
        bounce_ray(t, r);
        role = "bounce ray";
    }
    else if (in(t, PL_SEAM_direct_hemisphere)) {
        trace_frame *f = top(t);
        frame sf = shading_frame(&f->r, &f->h);
        vec3 wi = frame_to_local(&sf, r->d);
        role = "hemisphere ray";
        if (wi.z < 0.0f) mark(t, "this ray leaves below the surface (cos theta = %.5g)", (double)wi.z);
    }
    else if (t->depth)
        role = "ray";
    bool found = accel_intersect(ctx->accel, r, h);
    describe_hit(t, role, r, found, h);
    if (found && in(t, PL_SEAM_direct_hemisphere)) {
        int before = pl_todo_count();
        rgb Le = zero_bounce_radiance(top(t)->ctx, r, h);
        if (pl_todo_count() == before) {
            /* What the sample must add: Le f cos / pdf / N with task 3.4's uniform pdf 1/(2 pi) and
             * N = num_lights x the light samples at this vertex (render_light_samples). */
            trace_frame *f = top(t);
            const scene *s = f->ctx->scene;
            frame sf = shading_frame(&f->r, &f->h);
            vec3 wo = frame_to_local(&sf, vec3_neg(f->r.d)), wi = frame_to_local(&sf, vec3_normalize(r->d));
            int n = s->num_lights * render_light_samples(f->ctx, &f->r);
            rgb adds = rgb_gray(0.0f);
            if (wi.z > 0.0f && f->h.material >= 0 && f->h.material < s->num_materials && n > 0)
                adds = rgb_scale(rgb_mul(Le, material_f(&s->materials[f->h.material], wo, wi)),
                                 wi.z * 2.0f * (float)PL_PI / (float)n);
            t->direct.visible = rgb_add(t->direct.visible, adds);
            emit(t, "emission", json_pack("{s:o, s:o}", "emission", jrgb(Le), "contribution", jrgb(adds)),
                 "  emission towards the surface " V3 ", adds " V3 " (Le f cos / (1 / (2 pi)) / N, N = %d)", RGB(Le),
                 RGB(adds), n);
        }
    }
    if (role[0] == 'b') {
        t->path.cur = *r;
        if (found) t->path.at = *h;
    }
    return found;
}

/* A shadow ray a part traces (render_occluded), with its verdict: when blocked, by what (the nearest
 * primitive on the segment, and how far along it: a blocker at distance 0 is the surface the ray
 * started on, self-shadowing); when clear, that it reaches the light. */
bool trace_occluded(const render_ctx *ctx, const ray *r)
{
    trace_log *t = pl_trace;
    bool blocked = accel_occluded(ctx->accel, r);
    char what[200] = "clear: it reaches the light";
    int prim = -1;
    float dist = 0.0f;
    if (blocked) {
        ray probe = *r;
        hit h = {0};
        const scene *s = ctx->scene;
        if (accel_intersect(ctx->accel, &probe, &h) && h.prim >= 0 && h.prim < scene_prim_count(s)) {
            prim = h.prim;
            dist = h.t * vec3_length(r->d);
            bool tri = h.prim < s->num_triangles;
            const char *name = h.material >= 0 && h.material < s->num_materials ? s->materials[h.material].name : "?";
            snprintf(what, sizeof what, "occluded by %s %d (material \"%s\") at distance %.6g%s", tri ? "triangle" : "sphere",
                     h.prim, name, (double)dist, dist < 1e-4f * (1.0f + vec3_length(r->o)) ?
                     ": the surface it starts on? (a ray from the raw hit point)" : "");
        }
        else snprintf(what, sizeof what, "occluded");
    }
    json_t *j = json_pack("{s:o, s:o, s:o, s:o, s:b, s:i, s:o}", "origin", jpoint(t, r->o), "direction", jvec(r->d), "min_t",
                          jnum(r->min_t), "max_t", jnum(r->max_t), "occluded", blocked, "blocker", prim, "blocker_distance",
                          jnum(dist));
    /* A shadow ray towards a light at a finite distance (point, spot, area) is a segment
     * (spawn_ray_to_light: t in (0, 1], an unnormalised direction) whose far end stops just short
     * of the light: shown by its two ends and its length, which is what a student can check. */
    if (isfinite(r->max_t)) {
        vec3 end = vec3_add(r->o, vec3_scale(r->d, r->max_t));
        emit(t, "shadow_ray", j, "shadow ray from " V3 " to " V3 " (length %.6g): %s", PXYZ(r->o), PXYZ(end),
             (double)(vec3_length(r->d) * r->max_t), what);
    }
    else
        emit(t, "shadow_ray", j, "shadow ray from " V3 " along " V3 " (no far end): %s", PXYZ(r->o),
             XYZ(vec3_normalize(r->d)), what);
    return blocked;
}

/* One light sample, with what it adds by the framework's own visibility test: the shadow ray the
 * framework would spawn (spawn_ray_to_light), so the trace and a correct part agree on every sample. */
/* The density of direction w if drawn from texel (x, y): the tables' probability of the texel times
 * the Jacobian w h / (2 pi^2 sin(theta)); 1 / (4 pi) for uniform sampling (no tables). */
static double environment_pdf(const envmap *e, const env_distribution *d, int x, int y, vec3 w)
{
    if (!d) return 1.0 / (4.0 * PL_PI);
    const float *row = d->conditional_cdf + (size_t)y * (e->width + 1);
    double p = ((double)d->marginal_cdf[y + 1] - d->marginal_cdf[y]) * ((double)row[x + 1] - row[x]);
    double sin_theta = hypot(w.x, w.z) / vec3_length(w);
    return p * e->width * e->height / (2.0 * PL_PI * PL_PI * sin_theta);
}

/* An environment sample against the two facts that make it one (part 8): its radiance is the map's
 * in its direction, and its pdf is the density of the way it was drawn: 1 / (4 pi) for uniform
 * sampling (task 8.1), p(x, y) w h / (2 pi^2 sin(theta)) from the tables for importance sampling
 * (tasks 8.3, 8.4). A direction within 1e-4 of a texel's edge may belong to either texel (its
 * angles were rounded to floats): either one's radiance and density are right there. */
static void check_environment(trace_log *t, const light *l, const light_sample *ls)
{
    const envmap *e = l->env;
    const env_distribution *d = l->env_dist;
    vec2 c = envmap_texel_coords(e, ls->wi);
    double u = c.x, v = c.y;
    int x = (int)fmin(fmax(floor(u), 0.0), e->width - 1), y = (int)fmin(fmax(floor(v), 0.0), e->height - 1);
    /* The texel, and the one across each edge the direction is within 1e-4 of (phi wraps around). */
    int xs[2] = {x, x}, ys[2] = {y, y};
    if (u - floor(u) < 1e-4) xs[1] = (x + e->width - 1) % e->width;
    else if (ceil(u) - u < 1e-4) xs[1] = (x + 1) % e->width;
    if (v - floor(v) < 1e-4 && y > 0) ys[1] = y - 1;
    else if (ceil(v) - v < 1e-4 && y < e->height - 1) ys[1] = y + 1;
    bool radiance_ok = false, pdf_ok = false;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            rgb T = envmap_texel(e, xs[i], ys[j]);
            radiance_ok |= ls->L.r == T.r && ls->L.g == T.g && ls->L.b == T.b;
            double pdf = environment_pdf(e, d, xs[i], ys[j], ls->wi);
            /* 1e-3, and near a pole what sinf(acosf(y)) in float may cost a correct part. */
            double sin_theta = hypot(ls->wi.x, ls->wi.z) / vec3_length(ls->wi);
            pdf_ok |= fabs(ls->pdf - pdf) <= (1e-3 + 1e-6 / (sin_theta * sin_theta)) * pdf;
        }
    rgb want = envmap_texel(e, x, y);
    if (!radiance_ok)
        mark(t, "the environment sample's radiance " V3 " is not the map's in its direction, texel (%d, %d): " V3
             " (return the radiance of the direction you chose)", RGB(ls->L), x, y, RGB(want));
    if (!pdf_ok)
        mark(t, "the environment sample's pdf %.6g is not the density of its direction, %.6g (%s)", (double)ls->pdf,
             environment_pdf(e, d, x, y, ls->wi),
             d ? "texel (x, y)'s probability in the tables times w h / (2 pi^2 sin(theta)): task 8.3"
               : "uniform over the sphere: 1 / (4 pi), task 8.1");
}

void trace_light(const light *l, vec3 p, vec2 u, bool ok, const light_sample *ls)
{
    trace_log *t = pl_trace;
    const scene *s = t->ctx->scene;
    long index = l - s->lights;
    if (!ok) {
        emit(t, "light_sample", json_pack("{s:i, s:b}", "light", (int)index, "ok", 0),
             "light %ld, u = (%.5g, %.5g): contributes nothing at this point", index, (double)u.x, (double)u.y);
        return;
    }
    trace_frame *f = top(t);
    rgb c = rgb_gray(0.0f);
    float cosine = 0.0f;
    bool visible = true;
    rgb bright = rgb_gray(0.0f);  /* an f above 1/pi, or black */
    if (f && f->fn == PL_SEAM_direct_importance) {
        frame sf = shading_frame(&f->r, &f->h);
        vec3 wo = frame_to_local(&sf, vec3_neg(f->r.d)), wi = frame_to_local(&sf, ls->wi);
        cosine = wi.z;
        /* The samples this vertex takes per light: -l at the first vertex, one deeper (render.h). */
        int n = light_is_delta(l) ? 1 : render_light_samples(f->ctx, &f->r);
        ray probe = spawn_ray_to_light(&f->r, &f->h, l, ls);
        visible = !accel_occluded(t->ctx->accel, &probe);
        if (ls->pdf > 0.0f && cosine > 0.0f && f->h.material >= 0 && f->h.material < s->num_materials) {
            const material *m = &s->materials[f->h.material];
            rgb fr = material_f(m, wo, wi);
            c = rgb_scale(rgb_mul(ls->L, fr), cosine / ls->pdf / (float)n);
            bright = shades_diffuse(m) && rgb_max(fr) > 1.0001f * PL_INV_PI ? fr : bright;
        }
        if (visible) t->direct.visible = rgb_add(t->direct.visible, c);
        else t->direct.hidden = rgb_add(t->direct.hidden, c);
    }
    emit(t, "light_sample",
         json_pack("{s:i, s:b, s:o, s:o, s:o, s:o, s:o, s:b, s:o}", "light", (int)index, "ok", 1, "direction", jvec(ls->wi),
                   "distance", jnum(ls->dist), "pdf", jnum(ls->pdf), "radiance", jrgb(ls->L), "cosine",
                   jnum(cosine), "occluded", !visible, "contribution", jrgb(visible ? c : rgb_gray(0))),
         "light %ld%s: direction " V3 ", distance %.6g, pdf %.6g, radiance " V3 ", cos %.5g, %s, adds " V3, index,
         l->kind != LIGHT_ENVIRONMENT ? "" : l->env_dist ? " (the environment map, task 8.4)" : " (the environment map, task 8.1)",
         XYZ(ls->wi), (double)ls->dist, (double)ls->pdf, RGB(ls->L), (double)cosine,
         cosine <= 0.0f ? "light behind the surface (cos <= 0)" : visible ? "visible" : "occluded",
         RGB(visible ? c : rgb_gray(0)));
    if (!rgb_is_black(bright))
        mark(t, "bsdf_f is " V3 " here: a diffuse f is at most 1/pi = 0.3183, or the surface reflects more light "
             "than it receives", RGB(bright));
    if (l->kind == LIGHT_ENVIRONMENT && l->env) check_environment(t, l, ls);
}

/* A draw from the generator during part 4's path: the first four of each vertex are kept, so the
 * trace can replay material_sample_f on the same numbers (and knows whether the roulette drew). */
void trace_rng(float value)
{
    trace_path *p = &pl_trace->path;
    if (replaying || !p->active || !in(pl_trace, PL_SEAM_at_least_one_bounce_radiance) || p->draws >= 4) return;
    p->value[p->draws++] = value;
}

/* ---- the replay of part 4's path between seam calls ----------------------------------------- */

static const material *material_at(trace_log *t, const hit *h)
{
    const scene *s = t->ctx->scene;
    return h->material >= 0 && h->material < s->num_materials ? &s->materials[h->material] : NULL;
}


/* What a mirror's or glass's sample must weigh, f |cos| / pdf (part 6's handout): its reflectance
 * when it reflects (wi on wo's side), its transmittance times a radiance scale when it refracts
 * (eta^2, CS184's 1 / eta^2 or none: part 6's handout accepts each). Never R or 1 - R times that: the
 * branch's probability must cancel. */
static void check_delta_weight(trace_log *t, const material *m, vec3 wo, vec3 wi, rgb weight)
{
    if (rgb_is_black(weight)) return;  /* no direction: the path ends, nothing to weigh */
    if (wi.z * wo.z > 0.0f) {
        if (!rgb_close(weight, m->reflectance))
            mark(t, "this reflection weighs f |cos| / pdf = " V3 ", not the reflectance " V3 " (part 6, tasks 6.2 "
                 "and 6.5)", RGB(weight), RGB(m->reflectance));
        return;
    }
    float eta = wo.z > 0.0f ? 1.0f / m->ior : m->ior;
    const float scales[] = {eta * eta, 1.0f / (eta * eta), 1.0f};
    for (int i = 0; i < 3; i++)
        if (rgb_close(weight, rgb_scale(m->transmittance, scales[i]))) return;
    mark(t, "this refraction weighs f |cos| / pdf = " V3 ", not the transmittance " V3 " times eta^2 = %.4g (or 1 / eta^2, "
         "or 1) (part 6, tasks 6.4 and 6.5)", RGB(weight), RGB(m->transmittance), (double)(eta * eta));
}

/* A mirror's or glass's f and pdf are no functions of wi (material.h): the sample that sent the
 * bounce ray wi is replayed on the numbers the vertex drew, checked against wi and weighed. Its two
 * numbers are the vertex's first two draws, or the second and third where roulette drew first (both
 * orders are the part's to choose). Returns f and sets *pdf. */
static rgb delta_replay(trace_log *t, const material *m, vec3 wo, vec3 wi, float *pdf)
{
    trace_path *p = &t->path;
    rgb fr = rgb_gray(0.0f), first_fr = fr;
    vec3 said = wi, first = wi;
    float first_pdf = 0.0f;
    bool matched = false;
    for (int k = 0; k + 1 < p->draws && k < 2 && !matched; k++) {
        replaying = true;
        fr = material_sample_f(m, wo, vec2_make(p->value[k], p->value[k + 1]), &said, pdf);
        replaying = false;
        if (k == 0) {
            first = said;
            first_fr = fr;
            first_pdf = *pdf;
        }
        matched = vec3_dot(said, wi) >= 0.9999f * vec3_length(wi);
    }
    if (!matched) {
        /* Neither order sent wi: say so, and weigh the sample of the first two draws. */
        mark(t, "the bounce ray leaves along " V3 " (local) but material_sample_f sent " V3, XYZ(wi), XYZ(first));
        said = first;
        fr = first_fr;
        *pdf = first_pdf;
    }
    if (*pdf > 0.0f) check_delta_weight(t, m, wo, said, rgb_scale(fr, fabsf(said.z) / *pdf));
    return fr;
}

/* The BSDF sample that sent wi (local) from the current vertex; returns the new throughput. */
static rgb bsdf_step(trace_log *t, vec3 wo, vec3 wi, const char *how)
{
    trace_path *p = &t->path;
    const material *m = material_at(t, &p->at);
    rgb fr = rgb_gray(0.0f);
    float pdf = 0.0f;
    bool delta = m && material_is_delta(m);
    if (delta && p->draws >= 2)
        fr = delta_replay(t, m, wo, wi, &pdf);
    else if (m && !delta) {
        fr = material_f(m, wo, wi);
        pdf = material_pdf(m, wo, wi);
    }
    rgb factor = pdf > 0.0f ? rgb_scale(fr, fabsf(wi.z) / pdf) : rgb_gray(0.0f);
    rgb beta = rgb_mul(p->beta, factor);
    emit(t, "bsdf_sample",
         json_pack("{s:o, s:o, s:o, s:o, s:o}", "direction", jvec(wi), "f", jrgb(fr), "pdf", jnum(pdf), "cosine",
                   jnum(wi.z), "throughput", jrgb(beta)),
         "BSDF sample%s: direction " V3 " (local, +z the normal), f " V3 ", pdf %.6g, cos %.5g -> throughput " V3,
         how, XYZ(wi), RGB(fr), (double)pdf, (double)wi.z, RGB(beta));
    /* Light passes below a surface that transmits (glass); every other surface reflects. A diffuse
     * sampler never leaves below it; part 7's metal may draw a direction below, which it must
     * then return black, with pdf 0: the path ends there. */
    if (wi.z <= 0.0f && !p->at.transmits && m && (shades_diffuse(m) || !rgb_is_black(factor)))
        mark(t, "the bounce direction is below the surface it leaves (cos theta = %.5g)", (double)wi.z);
    if (!(pdf > 0.0f) && !rgb_is_black(fr)) mark(t, "pdf is 0 but f is " V3 " (not black)", RGB(fr));
    bool cosine_pdf = fabsf(pdf - wi.z * PL_INV_PI) <= 1e-3f * pdf;
    if (m && shades_diffuse(m) && ((cosine_pdf && rgb_max(factor) > 1.0001f) || rgb_max(fr) > 1.0001f * PL_INV_PI))
        mark(t, "throughput above 1 after a diffuse bounce: f cos / pdf = " V3 ", f = " V3 " (a diffuse f is at most 1/pi)",
             RGB(factor), RGB(fr));
    return beta;
}

/* Measures russian_roulette's rule at this vertex, whatever its convention (go on when the draw is
 * below q, or stop when it is below 1 - q: both are correct) and whenever it draws (before or after
 * the BSDF sample): replayed ROULETTE_DRAWS times with fresh generators, the probability of going on,
 * against the factor the throughput of a path that goes on is divided by. The mean stays the same
 * only when the two agree. Returns the throughput of a path that goes on. */
#define ROULETTE_DRAWS 4096

static rgb roulette(trace_log *t, rgb beta, bool went_on)
{
    trace_path *p = &t->path;
    if (p->draws < 3) return beta;  /* two draws for the direction: no roulette at this vertex */
    rgb after = beta;
    int goes = 0;
    replaying = true;
    for (int k = 0; k < ROULETTE_DRAWS; k++) {
        rgb b = beta;
        /* Independent draws (rng.h): the streams of one rng_seeded seed form a lattice, which moved
         * the sixth draw's measured probability by up to twice this check's slack. */
        rng g = rng_for_sample(0x7261636500000000ull, (uint64_t)p->bounce, (uint64_t)k);
        if (russian_roulette(&b, p->bounce + 1, &g)) goes++, after = b;
    }
    replaying = false;
    double q = (double)goes / ROULETTE_DRAWS;
    /* What the throughput of a path that goes on is divided by: before over after. */
    double divided = goes > 0 && rgb_max(after) > 0.0f ? (double)rgb_max(beta) / rgb_max(after) : NAN;
    emit(t, "roulette",
         json_pack("{s:o, s:o, s:b, s:o}", "probability", jnum((float)q), "divided_by", jnum((float)divided), "continue",
                   went_on, "throughput", jrgb(went_on ? after : rgb_gray(0))),
         "Russian roulette before bounce %d -> %s; the rule goes on with probability %.3g (measured over %d draws) "
         "and divides by %.3g", p->bounce + 1, went_on ? "continue" : "stop", q, ROULETTE_DRAWS, goes > 0 ? divided : 1.0);
    if (went_on && goes == 0)
        mark(t, "the path went on, but russian_roulette replayed with this throughput and depth ends every path");
    /* Five standard errors of the measured probability, and the draws' own step. */
    double slack = 5.0 * sqrt(q * (1.0 - q) / ROULETTE_DRAWS) + 2.0 / ROULETTE_DRAWS;
    p->gambled = p->gambled || goes < ROULETTE_DRAWS;
    if (goes > 0 && isfinite(divided) && fabs(q - divided) > slack) {
        if (divided > 0.9999 && q < 1.0 - slack)
            mark(t, "russian_roulette ends paths but does not divide the throughput of those that go on by its probability");
        else
            mark(t, "russian_roulette goes on with probability %.3g but divides the throughput by %.3g: the mean "
                 "changes unless the two are equal (handout/part4.md, 4.2)", q, divided);
    }
    if (went_on) emit(t, "throughput", json_pack("{s:o}", "throughput", jrgb(after)), "throughput / probability = " V3, RGB(after));
    return after;
}

/* A bounce ray left the vertex: the BSDF step that chose it and the roulette that let it go on. */
static void bounce_ray(trace_log *t, const ray *r)
{
    trace_path *p = &t->path;
    frame sf = shading_frame(&p->cur, &p->at);
    vec3 wo = frame_to_local(&sf, vec3_neg(p->cur.d)), wi = frame_to_local(&sf, r->d);
    p->beta = roulette(t, bsdf_step(t, wo, wi, ""), true);
    p->bounce++;  /* the ray reaches the next vertex: nothing drawn there yet */
    p->draws = 0;
}

/* The path ended: its last, unused direction replayed, then its sum against what the part returned. */
static void path_end(trace_log *t, rgb L)
{
    trace_path *p = &t->path;
    if (p->draws >= 2 && material_at(t, &p->at)) {
        /* The path ended after drawing its next direction: replay material_sample_f with those numbers. */
        frame sf = shading_frame(&p->cur, &p->at);
        vec3 wo = frame_to_local(&sf, vec3_neg(p->cur.d)), wi;
        float pdf;
        replaying = true;
        (void)material_sample_f(material_at(t, &p->at), wo, vec2_make(p->value[0], p->value[1]), &wi, &pdf);
        replaying = false;
        rgb beta = bsdf_step(t, wo, wi, " (replayed; the path ends after it)");
        roulette(t, beta, false);
    }
    p->active = false;
    /* The throughput a part hands russian_roulette is its own choice (the path's, or this bounce's
     * alone: CS184's recursion), and so is what it divides by: once roulette played, the trace's sum
     * is one correct answer of several. Its rule was checked at each vertex above. */
    if (p->gambled) {
        emit(t, "unchecked", json_pack("{s:o}", "expected", jrgb(p->expected)),
             "the bounces add up to " V3 " by the path's throughput; not checked, roulette played on this path",
             RGB(p->expected));
        return;
    }
    if (pl_todo_count() == t->stack[t->depth - 1].todo_before && !rgb_close(L, p->expected))
        mark(t, "the bounces add up to " V3 " but at_least_one_bounce_radiance returned " V3
             ": the throughput is not the product of f cos / pdf over the roulette's probabilities", RGB(p->expected), RGB(L));
}

/* ---- the driver ----------------------------------------------------------------------------- */

/* The pixel's value as the image holds it, from the same film accumulators a render uses. */
static void summary(trace_log *t, const film_pixel *px)
{
    rgb mean = film_pixel_rgb(px);
    rgb var = rgb_make((float)film_pixel_variance_of_mean(px, 0), (float)film_pixel_variance_of_mean(px, 1),
                       (float)film_pixel_variance_of_mean(px, 2));
    if (t->doc) {
        json_object_set_new(t->doc, "mean", jrgb(mean));
        json_object_set_new(t->doc, "variance_of_mean", jrgb(var));
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

/* Traces one pixel: renders it once through render_pixel (the render's own per-pixel loop) with the
 * hooks on, so every sample uses the generator stream it uses in a render: the trace shows the same
 * value the image has at that pixel. */
pl_status trace_pixel(const render_ctx *ctx, const trace_request *req, FILE *out, trace_result *result, pl_diag *diag)
{
    if (req->x < 0 || req->y < 0 || req->x >= ctx->width || req->y >= ctx->height)
        return pl_fail(diag, PL_ERR_INVALID, "--trace-pixel %d %d: outside the %dx%d image (x 0..%d, y 0..%d from the bottom-left)",
                       req->x, req->y, ctx->width, ctx->height, ctx->width - 1, ctx->height - 1);
    trace_log t = {.ctx = ctx, .req = *req, .out = out};
    if (req->json) {
        t.samples = json_array();
        t.checks = json_array();
        t.doc = json_pack("{s:s, s:[ii], s:s, s:I, s:o, s:o}", "format", "pathlab-trace-1", "pixel", req->x, req->y,
                          "command", ctx->opts->command_line ? ctx->opts->command_line : "", "seed",
                          (json_int_t)ctx->opts->seed, "samples", t.samples, "batch_checks", t.checks);
    }
    else
        fprintf(out, "pixel (%d, %d) of %s, %dx%d, seed %llu (counted from the bottom-left; lines marked !! break a rule)\n",
                req->x, req->y, ctx->scene->path, ctx->width, ctx->height, (unsigned long long)ctx->opts->seed);
    film_pixel px = {0};
    pl_trace = &t;
    render_pixel(ctx, req->x, req->y, &px);
    pl_trace = NULL;
    summary(&t, &px);
    pl_status st = PL_OK;
    if (t.doc) {
        if (json_dumpf(t.doc, out, JSON_INDENT(1)) != 0) st = pl_fail(diag, PL_ERR_IO, "--trace-format json: could not write");
        fputc('\n', out);
        json_decref(t.doc);
    }
    if (result) *result = (trace_result){px, t.marks};
    return st;
}
