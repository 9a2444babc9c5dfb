/* PCG32 (XSH RR output, 64-bit LCG state), after O'Neill's minimal reference description.
 * Streams are selected by the increment; (seed, pixel, sample) are mixed with SplitMix64 first so
 * that neighbouring pixels and samples get unrelated sequences. */
#include "rng.h"
#include "trace_hook.h"
#include "check.h"
#include <stddef.h>

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

rng rng_seeded(uint64_t seed, uint64_t stream)
{
    rng r;
    r.state = 0;
    r.inc = (stream << 1u) | 1u;  /* the increment must be odd */
    rng_u32(&r);
    r.state += seed;
    rng_u32(&r);
    return r;
}

rng rng_for_sample(uint64_t seed, uint64_t pixel, uint64_t sample)
{
    uint64_t a = splitmix64(seed ^ splitmix64(pixel));
    uint64_t b = splitmix64(a ^ splitmix64(sample + 0x632BE59BD9B4E019ull));
    return rng_seeded(a, b);
}

PL_HOT uint32_t rng_u32(rng *r)
{
    uint64_t old = r->state;
    r->state = old * 6364136223846793005ull + r->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
}

/* 24 random bits scaled by 2^-24: exactly representable, so the result is < 1. A seam function
 * (framework/seam.h): under a trace the value is reported, so the trace can replay part 4's BSDF
 * sample from it; a render only pays the (predicted) test. */
PL_HOT float rng_uniform(rng *r)
{
    float v = (float)(rng_u32(r) >> 8) * (1.0f / 16777216.0f);
    if (PL_UNLIKELY(pl_trace != NULL)) trace_rng(v);
    return v;
}
