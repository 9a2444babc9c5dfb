/* Random numbers with explicit state: PCG32 (O'Neill, pcg-random.org, minimal variant).
 * There is no global generator. Every (pixel, sample) pair gets its own stream, seeded from
 * (seed, pixel index, sample index), so an image is bit-identical whatever the thread count or
 * tile order, and a test can replay one pixel's sample exactly.
 * Parts may not call: none of these (every function here is marked PL_PART_API or static inline). */
#ifndef PL_RNG_H
#define PL_RNG_H

#include "part_api.h"

#include <stdint.h>
#include "vec.h"

typedef struct { uint64_t state, inc; } rng;

/* A generator for one (pixel, sample) of a render with the given seed. */
PL_PART_API rng rng_for_sample(uint64_t seed, uint64_t pixel, uint64_t sample);
/* A generator from a single 64-bit seed and stream id (tests, tools), for one long sequence of draws.
 * Streams of one seed are not independent of each other (their n-th states step evenly from one
 * stream to the next): samples that must be independent each take rng_for_sample. */
PL_PART_API rng rng_seeded(uint64_t seed, uint64_t stream);

PL_PART_API uint32_t rng_u32(rng *r);
/* Uniform in [0, 1): never returns 1.0f. */
PL_PART_API float rng_uniform(rng *r);
static inline vec2 rng_uniform2(rng *r)
{
    float a = rng_uniform(r);
    float b = rng_uniform(r);
    return vec2_make(a, b);
}

#endif
