/* The render: what every estimator reads (render_ctx and its settings), the estimator chosen once
 * per render from the options, and the tiled, multi-threaded loop over pixels.
 *
 * Pixel coordinates follow CS184: pixel (x, y) has (0, 0) at the BOTTOM-left of the image and
 * covers film coordinates [x/W, (x+1)/W] x [y/H, (y+1)/H]. The loop stores pixel (x, y) in image
 * row H - 1 - y, since image files are written top row first.
 * Parts may not call: render_ctx_init, render_rng, render_lens_ray, render_pixel, render_pixel_traced,
 * render_film, render_image (the grader refuses them; the functions marked PL_PART_API are theirs). */
#ifndef PL_RENDER_H
#define PL_RENDER_H

#include "part_api.h"

#include <stdint.h>
#include "scene.h"
#include "options.h"
#include "accel.h"
#include "image.h"
#include "rng.h"
#include "film.h"

/* What the estimators read of the options, copied once per render by render_ctx_init: part 4's
 * path loop and the framework's light policy read these, never the options struct, so a part's
 * contract is these five numbers and not the command line's fifty. */
typedef struct {
    int max_depth;         /* -m: the deepest bounce computed (0: emission seen directly only) */
    bool accumulate;       /* -o 1: bounces 1 .. max_depth all kept; -o 0: only bounce max_depth */
    bool roulette;         /* Russian roulette may end paths early (false under --no-rr) */
    bool hemisphere;       /* -H: direct light by uniform hemisphere sampling, else by light sampling */
    int light_samples;     /* -l: samples per area light where a camera ray lands, at least 1 */
} render_settings;

struct render_ctx;
/* One camera ray's radiance (render_ctx.estimate): which one is decided once per render. */
typedef rgb (*render_estimator)(const struct render_ctx *ctx, ray *r, rng *g);

typedef struct render_ctx {
    const scene *scene;    /* not owned */
    const accel *accel;    /* not owned */
    const options *opts;   /* not owned: the loop's own choices (threads, samples, adaptive); no estimator reads it */
    render_settings settings;  /* what the estimators read (above) */
    render_estimator estimate; /* chosen by render_ctx_init from the settings: radiance_estimate calls it */
    camera camera;         /* the scene's camera with aspect, framing and lens flags applied */
    int width, height;     /* pixels */
    /* The camera samples to take of every pixel: sample_begin .. sample_end - 1 (--samples A:B;
     * 0 .. opts->spp by default). Sample s is the same whatever range it is rendered in. */
    int sample_begin, sample_end;
    /* The window rendered: pixels x0 <= x < x1, y0 <= y < y1 (--crop; the whole image by default).
     * Cameras and random streams are the whole image's, so each pixel is the same as in a full
     * render; the film or image rendered into is the window's size, top row first. */
    int x0, y0, x1, y1;
    /* Progress reports while the render runs, from the thread that finished a tile (one at a
     * time, at most every 0.1 s), and once more at the end; NULL for none. */
    void (*on_progress)(void *user, int tiles_done, int tiles_total);
    void *progress_user;
} render_ctx;

/* Fills ctx from its parts; the camera is camera_for_render's (camera.h): the scene's (or the
 * default framing), aspect from width/height or CS184's framing, and the -b / -d lens when given.
 * The settings are o's, and the estimator is chosen here, once: no sample of the render asks the
 * options again. */
void render_ctx_init(render_ctx *ctx, const scene *s, const accel *a, const options *o);

/* The RNG stream of one camera sample: seeded from (opts->seed, pixel index, sample index). */
rng render_rng(const render_ctx *ctx, int x, int y, int sample);

/* Closest hit and shadow queries through the accelerator (BVH or linear scan). */
PL_PART_API bool render_intersect(const render_ctx *ctx, ray *r, hit *h);
PL_PART_API bool render_occluded(const render_ctx *ctx, const ray *r);

/* Radiance arriving along camera ray r (CS184's est_radiance_global_illumination), by the estimator
 * render_ctx_init chose: --normals -> normal_shade; -m 0 -> zero bounce; -m 1 -> zero bounce +
 * direct light; deeper -> zero bounce + at_least_one_bounce_radiance. With -o 0 only the bounce at
 * depth -m is kept. A miss sees the environment map where bounce 0 counts, else black. */
PL_PART_API rgb radiance_estimate(const render_ctx *ctx, ray *r, rng *g);

/* Direct light at a hit by the sampler the settings pick (-H: hemisphere, else light importance).
 * At a mirror or glass (material_is_delta, part 6) it follows the BSDF's sample instead: one ray,
 * adding the emission it meets (render.c says why). */
PL_PART_API rgb one_bounce_radiance(const render_ctx *ctx, const ray *r, const hit *h, rng *g);

/* The ray through the lens at u in [0,1)^2 of the sample whose pinhole ray is `pinhole`: part 9's
 * thin_lens_ray where the course has part 9, else the pinhole ray itself. The pixel loop's own call
 * of it, for the trace's measure of the lens (trace_density.c). */
ray render_lens_ray(const camera *c, ray pinhole, vec2 u);

/* Samples per area light at the surface that ray r reached: all -l of them (settings.light_samples,
 * at least 1) where a camera ray lands (r->depth == 0), one at every deeper vertex of a path. There
 * the noise of the path itself (which way it bounced, whether roulette kept it) dwarfs that of the
 * light sample, so more shadow rays buy almost nothing: on the Cornell bunny at -s 64 -l 4 -m 5
 * this takes about a quarter less time than -l everywhere for the same relMSE. Part 3's estimators
 * ask here, so the policy is the framework's and part 4 only sets each bounce ray's depth. */
PL_PART_API int render_light_samples(const render_ctx *ctx, const ray *r);

typedef struct {
    double seconds;         /* wall time of the pixel loop */
    uint64_t rays;          /* rays traced (camera, bounce, shadow) */
    uint64_t node_visits;   /* BVH nodes handed out by bvh_visit (0 for the linear scan) */
    uint64_t prim_tests;    /* primitive tests through scene_prim_intersect */
    uint64_t samples;       /* camera samples taken, all pixels */
    int bad_pixels;         /* pixels with a NaN, Inf, negative or huge sample (film.h) */
    int first_bad_x, first_bad_y;
} render_stats;

/* The per-pixel sample loop, the one place that takes camera samples. For each sample s of the
 * ctx's range: g = render_rng(ctx, x, y, s); u = the pixel centre (0.5, 0.5) when opts->spp == 1,
 * else rng_uniform2(&g); the ray from part 1's pixel_sample_ray; L = radiance_estimate; added to
 * p. With -a B T it asks part 5's adaptive_converged after every B samples (counted from 0) and
 * stops when it says so; it never goes past sample_end, so the last batch may be shorter. */
void render_pixel(const render_ctx *ctx, int x, int y, film_pixel *p);
/* The same loop, the same code, with the trace's hooks (trace_hook.h) at each step: what
 * --trace-pixel runs (trace.c). The render's loop carries no test for them. */
void render_pixel_traced(const render_ctx *ctx, int x, int y, film_pixel *p);

/* Renders every pixel's samples into out (film_alloc'ed by the caller at the window's size,
 * ctx->x1 - ctx->x0 by ctx->y1 - ctx->y0, zeroed) with opts->threads threads. The same bytes for any thread count. */
pl_status render_film(const render_ctx *ctx, film *out, render_stats *stats, pl_diag *diag);

/* render_film, then the image of the means into out (allocated by the caller at the window's
 * size). samples_per_pixel (may be NULL) receives the camera samples each pixel took,
 * indexed like the image (top row first). */
pl_status render_image(const render_ctx *ctx, image *out, int *samples_per_pixel, render_stats *stats, pl_diag *diag);

#endif
