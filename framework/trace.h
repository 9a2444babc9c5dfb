/* --trace-pixel X Y: every path of one pixel, exactly as the render computed it.
 *
 * How: the trace runs the render's own pixel loop (render_pixel_traced, render.h) for the one
 * pixel on the calling thread with this thread's trace pointer (pl_trace, trace_hook.h) set, so
 * every sample comes from the same per-(pixel, sample) stream and the same code as in the render,
 * and the traced value is the rendered value bit for bit. Nothing in the parts changes: the trace
 * is recorded at the seam (framework/seam.h). The framework functions the parts call
 * (render_intersect, render_occluded, light_sample_L, rng_uniform, one_bounce_radiance) report what
 * they return when pl_trace is set, and the framework calls the parts' functions through wrappers
 * (render.c) that report arguments and results: trace_hook.h lists the hooks.
 *
 * What the parts compute between two seam calls is replayed, not seen: the BSDF sample of a bounce
 * is read off the bounce ray (material_f and material_pdf evaluated at its direction), the roulette is
 * replayed on fresh generators, and the throughput is the product of f |cos| / pdf over the bounces
 * divided by the roulette's probabilities. Where the part's own result disagrees with that replay,
 * the trace says so (a "!!" line): such marks, and those for values that break an invariant, are
 * counted in trace_result.marks.
 *
 * What it measures besides: where a part samples (a BSDF at a vertex, the environment map, the
 * lens), the sampler's pdf against the distribution of its own samples drawn there, by a chi-square
 * test at level TRACE_DENSITY_ALPHA (trace_density.c), a few times a trace. Bugs that keep an
 * estimator consistent with itself and its samples (a wrong f that stays plausible) it cannot see:
 * the grader's images can (handout/README.md, "What a trace cannot see").
 *
 * The trace's modules and what they share: trace_internal.h.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_TRACE_H
#define PL_TRACE_H

#include <stdbool.h>
#include <stdio.h>
#include "render.h"

/* One density check's level: a correct sampler is marked with at most this probability. A trace
 * makes at most TRACE_DENSITY_CHECKS of them, so a correct trace is marked by one at most once in
 * 1 / (TRACE_DENSITY_ALPHA x TRACE_DENSITY_CHECKS) = 100,000 traces. */
#define TRACE_DENSITY_ALPHA 1e-6
#define TRACE_DENSITY_CHECKS 10

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

#endif
