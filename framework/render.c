/* The render: estimator dispatch and the tiled, multi-threaded pixel loop. */
#include "render.h"
#include "check.h"
#include "clock.h"
#include "counters.h"
#include "envmap.h"
#include "frame.h"
#include "material.h"
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
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TILE 16

void render_ctx_init(render_ctx *ctx, const scene *s, const accel *a, const options *o)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->scene = s;
    ctx->accel = a;
    ctx->opts = o;
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

rng render_rng(const render_ctx *ctx, int x, int y, int sample)
{
    uint64_t pixel = (uint64_t)y * (uint64_t)ctx->width + (uint64_t)x;
    return rng_for_sample(ctx->opts->seed, pixel, (uint64_t)sample);
}

/* Seam functions (framework/seam.h): with a trace on this thread (trace.h) they log what they
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

static rgb direct_light(const render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    if (material_is_delta(&ctx->scene->materials[h->material])) return delta_light(ctx, r, h, g);
    return ctx->opts->hemisphere ? SEAM_RGB(direct_hemisphere, ctx, r, h, direct_hemisphere(ctx, r, h, g))
                                 : SEAM_RGB(direct_importance, ctx, r, h, direct_importance(ctx, r, h, g));
}

rgb one_bounce_radiance(const render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return SEAM_RGB(one_bounce_radiance, ctx, r, h, direct_light(ctx, r, h, g));
}

int render_light_samples(const render_ctx *ctx, const ray *r)
{
    PL_CHECK(r->depth >= 0);
    int asked = ctx->opts->light_samples;
    return r->depth == 0 && asked > 1 ? asked : 1;
}

rgb radiance_estimate(const render_ctx *ctx, ray *r, rng *g)
{
    /* Zeroed: a hit is filled only on a hit, and with parts 2-4 stubbed link-time optimisation
     * cannot prove the shaders read it only then (it warned "used uninitialized"). */
    hit h = {0};
    const options *o = ctx->opts;
    /* Normal shading reads h->n only and spawns no ray: the hit's refinement is skipped (the trace
     * keeps its own path, which describes the hit in full). */
    bool found = o->normals && !pl_trace ? accel_intersect_bare(ctx->accel, r, &h) : render_intersect(ctx, r, &h);
    if (o->normals) return found ? SEAM_RGB(normal_shade, ctx, r, &h, normal_shade(&h)) : rgb_gray(0.0f);
    /* A ray that leaves the scene sees the environment map, if any: emission seen directly, counted
     * when zero_bounce_radiance's would be. */
    if (!found)
        return ctx->scene->env && (o->accumulate || o->max_depth == 0) ? envmap_radiance(ctx->scene->env, r->d)
                                                                      : rgb_gray(0.0f);

    /* Emission seen directly counts when bounces accumulate, or when it is the only bounce asked for. */
    rgb L = (o->accumulate || o->max_depth == 0) ? SEAM_RGB(zero_bounce_radiance, ctx, r, &h, zero_bounce_radiance(ctx, r, &h))
                                                   : rgb_gray(0.0f);
    if (o->max_depth == 1)
        L = rgb_add(L, one_bounce_radiance(ctx, r, &h, g));
    else if (o->max_depth >= 2)
        L = rgb_add(L, SEAM_RGB(at_least_one_bounce_radiance, ctx, r, &h, at_least_one_bounce_radiance(ctx, r, &h, g)));
    return L;
}

/* Part 5's stopping rule on the pixel's luminance sums, through the seam. */
static bool converged(const options *o, const film_pixel *p)
{
    double s1 = film_sum_value(p->sum[3]), s2 = film_sum_value(p->sum_sq[3]);
    bool stop = adaptive_converged((int)p->n, s1, s2, o->adaptive_tol);
    return pl_trace ? trace_converged((int)p->n, s1, s2, o->adaptive_tol, stop) : stop;
}

void render_pixel(const render_ctx *ctx, int x, int y, film_pixel *p)
{
    const options *o = ctx->opts;
    PL_CHECK(x >= 0 && x < ctx->width && y >= 0 && y < ctx->height && ctx->sample_begin <= ctx->sample_end);
    int batch = o->adaptive_batch > 0 ? o->adaptive_batch : 1;
    for (int s = ctx->sample_begin; s < ctx->sample_end; s++) {
        /* Everything sample s draws comes from its own stream: no dependence on threads or ranges. */
        rng g = render_rng(ctx, x, y, s);
        vec2 u = o->spp == 1 ? vec2_make(0.5f, 0.5f) : rng_uniform2(&g);  /* one sample: the centre */
        if (pl_trace) trace_sample_begin(s, u);
        ray r = pixel_sample_ray(&ctx->camera, x, y, ctx->width, ctx->height, u);
#ifdef PL_HAS_PART9
        /* A lens of some radius (-b): the pinhole ray through the lens. Its point on the lens is drawn
         * only here, so a pinhole render draws the same numbers as before the lens existed. */
        if (ctx->camera.lens_radius > 0.0f) {
            vec2 lens_u = rng_uniform2(&g);
            ray pinhole = r;
            r = thin_lens_ray(&ctx->camera, pinhole, lens_u);
            if (pl_trace) r = trace_lens_ray(&ctx->camera, pinhole, lens_u, r);
        }
#endif
        if (pl_trace) r = trace_camera_ray(r);
        /* A ray spanning no distance is no camera ray: task 1.1 or 1.4 is still a stub (or broken).
         * Show magenta, as every missing part does, rather than a black picture. */
        rgb L = r.max_t > r.min_t ? radiance_estimate(ctx, &r, &g) : rgb_magenta();
        if (pl_trace) trace_sample_end(L);
        film_pixel_add(p, L);
        if (o->adaptive && p->n % (uint32_t)batch == 0 && converged(o, p)) break;
    }
}

/* ---- the tiled loop ------------------------------------------------------------------------- */

typedef struct {
    const render_ctx *ctx;
    film *out;              /* every pixel's accumulators, or NULL: resolve each pixel at once into */
    image *image;           /* ... its mean colour and ... */
    int *samples;           /* ... its sample count (may be NULL) */
    int tiles_x, tiles_total;
    atomic_int next_tile;   /* tiles are handed out in order; any thread may take any tile */
    atomic_int tiles_done;
    atomic_uint_fast64_t rays, node_visits, prim_tests, camera_samples;
    atomic_int bad_pixels;
    atomic_int first_bad;   /* image index of the lowest bad pixel, INT32_MAX if none */
} render_job;

static void render_tile(render_job *job, int tile)
{
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
}

static void *render_worker(void *arg)
{
    render_job *job = arg;
    (void)counters_take();  /* start this thread's counts from zero */
    for (;;) {
        int tile = atomic_fetch_add(&job->next_tile, 1);
        if (tile >= job->tiles_total) break;
        render_tile(job, tile);
        atomic_fetch_add(&job->tiles_done, 1);
    }
    work_counts work = counters_take();
    atomic_fetch_add(&job->rays, work.rays);
    atomic_fetch_add(&job->node_visits, work.node_visits);
    atomic_fetch_add(&job->prim_tests, work.prim_tests);
    return NULL;
}

/* The loop behind render_film and render_image: into a film, or straight into an image. */
static pl_status render_run(render_job job, render_stats *stats, pl_diag *diag)
{
    const render_ctx *ctx = job.ctx;
    int w = ctx->x1 - ctx->x0, h = ctx->y1 - ctx->y0;
    job.tiles_x = (w + TILE - 1) / TILE;
    job.tiles_total = job.tiles_x * ((h + TILE - 1) / TILE);
    atomic_init(&job.next_tile, 0);
    atomic_init(&job.tiles_done, 0);
    atomic_init(&job.rays, 0);
    atomic_init(&job.node_visits, 0);
    atomic_init(&job.prim_tests, 0);
    atomic_init(&job.camera_samples, 0);
    atomic_init(&job.bad_pixels, 0);
    atomic_init(&job.first_bad, INT32_MAX);

    int nthreads = ctx->opts->threads > 0 ? ctx->opts->threads : 1;
    pthread_t *threads = calloc((size_t)nthreads, sizeof *threads);
    if (!threads) return pl_fail(diag, PL_ERR_NOMEM, "render: out of memory");
    double t0 = clock_seconds();
    int started = 0;
    for (; started < nthreads; started++)
        if (pthread_create(&threads[started], NULL, render_worker, &job) != 0) break;
    if (started == 0) render_worker(&job);  /* no thread could start: render on this one */

    /* The calling thread reports progress until the workers finish. */
    while (ctx->on_progress && atomic_load(&job.tiles_done) < job.tiles_total && started > 0) {
        ctx->on_progress(ctx->progress_user, atomic_load(&job.tiles_done), job.tiles_total);
        struct timespec pause = {0, 100 * 1000 * 1000};
        nanosleep(&pause, NULL);
    }
    for (int i = 0; i < started; i++) pthread_join(threads[i], NULL);
    free(threads);
    if (ctx->on_progress) ctx->on_progress(ctx->progress_user, job.tiles_total, job.tiles_total);

    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->seconds = clock_seconds() - t0;
        stats->rays = atomic_load(&job.rays);
        stats->node_visits = atomic_load(&job.node_visits);
        stats->prim_tests = atomic_load(&job.prim_tests);
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
