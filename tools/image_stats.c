/* Instructor tooling: not part of any assignment.
 * image_stats: reads a PNG or HDR back and prints its size and how much of it is stub magenta,
 * so the release check can tell that a stubbed renderer drew its "not implemented" colour.
 *
 *   image_stats FILE     prints "FILE: W x H, magenta fraction F" ; exit 2 if unreadable */
#include <stdio.h>
#include "../framework/image.h"

/* Stub magenta is rgb(1, 0, 1) radiance: 255, 0, 255 after the tone curve. The margins allow for
 * lossy viewers and future tone curves without letting red, blue or grey pass. */
static bool is_magenta(rgb c) { return c.r > 0.9f && c.b > 0.9f && c.g < 0.1f; }

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: image_stats FILE.png|FILE.hdr\n");
        return 2;
    }
    pl_diag diag = pl_diag_default();
    image img = {0};
    if (image_read(argv[1], &img, &diag) != PL_OK) {
        fprintf(stderr, "%s\n", diag.error);
        return 2;
    }
    long magenta = 0, total = (long)img.width * img.height;
    for (long i = 0; i < total; i++) magenta += is_magenta(img.pixels[i]);
    printf("%s: %d x %d, magenta fraction %.4f\n", argv[1], img.width, img.height,
           total ? (double)magenta / (double)total : 0.0);
    image_free(&img);
    return 0;
}
