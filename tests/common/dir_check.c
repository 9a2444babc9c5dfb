/* Test machinery: not part of any assignment. Direction samplers against their pdfs (dir_check.h). */
#include <stdio.h>
#include <stdlib.h>
#include "test.h"
#include "../../framework/stats.h"
#include "mc_assert.h"
#include "histogram_png.h"
#include "dir_check.h"
#include "../../framework/rng.h"

static int bin_of(vec3 w)
{
    if (!(w.z >= 0.0f)) return DIR_BINS - 1;
    int iz = (int)(w.z * DIR_BINS_Z);
    if (iz >= DIR_BINS_Z) iz = DIR_BINS_Z - 1;
    double phi = atan2(w.y, w.x);
    if (phi < 0) phi += 2 * M_PI;
    int ip = (int)(phi / (2 * M_PI) * DIR_BINS_PHI);
    if (ip >= DIR_BINS_PHI) ip = DIR_BINS_PHI - 1;
    return iz * DIR_BINS_PHI + ip;
}

/* Expected counts: the pdf integrated over each (z, phi) cell, dw = dz dphi, by an 8 x 8 midpoint
 * rule. Returns the total probability, which must be 1 for a normalised pdf. */
double dir_expected_counts(dir_pdf pdf, void *user, double *expected, double n)
{
    const int sub = 8;
    double total = 0.0;
    for (int iz = 0; iz < DIR_BINS_Z; iz++)
        for (int ip = 0; ip < DIR_BINS_PHI; ip++) {
            double p = 0.0;
            for (int a = 0; a < sub; a++)
                for (int b = 0; b < sub; b++) {
                    double z = (iz + (a + 0.5) / sub) / DIR_BINS_Z;
                    double phi = (ip + (b + 0.5) / sub) / DIR_BINS_PHI * 2 * M_PI;
                    double r = sqrt(fmax(0.0, 1.0 - z * z));
                    p += pdf(user, vec3_make((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z));
                }
            p *= (1.0 / DIR_BINS_Z) * (2 * M_PI / DIR_BINS_PHI) / (sub * sub);
            expected[iz * DIR_BINS_PHI + ip] = p * n;
            total += p;
        }
    expected[DIR_BINS - 1] = 0.0;
    return total;
}

void dir_check_sampler(const char *name, dir_sampler sample, dir_pdf pdf, void *user, uint64_t seed, double alpha,
                       const char *file, int line)
{
    mc_print_seed(name, seed);
    double *observed = calloc(DIR_BINS, sizeof *observed), *expected = calloc(DIR_BINS, sizeof *expected);
    check_true(observed && expected, "memory for the histogram", file, line);
    rng g = rng_seeded(seed, 0);
    for (int i = 0; i < DIR_SAMPLES; i++) {
        float p = 0.0f;
        vec3 w = sample(user, rng_uniform2(&g), &p);
        check_implemented(file, line);
        if (!(fabsf(vec3_length(w) - 1.0f) < 1e-3f)) {
            print_error("%s: sample %d is not a unit vector: (%g, %g, %g)\n", name, i, w.x, w.y, w.z);
            check_fail(file, line);
        }
        observed[bin_of(w)] += 1.0;
    }
    double total = dir_expected_counts(pdf, user, expected, DIR_SAMPLES);
    check_float_near(1.0, total, 2e-3, "total probability of the pdf", file, line);
    stats_result r = stats_chi2_test(observed, expected, DIR_BINS, 5.0, alpha);
    if (r.reject) {
        print_error("%s: directions do not follow the pdf: chi-square %.1f with %g dof, p = %.3g < %.3g "
                    "(below-surface samples: %g)\n", name, r.stat, r.dof, r.p, alpha, observed[DIR_BINS - 1]);
        print_error("  cos(theta) bin: observed / expected\n");
        for (int iz = 0; iz < DIR_BINS_Z; iz++) {
            double o = 0, e = 0;
            for (int ip = 0; ip < DIR_BINS_PHI; ip++) { o += observed[iz * DIR_BINS_PHI + ip]; e += expected[iz * DIR_BINS_PHI + ip]; }
            print_error("  [%.1f, %.1f): %8.0f / %8.0f\n", (double)iz / DIR_BINS_Z, (double)(iz + 1) / DIR_BINS_Z, o, e);
        }
        char png[256];
        pl_diag d = pl_diag_default();
        histogram_png_path(name, png, sizeof png);
        if (histogram_png_write(png, observed, expected, DIR_BINS_Z, DIR_BINS_PHI, &d) == PL_OK)
            print_error("  picture: %s (rows: cos(theta) from 0 at the top to 1; columns: phi from 0 to 2 pi;\n"
                        "  panels: observed, expected, residual: red = too many samples, blue = too few)\n", png);
    }
    free(observed);
    free(expected);
    check_true(!r.reject, "directions that follow the pdf", file, line);
}

