/* Grader machinery: not part of any assignment. Part 4's functions across the split (seam.h; see
 * seam_part1.c and seam_part3.c for the pattern). */
#include "seam.h"
#include "../../parts/part4_global/part4.h"
#include <string.h>

typedef struct { unsigned char go_on; rgb beta; } roulette_out;

static uint64_t bounce_inputs(const struct render_ctx *ctx, const ray *r, const hit *h, const rng *g)
{
    return seam_hash_rng(seam_hash_hit(seam_hash_ray(seam_hash_ctx(SEAM_HASH_START, ctx), r), h), g);
}

static uint64_t roulette_inputs(const rgb *beta, int next_depth, const rng *g)
{
    uint64_t h = beta ? SEAM_HASH(SEAM_HASH_START, *beta) : seam_hash_int(SEAM_HASH_START, -1);
    return seam_hash_rng(seam_hash_int(h, next_depth), g);
}

/* The path's radiance: one line, see SEAM_FIXED in seam.h. */
SEAM_FIXED(rgb, rgb, at_least_one_bounce_radiance, (const struct render_ctx *ctx, const ray *r, const hit *h, rng *g),
           (ctx, r, h, g), bounce_inputs(ctx, r, h, g), g)

/* russian_roulette also rescales *beta: its answer is the verdict and the throughput (roulette_out). */
#ifdef PL_SEAM_SUBJECT
bool __real_russian_roulette(rgb *beta, int next_depth, rng *g);
bool __wrap_russian_roulette(rgb *beta, int next_depth, rng *g);

bool __wrap_russian_roulette(rgb *beta, int next_depth, rng *g)
{
    seam_call call;
    uint64_t in = roulette_inputs(beta, next_depth, g);
    if (!seam_begin(&call)) return __real_russian_roulette(beta, next_depth, g);
    roulette_out out;
    memset(&out, 0, sizeof out);
    out.go_on = __real_russian_roulette(beta, next_depth, g);
    if (beta) out.beta = *beta;
    seam_end(&call, SEAM_russian_roulette, in, g, &out, sizeof out, NULL, NULL, 0);
    return out.go_on;
}
#endif

#ifdef PL_SEAM_JUDGE
bool russian_roulette(rgb *beta, int next_depth, rng *g)
{
    roulette_out out;
    seam_replay_fixed(SEAM_russian_roulette, roulette_inputs(beta, next_depth, g), g, &out, sizeof out);
    if (beta) *beta = out.beta;
    return out.go_on != 0;
}
#endif
