/* Part 1, task 1.4 (the fixed-rate pixel estimate) and the worked example (normal shading). */
#include "part1.h"
#include "../../framework/render.h"
#include "../../framework/todo.h"

/* === PART 1 | TASK 1.4 | pixel_estimate_fixed =========================================
 * The mean radiance through pixel (x, y) over ctx->opts->spp camera samples (handout/part1.md,
 * section 1.4).
 * In:  ctx (camera, width, height, opts->spp); pixel (x, y), (0,0) = bottom-left.
 * Out: the mean of radiance_estimate over the samples; *samples_taken = opts->spp.
 * Must: sample s uses the generator render_rng(ctx, x, y, s) for everything it draws, so renders
 *       do not depend on thread count; with spp == 1 the ray passes through the pixel centre; with
 *       spp > 1 each sample is uniform over the pixel's square.
 * Test: make test-part1
 * ====================================================================================== */
rgb pixel_estimate_fixed(const struct render_ctx *ctx, int x, int y, int *samples_taken)
{
    /* BEGIN SOLUTION */
    int n = ctx->opts->spp;
    double sum_r = 0.0, sum_g = 0.0, sum_b = 0.0;  /* many samples: sum in double */
    for (int s = 0; s < n; s++) {
        rng g = render_rng(ctx, x, y, s);
        vec2 jitter = n == 1 ? vec2_make(0.5f, 0.5f) : rng_uniform2(&g);
        ray r = camera_generate_ray(&ctx->camera, (x + jitter.x) / ctx->width, (y + jitter.y) / ctx->height);
        rgb L = radiance_estimate(ctx, &r, &g);
        sum_r += L.r;
        sum_g += L.g;
        sum_b += L.b;
    }
    *samples_taken = n;
    return rgb_make((float)(sum_r / n), (float)(sum_g / n), (float)(sum_b / n));
    /* END SOLUTION */
    /* STUB: *samples_taken = ctx->opts->spp; return PL_TODO_RGB("1.4", "pixel_estimate_fixed"); */
}

/* Worked example, complete: the pattern every task follows, finished. Maps each component of the
 * unit normal from [-1, 1] to [0, 1], so +X is red, +Y green, +Z blue. */
rgb normal_shade(const hit *h)
{
    return rgb_make(0.5f * h->n.x + 0.5f, 0.5f * h->n.y + 0.5f, 0.5f * h->n.z + 0.5f);
}
