/* --trace-pixel's driver: one pixel through the render's own loop with the hooks on, then its
 * value. framework/trace.h explains the approach, trace_internal.h the modules.
 *
 * How to read the trace: render.c calls trace_enter and trace_leave around every part function it
 * calls, and the framework functions the parts call (intersection, shadow rays, light samples, the
 * random generator) report to trace_intersect, trace_occluded, trace_light and trace_rng
 * (trace_events.c). From those reports the trace prints one line per event, nested by the calls
 * (trace_print.c), and recomputes what a correct part would have returned from the same numbers
 * (trace_referee.c) and whether each sampler's pdf is the density of its samples (trace_density.c):
 * a line marked !! is a place where the two disagree. The trace runs the very render code on one
 * pixel, so it shows what the render computed, not a model. */
#include "trace_internal.h"

_Thread_local struct trace_log *pl_trace;
_Thread_local bool trace_replaying;

/* The document's head: the request and the render it is a pixel of. */
static void begin(trace_log *t, const render_ctx *ctx, const trace_request *req, FILE *out)
{
    if (req->json) {
        t->samples = json_array();
        t->checks = json_array();
        t->doc = json_pack("{s:s, s:[ii], s:s, s:I, s:o, s:o}", "format", "pathlab-trace-1", "pixel", req->x, req->y,
                           "command", ctx->opts->command_line ? ctx->opts->command_line : "", "seed",
                           (json_int_t)ctx->opts->seed, "samples", t->samples, "batch_checks", t->checks);
    }
    else
        fprintf(out, "pixel (%d, %d) of %s, %dx%d, seed %llu (counted from the bottom-left; lines marked !! break a rule)\n",
                req->x, req->y, ctx->scene->path, ctx->width, ctx->height, (unsigned long long)ctx->opts->seed);
}

/* Traces one pixel: renders it once through the render's per-pixel loop with the hooks on, so
 * every sample uses the generator stream it uses in a render: the trace shows the same value the
 * image has at that pixel. */
pl_status trace_pixel(const render_ctx *ctx, const trace_request *req, FILE *out, trace_result *result, pl_diag *diag)
{
    if (req->x < 0 || req->y < 0 || req->x >= ctx->width || req->y >= ctx->height)
        return pl_fail(diag, PL_ERR_INVALID, "--trace-pixel %d %d: outside the %dx%d image (x 0..%d, y 0..%d from the bottom-left)",
                       req->x, req->y, ctx->width, ctx->height, ctx->width - 1, ctx->height - 1);
    trace_log t = {.ctx = ctx, .req = *req, .out = out};
    begin(&t, ctx, req, out);
    film_pixel px = {0};
    pl_trace = &t;
    render_pixel_traced(ctx, req->x, req->y, &px);
    pl_trace = NULL;
    trace_summary(&t, &px);
    pl_status st = PL_OK;
    if (t.doc) {
        if (json_dumpf(t.doc, out, JSON_INDENT(1)) != 0) st = pl_fail(diag, PL_ERR_IO, "--trace-format json: could not write");
        fputc('\n', out);
        json_decref(t.doc);
    }
    if (result) *result = (trace_result){px, t.marks};
    return st;
}
