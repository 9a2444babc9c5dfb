/* The trace's hooks: all that the render code knows of --trace-pixel (trace.h).
 *
 * The seam's framework functions (render_intersect, render_occluded, light_sample_L, rng_uniform,
 * one_bounce_radiance: framework/seam.h) and the traced pixel loop (render_pixel_traced) report
 * here when this thread's pl_trace is set; the trace's modules (trace_events.c and its neighbours)
 * turn the reports into the printed tree and its checks. This header names the structs it passes
 * without their headers, so the random generator, the lights and the render loop include only it,
 * and no framework module the trace itself reads leads back to the trace.
 *
 * Cost when off: one thread-local load and a predicted branch per seam call.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_TRACE_HOOK_H
#define PL_TRACE_HOOK_H

#include <stdbool.h>
#include "vec.h"
#include "ray.h"
#include "seam.h"

/* Every hook is out of line and cold: it runs only under --trace-pixel, and inlined into the
 * render's hot functions (light_sample_L into part 3's estimator, with the trace's checks behind
 * it) it cost the render's own code 0.15% more instructions by register pressure alone. */
#if defined(__GNUC__)
#define TRACE_HOOK __attribute__((cold, noinline))
#else
#define TRACE_HOOK
#endif

struct trace_log;
struct render_ctx;
struct camera;
struct light;
struct light_sample;

/* This thread's trace, or NULL (always NULL in a render's worker threads). */
extern _Thread_local struct trace_log *pl_trace;

/* ---- the pixel loop (render_pixel_traced) ----------------------------------------------------- */
TRACE_HOOK void trace_sample_begin(int sample, vec2 u);
TRACE_HOOK void trace_sample_end(rgb L);
TRACE_HOOK ray trace_camera_ray(ray r);
TRACE_HOOK ray trace_lens_ray(const struct camera *c, ray pinhole, vec2 u, ray r);  /* part 9's, beside its pinhole ray */
TRACE_HOOK bool trace_converged(int n, double s1, double s2, float tol, bool verdict);

/* ---- around each part function the framework calls (render.c's SEAM_RGB) -------------------- */
TRACE_HOOK void trace_enter(pl_seam_id fn, const struct render_ctx *ctx, const ray *r, const hit *h);
TRACE_HOOK rgb trace_leave(pl_seam_id fn, rgb L);

/* ---- framework functions the parts call ------------------------------------------------------ */
TRACE_HOOK bool trace_intersect(const struct render_ctx *ctx, ray *r, hit *h);
TRACE_HOOK bool trace_occluded(const struct render_ctx *ctx, const ray *r);
TRACE_HOOK void trace_light(const struct light *l, vec3 p, vec2 u, bool ok, const struct light_sample *ls);
TRACE_HOOK void trace_rng(float value);

#endif
