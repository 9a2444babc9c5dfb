/* The render: the estimators chosen once per render, and the tiled, multi-threaded pixel loop. */
#include "render.h"
#include "check.h"
#include "clock.h"
#include "counters.h"
#include "envmap.h"
#include "frame.h"
#include "material.h"
#include "parallel.h"
#include "spawn.h"
#include "todo.h"
#include "trace_hook.h"
#include "../parts/part1_raygen/part1.h"  /* call sites of the parts (framework/README.md) */
#include "../parts/part3_direct/part3.h"
#include "../parts/part4_global/part4.h"
#include "../parts/part5_adaptive/part5.h"
#ifdef PL_HAS_PART9  /* the thin lens, in a course that teaches it (the Makefile defines it: parts/part9_*) */
#include "../parts/part9_lens/part9.h"
#endif
#include <stdatomic.h>
#include <string.h>

#define TILE 16

rng render_rng(const render_ctx *ctx, int x, int y, int sample)
{
    uint64_t pixel = (uint64_t)y * (uint64_t)ctx->width + (uint64_t)x;
    return rng_for_sample(ctx->opts->seed, pixel, (uint64_t)sample);
}

/* Seam functions (framework/seam.h): with a trace on this thread (trace_hook.h) they log what they
 * return, and the parts' functions are called through SEAM_RGB, which logs the call and its result. */
bool render_intersect(const render_ctx *ctx, ray *r, hit *h)
{
    return pl_trace ? trace_intersect(ctx, r, h) : accel_intersect(ctx->accel, r, h);
}
bool render_occluded(const render_ctx *ctx, const ray *r)
{
    return pl_trace ? trace_occluded(ctx, r) : accel_occluded(ctx->accel, r);
}

#define SEAM_RGB(fn, ctx, r, h, call) \
    (pl_trace ? trace_leave(PL_SEAM_##fn, (trace_enter(PL_SEAM_##fn, ctx, r, h), (call))) : (call))

/* ---- direct light at one vertex -------------------------------------------------------------- */

/* Light at a mirror or glass vertex (material_is_delta). No light sample can land on the one
 * direction a delta BSDF reflects or bends light into (material_f is 0 for all of them), so the
 * vertex's direct light follows the BSDF's own sample instead: one ray, and the light it meets,
 * the emission of what it hits or the environment where it leaves the scene. A path's next vertex
 * never adds emission (part4.h), so this counts the light seen in a mirror once, as bounce k of a
 * path whose k-th vertex is the mirror: at -m 1, a mirror shows the lights it faces. */
static rgb delta_light(const render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    const material *m = &ctx->scene->materials[h->material];
    frame f = shading_frame(r, h);
    vec3 wo = frame_to_local(&f, vec3_neg(r->d)), wi;
    float pdf;
    int stubs = pl_todo_count();
    rgb fr = material_sample_f(m, wo, rng_uniform2(g), &wi, &pdf);
    if (pl_todo_count() != stubs) return rgb_magenta();  /* part 6 is a stub: show it, as every stub does */
    float cos_i = fabsf(cos_theta(wi));
    if (!(pdf > 0.0f) || rgb_is_black(fr) || cos_i == 0.0f) return rgb_gray(0.0f);

    ray next = spawn_ray(r, h, frame_to_world(&f, wi));
    hit at = {0};
    rgb Le = rgb_gray(0.0f);
    if (render_intersect(ctx, &next, &at))
        Le = SEAM_RGB(zero_bounce_radiance, ctx, &next, &at, zero_bounce_radiance(ctx, &next, &at));
    else if (ctx->scene->env)
        Le = envmap_radiance(ctx->scene->env, next.d);
    return rgb_mul(Le, rgb_scale(fr, cos_i / pdf));
}

/* Part 3's two samplers of the direct light, by the setting (-H). A test of one settled bool, not
 * a pointer to the sampler: part 4 asks here at every vertex, and a call through a pointer keeps
 * link-time optimisation from inlining part 3's estimator (measured: 17 instructions more a vertex). */
static rgb direct_light(const render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    if (material_is_delta(&ctx->scene->materials[h->material])) return delta_light(ctx, r, h, g);
    return ctx->settings.hemisphere ? SEAM_RGB(direct_hemisphere, ctx, r, h, direct_hemisphere(ctx, r, h, g))
                                    : SEAM_RGB(direct_importance, ctx, r, h, direct_importance(ctx, r, h, g));
}

rgb one_bounce_radiance(const render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return SEAM_RGB(one_bounce_radiance, ctx, r, h, direct_light(ctx, r, h, g));
}

int render_light_samples(const render_ctx *ctx, const ray *r)
{
    PL_CHECK(r->depth >= 0);
    return r->depth == 0 ? ctx->settings.light_samples : 1;
}

/* ---- the estimators of one camera ray, one of which render_ctx_init makes ctx->estimate -------- */

/* Normal shading reads h->n only and spawns no ray: the hit's refinement is skipped (the trace
 * keeps its own path, which describes the hit in full). */
static rgb estimate_normals(const render_ctx *ctx, ray *r, rng *g)
{
    (void)g;
    /* Zeroed: a hit is filled only on a hit, and with parts 2-4 stubbed link-time optimisation
     * cannot prove the shaders read it only then (it warned "used uninitialized"). */
    hit h = {0};
    bool found = pl_trace ? render_intersect(ctx, r, &h) : accel_intersect_bare(ctx->accel, r, &h);
    return found ? SEAM_RGB(normal_shade, ctx, r, &h, normal_shade(&h)) : rgb_gray(0.0f);
}

/* What a camera ray sees: emission seen directly (bounce 0, when `seen`: the bounces accumulate,
 * or bounce 0 is the one asked for), the environment map where it leaves the scene (counted as
 * bounce 0), and the light reflected at its first hit: none, one bounce of direct light, or part
 * 4's paths. Called with constants only (below), so each estimator is this body with its
 * decisions made: no sample tests a setting. */
enum { REFLECTED_NONE, REFLECTED_DIRECT, REFLECTED_PATHS };

static inline rgb estimate_surface(const render_ctx *ctx, ray *r, rng *g, bool seen, int reflected)
{
    hit h = {0};  /* zeroed: see estimate_normals */
    if (!render_intersect(ctx, r, &h))
        return seen && ctx->scene->env ? envmap_radiance(ctx->scene->env, r->d) : rgb_gray(0.0f);
    rgb L = seen ? SEAM_RGB(zero_bounce_radiance, ctx, r, &h, zero_bounce_radiance(ctx, r, &h)) : rgb_gray(0.0f);
    if (reflected == REFLECTED_DIRECT)
        L = rgb_add(L, one_bounce_radiance(ctx, r, &h, g));
    else if (reflected == REFLECTED_PATHS)
        L = rgb_add(L, SEAM_RGB(at_least_one_bounce_radiance, ctx, r, &h, at_least_one_bounce_radiance(ctx, r, &h, g)));
    return L;
}

static rgb estimate_emission(const render_ctx *ctx, ray *r, rng *g)       /* -m 0 */
{
    return estimate_surface(ctx, r, g, true, REFLECTED_NONE);
}
static rgb estimate_direct(const render_ctx *ctx, ray *r, rng *g)         /* -m 1 */
{
    return estimate_surface(ctx, r, g, true, REFLECTED_DIRECT);
}
static rgb estimate_direct_alone(const render_ctx *ctx, ray *r, rng *g)   /* -m 1 -o 0 */
{
    return estimate_surface(ctx, r, g, false, REFLECTED_DIRECT);
}
static rgb estimate_paths(const render_ctx *ctx, ray *r, rng *g)          /* -m 2 and deeper */
{
    return estimate_surface(ctx, r, g, true, REFLECTED_PATHS);
}
static rgb estimate_paths_last(const render_ctx *ctx, ray *r, rng *g)     /* -m 2 and deeper, -o 0 */
{
    return estimate_surface(ctx, r, g, false, REFLECTED_PATHS);
}

rgb radiance_estimate(const render_ctx *ctx, ray *r, rng *g)
{
    return ctx->estimate(ctx, r, g);
}

/* ---- the context: settings and estimators, decided once --------------------------------------- */

static render_estimator choose_estimator(const options *o)
{
    if (o->normals) return estimate_normals;
    if (o->max_depth <= 0) return estimate_emission;
    if (o->max_depth == 1) return o->accumulate ? estimate_direct : estimate_direct_alone;
    return o->accumulate ? estimate_paths : estimate_paths_last;
}

void render_ctx_init(render_ctx *ctx, const scene *s, const accel *a, const options *o)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->scene = s;
    ctx->accel = a;
    ctx->opts = o;
    ctx->settings = (render_settings){.max_depth = o->max_depth > 0 ? o->max_depth : 0,
                                      .accumulate = o->accumulate,
                                      .roulette = !o->no_roulette,
                                      .hemisphere = o->hemisphere,
                                      .light_samples = o->light_samples > 1 ? o->light_samples : 1};
    ctx->estimate = choose_estimator(o);
    ctx->width = o->width;
    ctx->height = o->height;
    ctx->camera = camera_for_render(s, o);
    ctx->sample_begin = o->sample_end ? o->sample_begin : 0;  /* --samples A:B, else all of -s */
    ctx->sample_end = o->sample_end ? o->sample_end : o->spp;
    ctx->x0 = o->crop ? o->crop_x0 : 0;
    ctx->y0 = o->crop ? o->crop_y0 : 0;
    ctx->x1 = o->crop ? o->crop_x1 : o->width;
    ctx->y1 = o->crop ? o->crop_y1 : o->height;
}

/* ---- the pixel loop --------------------------------------------------------------------------- */

ray render_lens_ray(const camera *c, ray pinhole, vec2 u)
{
#ifdef PL_HAS_PART9
    return thin_lens_ray(c, pinhole, u);
#else
    (void)c, (void)u;
    return pinhole;
#endif
}

/* Part 5's stopping rule on the pixel's luminance sums, through the seam. */
static bool converged(const options *o, const film_pixel *p, bool traced)
{
    double s1 = film_sum_value(p->sum[3]), s2 = film_sum_value(p->sum_sq[3]);
    bool stop = adaptive_converged((int)p->n, s1, s2, o->adaptive_tol);
    return traced ? trace_converged((int)p->n, s1, s2, o->adaptive_tol, stop) : stop;
}

/* The loop of render_pixel, and of render_pixel_traced with `traced` (a constant in each: the
 * render's copy has no hook in it, and the trace runs the same statements with them). */
static inline void pixel_loop(const render_ctx *ctx, int x, int y, film_pixel *p, bool traced)
{
    const options *o = ctx->opts;
    PL_CHECK(x >= 0 && x < ctx->width && y >= 0 && y < ctx->height && ctx->sample_begin <= ctx->sample_end);
    const bool centre = o->spp == 1;  /* one sample: the pixel's centre */
    const uint32_t batch = o->adaptive ? (uint32_t)(o->adaptive_batch > 0 ? o->adaptive_batch : 1) : 0;
    for (int s = ctx->sample_begin; s < ctx->sample_end; s++) {
        /* Everything sample s draws comes from its own stream: no dependence on threads or ranges. */
        rng g = render_rng(ctx, x, y, s);
        vec2 u = centre ? vec2_make(0.5f, 0.5f) : rng_uniform2(&g);
        if (traced) trace_sample_begin(s, u);
        ray r = pixel_sample_ray(&ctx->camera, x, y, ctx->width, ctx->height, u);
#ifdef PL_HAS_PART9
        /* A lens of some radius (-b): the pinhole ray through the lens. Its point on the lens is drawn
         * only here, so a pinhole render draws the same numbers as before the lens existed. */
        if (ctx->camera.lens_radius > 0.0f) {
            vec2 lens_u = rng_uniform2(&g);
            ray pinhole = r;
            r = render_lens_ray(&ctx->camera, pinhole, lens_u);
            if (traced) r = trace_lens_ray(&ctx->camera, pinhole, lens_u, r);
        }
#endif
        if (traced) r = trace_camera_ray(r);
        /* A ray spanning no distance is no camera ray: task 1.1 or 1.4 is still a stub (or broken).
         * Show magenta, as every missing part does, rather than a black picture. */
        rgb L = r.max_t > r.min_t ? ctx->estimate(ctx, &r, &g) : rgb_magenta();
        if (traced) trace_sample_end(L);
        film_pixel_add(p, L);
        if (batch && p->n % batch == 0 && converged(o, p, traced)) break;
    }
}

void render_pixel(const render_ctx *ctx, int x, int y, film_pixel *p)
{
    pixel_loop(ctx, x, y, p, false);
}

void render_pixel_traced(const render_ctx *ctx, int x, int y, film_pixel *p)
{
    pixel_loop(ctx, x, y, p, true);
}

/* ---- the tiled loop ------------------------------------------------------------------------- */

typedef struct {
    const render_ctx *ctx;
    film *out;              /* every pixel's accumulators, or NULL: resolve each pixel at once into */
    image *image;           /* ... its mean colour and ... */
    int *samples;           /* ... its sample count (may be NULL) */
    int tiles_x, tiles_total;
    atomic_int tiles_done;
    atomic_flag reporting;  /* held by the one thread reporting progress just now */
    _Atomic double next_report;  /* clock_seconds() before which nobody reports again */
    atomic_uint_fast64_t camera_samples;
    atomic_int bad_pixels;
    atomic_int first_bad;   /* image index of the lowest bad pixel, INT32_MAX if none */
} render_job;

/* Every PROGRESS_SECONDS at most, the thread that finishes a tile says how far the render is; one
 * thread at a time (the flag), so a progress line is never printed twice at once. */
#define PROGRESS_SECONDS 0.1

static void report_progress(render_job *job, int done)
{
    const render_ctx *ctx = job->ctx;
    double now = clock_seconds();
    if (now < atomic_load(&job->next_report) || atomic_flag_test_and_set(&job->reporting)) return;
    atomic_store(&job->next_report, now + PROGRESS_SECONDS);
    if (done < job->tiles_total) ctx->on_progress(ctx->progress_user, done, job->tiles_total);
    atomic_flag_clear(&job->reporting);
}

/* One tile's pixels, rendered by whichever thread parallel_for hands it to. */
static void render_tile(void *arg, int tile)
{
    render_job *job = arg;
    const render_ctx *ctx = job->ctx;
    int x0 = ctx->x0 + (tile % job->tiles_x) * TILE, y0 = ctx->y0 + (tile / job->tiles_x) * TILE;
    int x1 = x0 + TILE < ctx->x1 ? x0 + TILE : ctx->x1;
    int y1 = y0 + TILE < ctx->y1 ? y0 + TILE : ctx->y1;
    uint64_t samples = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            /* Pixel y counts from the bottom; the window's top row is stored first. */
            int index = (ctx->y1 - 1 - y) * (ctx->x1 - ctx->x0) + (x - ctx->x0);
            film_pixel local = {0};
            film_pixel *p = job->out ? &job->out->pixels[index] : &local;
            uint32_t before = p->n, bad_before = p->bad;
            render_pixel(ctx, x, y, p);
            if (!job->out) {
                job->image->pixels[index] = film_pixel_rgb(p);
                if (job->samples) job->samples[index] = (int)p->n;
            }
            if (p->bad > bad_before) {
                atomic_fetch_add(&job->bad_pixels, 1);
                int seen = atomic_load(&job->first_bad);
                while (index < seen && !atomic_compare_exchange_weak(&job->first_bad, &seen, index)) {}
            }
            samples += p->n - before;
        }
    atomic_fetch_add(&job->camera_samples, samples);
    int done = atomic_fetch_add(&job->tiles_done, 1) + 1;
    if (ctx->on_progress) report_progress(job, done);
}

/* The loop behind render_film and render_image: into a film, or straight into an image, on -t
 * threads (parallel_for_threads: the calling thread renders too). */
static pl_status render_run(render_job job, render_stats *stats, pl_diag *diag)
{
    (void)diag;
    const render_ctx *ctx = job.ctx;
    int w = ctx->x1 - ctx->x0, h = ctx->y1 - ctx->y0;
    job.tiles_x = (w + TILE - 1) / TILE;
    job.tiles_total = job.tiles_x * ((h + TILE - 1) / TILE);
    atomic_init(&job.tiles_done, 0);
    atomic_flag_clear(&job.reporting);
    atomic_init(&job.next_report, 0.0);
    atomic_init(&job.camera_samples, 0);
    atomic_init(&job.bad_pixels, 0);
    atomic_init(&job.first_bad, INT32_MAX);

    /* The work the render counts is what this thread's counters gain: parallel_for adds each
     * helper's to them after the join. */
    work_counts before = counters_peek();
    double t0 = clock_seconds();
    parallel_for_threads(ctx->opts->threads, job.tiles_total, render_tile, &job);
    if (ctx->on_progress) ctx->on_progress(ctx->progress_user, job.tiles_total, job.tiles_total);
    work_counts after = counters_peek();

    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->seconds = clock_seconds() - t0;
        stats->rays = after.rays - before.rays;
        stats->node_visits = after.node_visits - before.node_visits;
        stats->prim_tests = after.prim_tests - before.prim_tests;
        stats->samples = atomic_load(&job.camera_samples);
        stats->bad_pixels = atomic_load(&job.bad_pixels);
        int first = atomic_load(&job.first_bad);
        /* Report the bad pixel in the same bottom-left coordinates the estimators use. */
        stats->first_bad_x = stats->bad_pixels ? ctx->x0 + first % w : -1;
        stats->first_bad_y = stats->bad_pixels ? ctx->y1 - 1 - first / w : -1;
    }
    return PL_OK;
}

pl_status render_film(const render_ctx *ctx, film *out, render_stats *stats, pl_diag *diag)
{
    if (out->width != ctx->x1 - ctx->x0 || out->height != ctx->y1 - ctx->y0)
        return pl_fail(diag, PL_ERR_INVALID, "render_film: film is %dx%d, the render %dx%d",
                       out->width, out->height, ctx->x1 - ctx->x0, ctx->y1 - ctx->y0);
    render_job job = {.ctx = ctx, .out = out};
    return render_run(job, stats, diag);
}

/* Without a film: 144 bytes a pixel of accumulators are 69 MB at 800x600, and faulting them in
 * costs more than a normal-shaded render. A pixel's sums live on the stack while it renders, and
 * its mean goes straight to the image: the same values film_to_image would give. */
pl_status render_image(const render_ctx *ctx, image *out, int *samples_per_pixel, render_stats *stats, pl_diag *diag)
{
    if (out->width != ctx->x1 - ctx->x0 || out->height != ctx->y1 - ctx->y0)
        return pl_fail(diag, PL_ERR_INVALID, "render_image: image is %dx%d, the render %dx%d",
                       out->width, out->height, ctx->x1 - ctx->x0, ctx->y1 - ctx->y0);
    render_job job = {.ctx = ctx, .image = out, .samples = samples_per_pixel};
    return render_run(job, stats, diag);
}
