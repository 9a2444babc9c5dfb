/* Benchmark, not a test: writing one 800x600 render's outputs (`make bench-write`): the tone-mapped
 * PNG, the rate map and a sidecar-sized JSON, as bin/pathtracer writes them (one output set, files
 * encoded in parallel), best of N. The image is a real render (the 58k-triangle bunny, normal
 * shading, 800x600: issue 7's figure) so the PNG compresses as renders do. */
#include "../framework/clock.h"
#include "../framework/output.h"
#include "../framework/image.h"
#include "../framework/colormap.h"
#include "../framework/dae.h"
#include "../framework/accel.h"
#include "../framework/render.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

extern int stbi_write_png_compression_level;

static pl_status encode_json(FILE *f, const void *user, pl_diag *diag)
{
    (void)diag;
    return fputs(user, f) >= 0 ? PL_OK : PL_ERR_IO;
}

int main(void)
{
    int runs = getenv("BENCH_RUNS") ? atoi(getenv("BENCH_RUNS")) : 20;
    options o = options_default();
    o.width = 800, o.height = 600, o.threads = 2, o.normals = true, o.output = "/tmp/pathlab-bench-write.png";
    o.scene_path = "bench/data/cornell_bunny_58k.dae";
    scene s;
    accel a;
    memset(&a, 0, sizeof a);
    image img = {0};
    int *samples = calloc((size_t)o.width * o.height, sizeof *samples);
    render_stats stats;
    render_ctx ctx;
    if (dae_load(o.scene_path, &s, NULL) || accel_build(&a, &s, true, 4, NULL) || !samples ||
        image_alloc(&img, o.width, o.height))
        return 1;
    render_ctx_init(&ctx, &s, &a, &o);
    render_image(&ctx, &img, samples, &stats, NULL);
    rate_map rates = {samples, o.width, o.height, o.spp};
    char json[4096];
    memset(json, ' ', sizeof json - 1);
    json[sizeof json - 1] = '\0';

    output_set set;
    pl_diag d = pl_diag_default();
    if (output_plan(&set, &o, &d)) return fprintf(stderr, "%s\n", d.error), 1;
    output_bind(&set, OUTPUT_IMAGE, image_encode_png, &img);
    output_bind(&set, OUTPUT_RATE_MAP, rate_map_encode, &rates);
    output_bind(&set, OUTPUT_SIDECAR, encode_json, json);
    /* Wall time depends on what else the machine runs; CPU time (all threads) much less so. */
    double best = 1e9, best_cpu = 1e9;
    for (int r = 0; r < runs; r++) {
        double t0 = clock_seconds(), c0 = clock_cpu_seconds();
        if (output_write(&set, OUTPUT_IMAGE, OUTPUT_SIDECAR, &d)) return fprintf(stderr, "%s\n", d.error), 1;
        double t = clock_seconds() - t0, c = clock_cpu_seconds() - c0;
        best = t < best ? t : best;
        best_cpu = c < best_cpu ? c : best_cpu;
    }
    printf("write 800x600 PNG + rate map + sidecar (one output set): %.2f ms wall, %.2f ms CPU (best of %d)\n",
           best * 1e3, best_cpu * 1e3, runs);
    for (int k = 0; k < 3; k++) unlink(set.path[k]);
    output_free(&set);
    image_free(&img);
    free(samples);
    accel_free(&a);
    scene_free(&s);
    return 0;
}
