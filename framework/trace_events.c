/* --trace-pixel's events: the hooks trace_hook.h declares, implemented. Each report from the seam
 * becomes one or more lines of the tree (trace_print.c) and hands its numbers to the referee
 * (trace_referee.c) and the density checks (trace_density.c). framework/trace.h explains the approach.
 * Test machinery: not part of any assignment. */
#include "trace_internal.h"
#include "accel.h"
#include "frame.h"
#include "spawn.h"
#include "todo.h"
#include <math.h>

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

/* ---- the pixel loop --------------------------------------------------------------------------- */

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
    trace_emit(t, "sample", NULL, "sample %d: offset in the pixel u = (%.5g, %.5g)", sample, (double)u.x, (double)u.y);
    t->depth = 0;
}

void trace_sample_end(rgb L)
{
    trace_log *t = pl_trace;
    t->depth = 0;
    trace_check_radiance(t, "the sample's value", L);
    trace_emit(t, "value", json_pack("{s:o}", "value", trace_jrgb(L)), "sample %d's value: " V3, t->sample, RGB(L));
    if (t->doc && t->events) {
        json_object_set_new(json_array_get(t->samples, json_array_size(t->samples) - 1), "value", trace_jrgb(L));
        t->events = NULL;
    }
    t->recording = false;
}

ray trace_camera_ray(ray r)
{
    trace_log *t = pl_trace;
    trace_emit(t, "camera_ray",
               json_pack("{s:o, s:o, s:o, s:o}", "origin", trace_jpoint(t, r.o), "direction", trace_jvec(r.d), "min_t",
                         trace_jnum(r.min_t), "max_t", trace_jnum(r.max_t)),
               "camera ray from " V3 " along " V3 ", t in [%.5g, %.5g]", PXYZ(r.o), XYZ(r.d), (double)r.min_t,
               (double)r.max_t);
    if (!(r.max_t > r.min_t))
        trace_mark(t, "the camera ray spans no distance: %s is a stub or broken",
                   t->camera_ray_by ? t->camera_ray_by : "pixel_sample_ray or camera_generate_ray");
    t->camera_ray_by = NULL;
    return r;
}

/* Part 9's lens ray: its facts (the referee), and once a trace its points' spread (the density). */
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
    referee_lens_ray(t, c, pinhole, u, r);
    if (t->recording && !t->density.lens) density_check_lens(t, c, pinhole);
    return r;
}

bool trace_converged(int n, double s1, double s2, float tol, bool verdict)
{
    referee_converged(pl_trace, n, s1, s2, tol, verdict);
    return verdict;
}

/* ---- the part functions the framework calls ---------------------------------------------------- */

/* The framework is about to call part function fn: a line naming it and its task, a frame on the
 * stack, and the replays it starts (a path for part 4, a sum of samples for tasks 3.4 and 3.5). */
void trace_enter(pl_seam_id fn, const render_ctx *ctx, const ray *r, const hit *h)
{
    trace_log *t = pl_trace;
    if (fn == PL_SEAM_one_bounce_radiance && t->path.active && trace_in(t, PL_SEAM_at_least_one_bounce_radiance)) {
        trace_emit(t, "bounce", json_pack("{s:i, s:o}", "bounce", t->path.bounce, "throughput", trace_jrgb(t->path.beta)),
                   "bounce %d: direct light at this vertex, throughput " V3, t->path.bounce, RGB(t->path.beta));
    }
    else if (fn != PL_SEAM_one_bounce_radiance)
        trace_emit(t, "call", json_pack("{s:s, s:s}", "function", seam_names[fn], "task", seam_tasks[fn]),
                   "%s (task %s):", seam_names[fn], seam_tasks[fn]);
    else if (!material_is_delta(&ctx->scene->materials[h->material]))
        trace_emit(t, "call", json_pack("{s:s}", "function", seam_names[fn]),
                   "one_bounce_radiance (the framework's: -H picks direct_hemisphere, else direct_importance):");
    else
        trace_emit(t, "call", json_pack("{s:s}", "function", seam_names[fn]),
                   "one_bounce_radiance (the framework's: at a mirror or glass it follows material_sample_f's direction "
                   "and adds the light that ray meets):");
    if (t->depth >= MAX_NEST) return;
    /* The frame keeps copies: a part may reuse its ray and hit once the call returns. */
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
        trace_mark(t, "stub: %s is not implemented yet (its placeholder answer is used)", pl_todo_last());
    if (now > t->stubs_marked) t->stubs_marked = now;
}

/* Part function fn returned L: the referee's checks, its line, and (for one bounce of a path) what
 * the bounce adds to the path's expected sum. */
rgb trace_leave(pl_seam_id fn, rgb L)
{
    trace_log *t = pl_trace;
    if (t->depth == 0) return L;
    trace_frame *f = trace_top(t);
    stub_mark(t, f);
    /* The referee's checks come before the return's line, so a mark sits inside the call it judges. */
    if (fn == PL_SEAM_at_least_one_bounce_radiance) referee_path_end(t, L);
    if ((fn == PL_SEAM_direct_importance || fn == PL_SEAM_direct_hemisphere) && pl_todo_count() == f->todo_before)
        referee_direct(t, fn, L);
    trace_check_radiance(t, seam_names[fn], L);
    if (fn != PL_SEAM_one_bounce_radiance)  /* it returns what direct_* returned, shown already */
        trace_emit(t, "return", json_pack("{s:s, s:o}", "function", seam_names[fn], "value", trace_jrgb(L)),
                   "%s returns " V3, seam_names[fn], RGB(L));
    t->depth--;
    if (fn == PL_SEAM_one_bounce_radiance && t->path.active && trace_in(t, PL_SEAM_at_least_one_bounce_radiance))
        referee_bounce_added(t, L);
    return L;
}

/* ---- framework functions the parts call ------------------------------------------------------- */

/* A ray a part traces (render_intersect), named by the call it comes from: a camera ray, a bounce
 * ray of part 4's path, a hemisphere ray of task 3.4. */
bool trace_intersect(const render_ctx *ctx, ray *r, hit *h)
{
    trace_log *t = pl_trace;
    const char *role = "camera ray";
    if (trace_in(t, PL_SEAM_at_least_one_bounce_radiance) && t->path.active) {
        referee_bounce_ray(t, r);
        role = "bounce ray";
    }
    else if (trace_in(t, PL_SEAM_direct_hemisphere)) {
        trace_frame *f = trace_top(t);
        frame sf = shading_frame(&f->r, &f->h);
        vec3 wi = frame_to_local(&sf, r->d);
        role = "hemisphere ray";
        if (wi.z < 0.0f) trace_mark(t, "this ray leaves below the surface (cos theta = %.5g)", (double)wi.z);
    }
    else if (t->depth)
        role = "ray";
    /* The same query render_intersect makes without a trace: the traced hit is the rendered one. */
    bool found = accel_intersect(ctx->accel, r, h);
    trace_describe_hit(t, role, r, found, h);
    if (found && trace_in(t, PL_SEAM_direct_hemisphere)) referee_hemisphere_hit(t, r, h);
    /* A bounce ray's hit is the path's next vertex: where its next BSDF sample is replayed. */
    if (role[0] == 'b') {
        t->path.cur = *r;
        if (found) t->path.at = *h;
    }
    return found;
}

/* What blocks a shadow ray, in words: the nearest primitive on the segment, and how far along it
 * (a blocker at distance 0 is the surface the ray started on, self-shadowing). */
static void describe_blocker(const render_ctx *ctx, const ray *r, char *what, size_t size, int *prim, float *dist)
{
    ray probe = *r;
    hit h = {0};
    const scene *s = ctx->scene;
    if (!accel_intersect(ctx->accel, &probe, &h) || h.prim < 0 || h.prim >= scene_prim_count(s)) {
        snprintf(what, size, "occluded");
        return;
    }
    *prim = h.prim;
    *dist = h.t * vec3_length(r->d);
    bool tri = h.prim < s->num_triangles;
    const char *name = h.material >= 0 && h.material < s->num_materials ? s->materials[h.material].name : "?";
    snprintf(what, size, "occluded by %s %d (material \"%s\") at distance %.6g%s", tri ? "triangle" : "sphere", h.prim,
             name, (double)*dist, *dist < 1e-4f * (1.0f + vec3_length(r->o)) ?
             ": the surface it starts on? (a ray from the raw hit point)" : "");
}

/* A shadow ray a part traces (render_occluded), with its verdict: when blocked, by what; when
 * clear, that it reaches the light. */
bool trace_occluded(const render_ctx *ctx, const ray *r)
{
    trace_log *t = pl_trace;
    /* The verdict is the render's own query; the blocker is looked up only to name it. */
    bool blocked = accel_occluded(ctx->accel, r);
    char what[200] = "clear: it reaches the light";
    int prim = -1;
    float dist = 0.0f;
    if (blocked) describe_blocker(ctx, r, what, sizeof what, &prim, &dist);
    json_t *j = json_pack("{s:o, s:o, s:o, s:o, s:b, s:i, s:o}", "origin", trace_jpoint(t, r->o), "direction",
                          trace_jvec(r->d), "min_t", trace_jnum(r->min_t), "max_t", trace_jnum(r->max_t), "occluded",
                          blocked, "blocker", prim, "blocker_distance", trace_jnum(dist));
    /* A shadow ray towards a light at a finite distance (point, spot, area) is a segment
     * (spawn_ray_to_light: t in (0, 1], an unnormalised direction) whose far end stops just short
     * of the light: shown by its two ends and its length, which is what a student can check. */
    if (isfinite(r->max_t)) {
        vec3 end = vec3_add(r->o, vec3_scale(r->d, r->max_t));
        trace_emit(t, "shadow_ray", j, "shadow ray from " V3 " to " V3 " (length %.6g): %s", PXYZ(r->o), PXYZ(end),
                   (double)(vec3_length(r->d) * r->max_t), what);
    }
    else
        trace_emit(t, "shadow_ray", j, "shadow ray from " V3 " along " V3 " (no far end): %s", PXYZ(r->o),
                   XYZ(vec3_normalize(r->d)), what);
    return blocked;
}

/* One light sample, with what it adds by the framework's own visibility test (the referee), and
 * for the environment map its facts and, once a trace, its sampler's density. */
void trace_light(const light *l, vec3 p, vec2 u, bool ok, const light_sample *ls)
{
    trace_log *t = pl_trace;
    const scene *s = t->ctx->scene;
    long index = l - s->lights;
    if (!ok) {
        trace_emit(t, "light_sample", json_pack("{s:i, s:b}", "light", (int)index, "ok", 0),
                   "light %ld, u = (%.5g, %.5g): contributes nothing at this point", index, (double)u.x, (double)u.y);
        return;
    }
    float cosine = 0.0f;
    bool visible = true;
    rgb bright = rgb_gray(0.0f);
    rgb c = referee_light_sample(t, l, ls, &cosine, &visible, &bright);
    trace_emit(t, "light_sample",
               json_pack("{s:i, s:b, s:o, s:o, s:o, s:o, s:o, s:b, s:o}", "light", (int)index, "ok", 1, "direction",
                         trace_jvec(ls->wi), "distance", trace_jnum(ls->dist), "pdf", trace_jnum(ls->pdf), "radiance",
                         trace_jrgb(ls->L), "cosine", trace_jnum(cosine), "occluded", !visible, "contribution",
                         trace_jrgb(visible ? c : rgb_gray(0))),
               "light %ld%s: direction " V3 ", distance %.6g, pdf %.6g, radiance " V3 ", cos %.5g, %s, adds " V3, index,
               l->kind != LIGHT_ENVIRONMENT ? "" : l->env_dist ? " (the environment map, task 8.4)" : " (the environment map, task 8.1)",
               XYZ(ls->wi), (double)ls->dist, (double)ls->pdf, RGB(ls->L), (double)cosine,
               cosine <= 0.0f ? "light behind the surface (cos <= 0)" : visible ? "visible" : "occluded",
               RGB(visible ? c : rgb_gray(0)));
    referee_diffuse_bound(t, bright);
    if (l->kind == LIGHT_ENVIRONMENT && l->env) {
        referee_environment(t, l, ls);
        if (t->recording && !t->density.environment) density_check_environment(t, l);
    }
}

/* A draw from the generator during part 4's path: the first four of each vertex are kept, so the
 * trace can replay material_sample_f on the same numbers (and knows whether the roulette drew). */
void trace_rng(float value)
{
    trace_path *p = &pl_trace->path;
    if (trace_replaying || !p->active || !trace_in(pl_trace, PL_SEAM_at_least_one_bounce_radiance) || p->draws >= 4) return;
    p->value[p->draws++] = value;
}
