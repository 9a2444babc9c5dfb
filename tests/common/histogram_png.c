/* Test machinery: not part of any assignment. */
#include "histogram_png.h"
#include "../../framework/colormap.h"
#include "../../framework/image.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#define CELL 12  /* pixels per histogram bin */
#define GAP 8    /* pixels between panels */

void histogram_png_path(const char *name, char *out, int out_len)
{
    mkdir("build", 0777);
    mkdir("build/test-output", 0777);
    snprintf(out, (size_t)out_len, "build/test-output/%s.png", name);
}

/* Residual colour: grey at 0, towards red (positive) or blue (negative), saturated at |z| = 4. */
static void residual_colour(double z, uint8_t out[3])
{
    double k = fmin(fabs(z) / 4.0, 1.0);
    uint8_t grey = 128;
    uint8_t strong = (uint8_t)(128 + 127 * k), weak = (uint8_t)(128 - 128 * k);
    out[0] = z > 0 ? strong : (z < 0 ? weak : grey);
    out[1] = weak;
    out[2] = z < 0 ? strong : (z > 0 ? weak : grey);
}

pl_status histogram_png_write(const char *path, const double *observed, const double *expected, int rows, int cols,
                              pl_diag *diag)
{
    int panel_w = cols * CELL, width = 3 * panel_w + 2 * GAP, height = rows * CELL;
    uint8_t *px = calloc((size_t)width * height * 3, 1);
    if (!px) return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    double top = 0.0;
    for (int i = 0; i < rows * cols; i++) top = fmax(top, fmax(observed[i], expected[i]));
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            int i = r * cols + c;
            uint8_t colour[3][3];
            colormap_rate(top > 0 ? (float)(observed[i] / top) : 0.0f, colour[0]);
            colormap_rate(top > 0 ? (float)(expected[i] / top) : 0.0f, colour[1]);
            double z = expected[i] > 0 ? (observed[i] - expected[i]) / sqrt(expected[i]) : (observed[i] > 0 ? 4.0 : 0.0);
            residual_colour(z, colour[2]);
            for (int panel = 0; panel < 3; panel++)
                for (int y = r * CELL; y < (r + 1) * CELL - 1; y++)      /* one dark line between cells */
                    for (int x = c * CELL; x < (c + 1) * CELL - 1; x++) {
                        uint8_t *p = px + 3 * ((size_t)y * width + panel * (panel_w + GAP) + x);
                        p[0] = colour[panel][0], p[1] = colour[panel][1], p[2] = colour[panel][2];
                    }
        }
    pl_status s = image_write_png_rgb8(px, width, height, path, diag);
    free(px);
    return s;
}
