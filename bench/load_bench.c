/* Benchmark, not a test: how long dae_load takes, best of N runs per file (`make bench-load`).
 * Best-of, not mean: the figure is the loader's cost, not the machine's other load. */
#include "../framework/clock.h"
#include "../framework/dae.h"
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    int runs = getenv("BENCH_RUNS") ? atoi(getenv("BENCH_RUNS")) : 20;
    printf("%-40s %10s %10s\n", "scene", "triangles", "load ms");
    for (int i = 1; i < argc; i++) {
        double best = 1e9;
        int triangles = 0;
        for (int r = 0; r < runs; r++) {
            scene s;
            pl_diag d = pl_diag_default();
            double t0 = clock_seconds();
            if (dae_load(argv[i], &s, &d) != PL_OK) {
                fprintf(stderr, "load_bench: %s\n", d.error);
                return 1;
            }
            double t = clock_seconds() - t0;
            best = t < best ? t : best;
            triangles = s.num_triangles;
            scene_free(&s);
        }
        printf("%-40s %10d %10.2f\n", argv[i], triangles, best * 1e3);
    }
    return 0;
}
