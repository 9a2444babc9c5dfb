/* --trace-pixel X Y: every path of one pixel, exactly as the render computed it.
 *
 * How: the trace runs render_pixel (render.h) for the one pixel on the calling thread with this
 * thread's trace pointer (pl_trace) set, so every sample comes from the same per-(pixel, sample)
 * stream and the same code as in the render, and the traced value is the rendered value bit for
 * bit. Nothing in the parts changes: the trace is recorded at the seam (framework/seam.h). The
 * framework functions the parts call (render_intersect, render_occluded, light_sample_L,
 * rng_uniform, one_bounce_radiance) log what they return when pl_trace is set, and the framework
 * calls the parts' functions through wrappers (render.c) that log arguments and results.
 *
 * What the parts compute between two seam calls is replayed, not seen: the BSDF sample of a bounce
 * is read off the bounce ray (material_f and material_pdf evaluated at its direction), the roulette is
 * replayed with a copy of the generator's state before its draw, and the throughput is the
 * product of f |cos| / pdf over the bounces divided by the roulette's probabilities. Where the part's
 * own result disagrees with that replay, the trace says so (a "!!" line): such marks, and those
 * for values that break an invariant, are counted in trace_result.marks.
 *
 * Cost when off: one thread-local load and a branch per seam call. */
#ifndef PL_TRACE_H
#define PL_TRACE_H

#include <stdbool.h>
#include <stdio.h>
#include "render.h"
#include "light.h"
#include "seam.h"

struct trace_log;
/* This thread's trace, or NULL (always NULL in a render's worker threads). */
extern _Thread_local struct trace_log *pl_trace;

typedef struct {
    int x, y;                   /* the pixel, (0, 0) at the bottom-left like render.h's */
    int first, last;            /* samples printed: first .. last (inclusive); last < 0: all */
    bool json;                  /* one JSON document (framework/trace.schema.json) instead of text */
} trace_request;

typedef struct {
    film_pixel pixel;           /* the pixel's accumulators, as the render's film holds them */
    int marks;                  /* "!!" lines printed (invariant broken, replay disagrees, stub) */
} trace_result;

/* Traces pixel req->x, req->y of the render ctx describes, printing to out. */
pl_status trace_pixel(const render_ctx *ctx, const trace_request *req, FILE *out, trace_result *result,
                      pl_diag *diag);

/* ---- hooks: called by framework functions only when pl_trace is set ------------------------- */
void trace_sample_begin(int sample, vec2 u);
void trace_sample_end(rgb L);
void trace_enter(pl_seam_id fn, const render_ctx *ctx, const ray *r, const hit *h);
rgb trace_leave(pl_seam_id fn, rgb L);
ray trace_camera_ray(ray r);
ray trace_lens_ray(const camera *c, ray pinhole, vec2 u, ray r);  /* part 9's, beside its pinhole ray */
bool trace_converged(int n, double s1, double s2, float tol, bool verdict);
bool trace_intersect(const render_ctx *ctx, ray *r, hit *h);
bool trace_occluded(const render_ctx *ctx, const ray *r);
void trace_light(const light *l, vec3 p, vec2 u, bool ok, const light_sample *ls);
void trace_rng(float value);

#endif
