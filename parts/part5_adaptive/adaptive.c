/* Part 5: adaptive sampling. Handout: handout/part5.md. */
#include "part5.h"
#include "../part1_raygen/part1.h"
#include "../../framework/render.h"
#include "../../framework/todo.h"

/* === PART 5 | TASK 5.1 | pixel_estimate_adaptive ====================================
 * Sample pixel (x, y) until its luminance is known to within T of its mean (handout/part5.md).
 * In:  ctx (opts->spp, opts->adaptive_batch B, opts->adaptive_tol T); pixel (x, y), (0,0) at the
 *      bottom-left, as in part 1.
 * Out: mean radiance of the n samples taken; *samples_taken = n.
 * Must: sample s draws only from render_rng(ctx, x, y, s), like part 1 (centre of the pixel when
 *       spp == 1, uniform over it otherwise); test convergence only when n is a multiple of B,
 *       on luminance, with the rule in part5.h; a pixel of constant radiance stops at n = B;
 *       n never exceeds spp.
 * Test: make test-part5
 * =================================================================================== */
rgb pixel_estimate_adaptive(const struct render_ctx *ctx, int x, int y, int *samples_taken)
{
    /* BEGIN SOLUTION */
    const options *o = ctx->opts;
    int batch = o->adaptive_batch > 0 ? o->adaptive_batch : 1;
    double sum_r = 0.0, sum_g = 0.0, sum_b = 0.0;  /* many samples: sum in double */
    double s1 = 0.0, s2 = 0.0;
    int n = 0;
    while (n < o->spp) {
        rng g = render_rng(ctx, x, y, n);
        vec2 jitter = o->spp == 1 ? vec2_make(0.5f, 0.5f) : rng_uniform2(&g);
        ray r = camera_generate_ray(&ctx->camera, (x + jitter.x) / ctx->width, (y + jitter.y) / ctx->height);
        rgb L = radiance_estimate(ctx, &r, &g);
        sum_r += L.r;
        sum_g += L.g;
        sum_b += L.b;
        double lum = rgb_luminance(L);
        s1 += lum;
        s2 += lum * lum;
        n++;
        if (n % batch == 0 && n > 1) {
            double mean = s1 / n;
            double var = fmax(0.0, (s2 - s1 * s1 / n) / (n - 1));  /* rounding can dip below 0 */
            double half_width = 1.96 * sqrt(var / n);
            if (half_width <= o->adaptive_tol * mean)
                break;
        }
    }
    *samples_taken = n;
    return rgb_make((float)(sum_r / n), (float)(sum_g / n), (float)(sum_b / n));
    /* END SOLUTION */
    /* STUB: *samples_taken = ctx->opts->spp; return PL_TODO_RGB("5.1", "pixel_estimate_adaptive"); */
}
