/* Benchmark, not a test: part 8's importance sampling of an environment map (`make bench-env`): for
 * maps of 64 x 32 to 4096 x 2048 texels, the time to build the tables (task 8.2, once a render) and
 * the time per sample of task 8.4 against task 8.1's uniform sampling, best of BENCH_RUNS. A sample
 * searches two CDFs, so its cost should grow with log(width) + log(height): about one step more
 * each time a side doubles, not twice the time. The maps are a sky-like gradient with noise, so
 * the searches go everywhere. */
#include "../framework/clock.h"
#include "../framework/envmap.h"
#include "../framework/rng.h"
#include "../parts/part8_envlight/part8.h"
#include <stdio.h>
#include <stdlib.h>

#define SAMPLES 2000000

/* Seconds per call of n samples by importance (d) or uniformly (d NULL); the sum keeps the calls. */
static double per_sample(const envmap *e, const env_distribution *d, int n, double *sink)
{
    rng g = rng_seeded(7, 0);
    double t0 = clock_seconds(), sum = 0.0;
    for (int i = 0; i < n; i++) {
        vec3 wi;
        float pdf;
        rgb L = d ? env_sample_importance(e, d, rng_uniform2(&g), &wi, &pdf) : env_sample_uniform(e, rng_uniform2(&g), &wi, &pdf);
        sum += L.r + pdf;
    }
    *sink += sum;
    return (clock_seconds() - t0) / n;
}

int main(void)
{
    int runs = getenv("BENCH_RUNS") ? atoi(getenv("BENCH_RUNS")) : 5;
    if (runs < 1) runs = 1;
    double sink = 0.0;
    printf("== environment light (part 8), best of %d runs; %d samples a run\n", runs, SAMPLES);
    printf("  %-12s %14s %16s %16s\n", "map", "build tables", "importance", "uniform");
    for (int w = 64; w <= 4096; w *= 4) {
        int h = w / 2;
        envmap e;
        env_distribution d;
        if (envmap_make_constant(&e, w, h, rgb_gray(0.0f)) || env_distribution_alloc(&d, w, h)) return 1;
        rng g = rng_seeded(1, 0);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) e.texels[(size_t)y * w + x] = rgb_gray((1.0f - (float)y / h) * (0.5f + rng_uniform(&g)));
        double build = 1e9, imp = 1e9, uni = 1e9;
        for (int r = 0; r < runs; r++) {
            double t0 = clock_seconds();
            env_build_distribution(&e, &d);
            double t = clock_seconds() - t0;
            build = t < build ? t : build;
            double a = per_sample(&e, &d, SAMPLES, &sink), b = per_sample(&e, NULL, SAMPLES, &sink);
            imp = a < imp ? a : imp;
            uni = b < uni ? b : uni;
        }
        char size[32];
        snprintf(size, sizeof size, "%dx%d", w, h);
        printf("  %-12s %11.2f ms %13.1f ns %13.1f ns\n", size, build * 1e3, imp * 1e9, uni * 1e9);
        env_distribution_free(&d);
        envmap_free(&e);
    }
    return sink == 42.0;  /* never: the sums only keep the calls */
}
