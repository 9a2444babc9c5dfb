/* Part 4: global illumination. Handout: handout/part4.md. Test: make test-part4.
 *
 * Bounce numbering: the light that reaches the camera after reflecting at k surfaces is the k-th
 * bounce. Bounce 0 is emission seen directly (part 3's zero_bounce_radiance, added by the
 * framework at the camera); bounce 1 is direct light (one_bounce_radiance); bounce k >= 2 is direct
 * light at the k-th vertex of a path, carried back by the k - 1 reflections before it.
 *
 * No double counting: emission is added only at the camera. At every later vertex light arrives
 * only through one_bounce_radiance, so a bounce ray that happens to hit an emitter does NOT add that
 * emitter's Le: the direct term of the vertex before it already counted that light. */
#ifndef PL_PART4_H
#define PL_PART4_H

#include "../../framework/scene.h"
#include "../../framework/ray.h"
#include "../../framework/rng.h"
#include "../../framework/spawn.h"  /* spawn_ray: how a bounce ray leaves the surface */
#include "../../framework/material.h"  /* material_sample_f: the next direction, whatever the material */

struct render_ctx;

/* TASK 4.1: radiance reflected at h towards r's origin, bounces 1 .. max_depth (-m >= 2), as
 * ctx->settings says (framework/render.h: render_settings, never the options ctx->opts points to):
 * all of them with settings.accumulate (-o 1), only bounce max_depth without (-o 0). Russian
 * roulette (when settings.roulette, that is without --no-rr) ends paths early without changing
 * the mean. */
rgb at_least_one_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g);

/* TASK 4.2: the Russian roulette rule for a path about to take bounce `next_depth` with
 * throughput *beta: returns false to end the path, or true after dividing *beta by the
 * probability of going on. */
bool russian_roulette(rgb *beta, int next_depth, rng *g);

#endif
