/* Bench and figure helper: not part of any assignment.
 *   transport_img relmse CANDIDATE.hdr REFERENCE.hdr   prints relMSE = mean over pixels and channels
 *                                                      of (c - r)^2 / (r^2 + 0.01)
 *   transport_img sub A.hdr B.hdr OUT.png|OUT.hdr       writes max(A - B, 0), e.g. indirect light
 *                                                      alone = (-m 5 render) - (-m 1 render)
 *   transport_img mean A.hdr                            prints the mean of each channel
 *   transport_img montage OUT.png A.png B.png ...       the PNGs side by side (same size), to look
 *                                                      at a ladder of figures in one picture */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../framework/image.h"

static int load(const char *path, image *img)
{
    pl_diag d = pl_diag_default();
    if (image_read(path, img, &d) != PL_OK) {
        fprintf(stderr, "transport_img: %s\n", d.error);
        return 1;
    }
    return 0;
}

/* PNGs are read as 8-bit values / 255 and written back byte for byte, no tone curve. */
static int montage(const char *out, int count, char **paths)
{
    image tiles[32];
    if (count < 1 || count > 32) { fprintf(stderr, "transport_img: montage takes 1 to 32 images\n"); return 2; }
    for (int i = 0; i < count; i++)
        if (load(paths[i], &tiles[i])) return 1;
    int w = tiles[0].width, h = tiles[0].height;
    uint8_t *rgb8 = calloc((size_t)w * count * h * 3, 1);
    if (!rgb8) return 1;
    for (int i = 0; i < count; i++)
        for (int y = 0; y < h && y < tiles[i].height; y++)
            for (int x = 0; x < w && x < tiles[i].width; x++) {
                rgb c = image_get(&tiles[i], x, y);
                uint8_t *p = &rgb8[((size_t)y * w * count + (size_t)i * w + x) * 3];
                p[0] = (uint8_t)(c.r * 255.0f + 0.5f);
                p[1] = (uint8_t)(c.g * 255.0f + 0.5f);
                p[2] = (uint8_t)(c.b * 255.0f + 0.5f);
            }
    pl_diag d = pl_diag_default();
    pl_status st = image_write_png_rgb8(rgb8, w * count, h, out, &d);
    free(rgb8);
    for (int i = 0; i < count; i++) image_free(&tiles[i]);
    if (st != PL_OK) { fprintf(stderr, "transport_img: %s\n", d.error); return 1; }
    return 0;
}

int main(int argc, char **argv)
{
    image a = {0}, b = {0};
    if (argc >= 4 && strcmp(argv[1], "montage") == 0)
        return montage(argv[2], argc - 3, argv + 3);
    if (argc == 3 && strcmp(argv[1], "mean") == 0) {
        if (load(argv[2], &a)) return 1;
        double m[3] = {0, 0, 0};
        for (long i = 0; i < (long)a.width * a.height; i++) {
            m[0] += a.pixels[i].r; m[1] += a.pixels[i].g; m[2] += a.pixels[i].b;
        }
        long n = (long)a.width * a.height;
        printf("%.6f %.6f %.6f\n", m[0] / n, m[1] / n, m[2] / n);
        image_free(&a);
        return 0;
    }
    if (argc < 4 || (strcmp(argv[1], "relmse") != 0 && strcmp(argv[1], "sub") != 0) ||
        (strcmp(argv[1], "sub") == 0 && argc < 5)) {
        fprintf(stderr, "usage: %s relmse CANDIDATE.hdr REFERENCE.hdr | sub A.hdr B.hdr OUT.png\n", argv[0]);
        return 2;
    }
    if (load(argv[2], &a) || load(argv[3], &b))
        return 1;
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "transport_img: %s is %dx%d but %s is %dx%d\n", argv[2], a.width, a.height, argv[3],
                b.width, b.height);
        return 1;
    }
    long n = (long)a.width * a.height;
    if (strcmp(argv[1], "relmse") == 0) {
        double sum = 0.0;
        for (long i = 0; i < n; i++) {
            const float *c = &a.pixels[i].r, *r = &b.pixels[i].r;
            for (int k = 0; k < 3; k++)
                sum += (double)(c[k] - r[k]) * (c[k] - r[k]) / ((double)r[k] * r[k] + 0.01);
        }
        printf("%.6f\n", sum / (3.0 * n));
    } else {
        for (long i = 0; i < n; i++) {
            rgb d = {a.pixels[i].r - b.pixels[i].r, a.pixels[i].g - b.pixels[i].g, a.pixels[i].b - b.pixels[i].b};
            a.pixels[i] = rgb_make(fmaxf(d.r, 0.0f), fmaxf(d.g, 0.0f), fmaxf(d.b, 0.0f));
        }
        pl_diag d = pl_diag_default();
        if (image_write(&a, argv[4], &d) != PL_OK) {
            fprintf(stderr, "transport_img: %s\n", d.error);
            return 1;
        }
    }
    image_free(&a);
    image_free(&b);
    return 0;
}
