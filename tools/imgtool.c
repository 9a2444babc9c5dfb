/* Image tool: not part of any assignment. One reader of rendered images for the tests, the release
 * check, the benchmarks and the handout's figures (PNG and Radiance .hdr, through framework/image.h).
 *
 *   imgtool stats FILE                    "FILE: W x H, magenta fraction F": how much of the image is
 *                                         the stubs' "not implemented" magenta (the release check)
 *   imgtool mean FILE                     the mean of each channel: "r g b"
 *   imgtool relmse CANDIDATE REFERENCE    relMSE = mean over pixels and channels of
 *                                         (c - r)^2 / (r^2 + 0.01) (the transport benchmark)
 *   imgtool sub A B OUT.png|OUT.hdr       max(A - B, 0) per channel, e.g. indirect light alone =
 *                                         (-m 5 render) - (-m 1 render)
 *   imgtool montage OUT.png A.png B.png   PNGs of one size side by side, to see a ladder of figures
 *   imgtool sky OUT.exr [W H]             environment maps (-e) made here, free to ship: a clear sky
 *   imgtool studio OUT.exr [W H]          with a sun, or a dark studio with three soft boxes; W x H
 *                                         texels, 512 x 256 by default (framework/envmap.h)
 *
 * Exit status: 0 done, 1 an image could not be read or written, 2 bad usage. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../framework/envmap.h"
#include "../framework/exr.h"
#include "../framework/image.h"
#include "../framework/output.h"
#include "../framework/stats.h"

#define MONTAGE_MAX 32

/* ---- reading, with one message format ---------------------------------------------------------- */
static bool load(const char *path, image *img)
{
    pl_diag d = pl_diag_default();
    if (image_read(path, img, &d) != PL_OK) {
        fprintf(stderr, "imgtool: %s\n", d.error);
        return false;
    }
    return true;
}

/* Two images compared pixel by pixel must have one size. */
static bool same_size(const image *a, const char *pa, const image *b, const char *pb)
{
    if (a->width == b->width && a->height == b->height) return true;
    fprintf(stderr, "imgtool: %s is %dx%d but %s is %dx%d\n", pa, a->width, a->height, pb, b->width, b->height);
    return false;
}

/* ---- stats: the stub colour's share ------------------------------------------------------------ */
/* Stub magenta is rgb(1, 0, 1) radiance: 255, 0, 255 after the tone curve. The margins allow for
 * lossy viewers and future tone curves without letting red, blue or grey pass. */
static bool is_magenta(rgb c) { return c.r > 0.9f && c.b > 0.9f && c.g < 0.1f; }

static int cmd_stats(const char *path)
{
    image img = {0};
    if (!load(path, &img)) return 1;
    long magenta = 0, total = (long)img.width * img.height;
    for (long i = 0; i < total; i++) magenta += is_magenta(img.pixels[i]);
    printf("%s: %d x %d, magenta fraction %.4f\n", path, img.width, img.height,
           total ? (double)magenta / (double)total : 0.0);
    image_free(&img);
    return 0;
}

/* ---- mean, relmse, sub: radiance arithmetic ---------------------------------------------------- */
static int cmd_mean(const char *path)
{
    image a = {0};
    if (!load(path, &a)) return 1;
    double m[3] = {0, 0, 0};
    long n = (long)a.width * a.height;
    for (long i = 0; i < n; i++) {
        m[0] += a.pixels[i].r;
        m[1] += a.pixels[i].g;
        m[2] += a.pixels[i].b;
    }
    printf("%.6f %.6f %.6f\n", m[0] / n, m[1] / n, m[2] / n);
    image_free(&a);
    return 0;
}

/* relmse (out == NULL) or sub (out names the difference image). */
static int cmd_pair(const char *pa, const char *pb, const char *out)
{
    image a = {0}, b = {0};
    int status = 1;
    if (!load(pa, &a) || !load(pb, &b) || !same_size(&a, pa, &b, pb)) goto done;
    long n = (long)a.width * a.height;
    if (!out) {
        /* rgb is three floats, so the pixels are 3n floats in a row. */
        printf("%.6f\n", stats_rel_mse(&a.pixels[0].r, &b.pixels[0].r, 3 * n));
    } else {
        for (long i = 0; i < n; i++) {
            rgb p = a.pixels[i], q = b.pixels[i];
            a.pixels[i] = rgb_make(fmaxf(p.r - q.r, 0.0f), fmaxf(p.g - q.g, 0.0f), fmaxf(p.b - q.b, 0.0f));
        }
        pl_diag d = pl_diag_default();
        if (image_write(&a, out, &d) != PL_OK) {
            fprintf(stderr, "imgtool: %s\n", d.error);
            goto done;
        }
    }
    status = 0;
done:
    image_free(&a);
    image_free(&b);
    return status;
}

/* ---- montage: PNGs side by side ---------------------------------------------------------------- */
/* PNGs are read as 8-bit values / 255 and written back byte for byte, no tone curve. */
static int cmd_montage(const char *out, int count, char **paths)
{
    image tiles[MONTAGE_MAX] = {{0}};
    int loaded = 0, status = 1;
    uint8_t *rgb8 = NULL;
    for (; loaded < count; loaded++)
        if (!load(paths[loaded], &tiles[loaded]) || !same_size(&tiles[0], paths[0], &tiles[loaded], paths[loaded]))
            goto done;
    int w = tiles[0].width, h = tiles[0].height;
    rgb8 = calloc((size_t)w * count * h * 3, 1);
    if (!rgb8) { fprintf(stderr, "imgtool: out of memory\n"); goto done; }
    for (int i = 0; i < count; i++)
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                rgb c = image_get(&tiles[i], x, y);
                uint8_t *p = &rgb8[((size_t)y * w * count + (size_t)i * w + x) * 3];
                p[0] = (uint8_t)(c.r * 255.0f + 0.5f);
                p[1] = (uint8_t)(c.g * 255.0f + 0.5f);
                p[2] = (uint8_t)(c.b * 255.0f + 0.5f);
            }
    pl_diag d = pl_diag_default();
    if (image_write_png_rgb8(rgb8, w * count, h, out, &d) != PL_OK) fprintf(stderr, "imgtool: %s\n", d.error);
    else status = 0;
done:
    free(rgb8);
    for (int i = 0; i < loaded && i < count; i++) image_free(&tiles[i]);
    return status;
}

/* ---- sky, studio: environment maps made in code ------------------------------------------------- */
/* Each texel holds the radiance at its centre's direction (envmap.h's mapping), so a map of any size
 * is the same sky. The figures are radiance in the scenes' units, chosen so that the Cornell boxes'
 * materials come out at a similar brightness as under their own lights. */

/* The angle in radians between unit directions a and b. */
static float angle_between(vec3 a, vec3 b) { return acosf(fminf(1.0f, fmaxf(-1.0f, vec3_dot(a, b)))); }

/* A clear sky: blue overhead, pale at the horizon, a sun 3 degrees across (2.6 W/m^2 of irradiance at
 * normal incidence, about what the sky gives a surface facing up) 35 degrees above the horizon, and
 * a dim brown ground below the horizon. */
static rgb sky_radiance(vec3 d)
{
    vec3 sun = vec3_normalize(vec3_make(-0.6f, 0.574f, -0.557f));  /* elevation 35 degrees */
    if (angle_between(d, sun) < deg_to_rad(1.5f)) return rgb_make(1250.0f, 1150.0f, 1000.0f);
    if (d.y < 0.0f) return rgb_make(0.12f, 0.10f, 0.08f);
    float t = powf(1.0f - d.y, 3.0f);  /* 0 overhead, 1 at the horizon */
    rgb zenith = rgb_make(0.20f, 0.38f, 0.85f), horizon = rgb_make(0.85f, 0.90f, 1.0f);
    return rgb_add(rgb_scale(zenith, 1.0f - t), rgb_scale(horizon, t));
}

/* A photographer's studio: a dark room, a large key light up and to one side, a dimmer fill on the
 * other, a narrow strip behind; each a box of constant radiance in (elevation, azimuth). */
static rgb studio_radiance(vec3 d)
{
    vec2 a = envmap_angles(d);
    float elev = 90.0f - rad_to_deg(a.x), azim = rad_to_deg(a.y);
    struct { float e0, e1, a0, a1; float L; } box[] = {
        {25.0f, 55.0f, 200.0f, 240.0f, 12.0f},  /* key */
        {5.0f, 30.0f, 300.0f, 330.0f, 3.0f},    /* fill */
        {10.0f, 70.0f, 85.0f, 95.0f, 8.0f},     /* strip behind */
    };
    for (size_t i = 0; i < sizeof box / sizeof box[0]; i++)
        if (elev >= box[i].e0 && elev < box[i].e1 && azim >= box[i].a0 && azim < box[i].a1) return rgb_gray(box[i].L);
    return d.y < 0.0f ? rgb_gray(0.05f) : rgb_gray(0.02f);
}

static int cmd_envmap(const char *kind, const char *out, int w, int h)
{
    rgb (*radiance)(vec3) = strcmp(kind, "sky") == 0 ? sky_radiance : studio_radiance;
    pl_diag d = pl_diag_default();
    output_set set;
    if (output_plan_merge(&set, out, NULL, 0, &d) != PL_OK) {
        fprintf(stderr, "imgtool: %s\n", d.error);
        return 1;
    }
    exr_rgb_image img = {w, h, malloc(3 * (size_t)w * (size_t)h * sizeof(float))};
    int status = 1;
    if (!img.texels) fprintf(stderr, "imgtool: out of memory\n");
    for (int y = 0; img.texels && y < h; y++)
        for (int x = 0; x < w; x++) {
            float theta = ((float)y + 0.5f) * PL_PI / (float)h, phi = ((float)x + 0.5f) * 2.0f * PL_PI / (float)w;
            rgb L = radiance(envmap_direction(theta, phi));
            float *t = &img.texels[3 * ((size_t)y * w + x)];
            t[0] = L.r, t[1] = L.g, t[2] = L.b;
        }
    if (img.texels) {
        output_bind(&set, OUTPUT_IMAGE, exr_encode_rgb, &img);
        if (output_write(&set, OUTPUT_IMAGE, OUTPUT_IMAGE, &d) != PL_OK) fprintf(stderr, "imgtool: %s\n", d.error);
        else status = 0;
    }
    free(img.texels);
    output_free(&set);
    return status;
}

/* A map's size on the command line: 2 to ENVMAP_MAX_SIDE texels a side. */
static bool parse_side(const char *s, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*s == 0 || *end != 0 || v < 2 || v > ENVMAP_MAX_SIDE) {
        fprintf(stderr, "imgtool: %s: expected a size of 2 to %d texels\n", s, ENVMAP_MAX_SIDE);
        return false;
    }
    *out = (int)v;
    return true;
}

static int usage(void)
{
    fprintf(stderr, "usage: imgtool stats FILE | mean FILE | relmse CANDIDATE REFERENCE | sub A B OUT |\n"
                    "       montage OUT.png A.png B.png ... (at most %d) | sky|studio OUT.exr [W H]\n", MONTAGE_MAX);
    return 2;
}

int main(int argc, char **argv)
{
    const char *cmd = argc > 1 ? argv[1] : "";
    if (strcmp(cmd, "stats") == 0 && argc == 3) return cmd_stats(argv[2]);
    if (strcmp(cmd, "mean") == 0 && argc == 3) return cmd_mean(argv[2]);
    if (strcmp(cmd, "relmse") == 0 && argc == 4) return cmd_pair(argv[2], argv[3], NULL);
    if (strcmp(cmd, "sub") == 0 && argc == 5) return cmd_pair(argv[2], argv[3], argv[4]);
    if (strcmp(cmd, "montage") == 0 && argc >= 4 && argc - 3 <= MONTAGE_MAX)
        return cmd_montage(argv[2], argc - 3, argv + 3);
    if ((strcmp(cmd, "sky") == 0 || strcmp(cmd, "studio") == 0) && (argc == 3 || argc == 5)) {
        int w = 512, h = 256;
        if (argc == 5 && (!parse_side(argv[3], &w) || !parse_side(argv[4], &h))) return 2;
        return cmd_envmap(cmd, argv[2], w, h);
    }
    return usage();
}
