/* Test machinery: not part of any assignment.
 * The scene fuzzer (libFuzzer, `make fuzz`): every input is a COLLADA file as an attacker would
 * write it. It is loaded, its BVH built, and a tiny image rendered twice (normal shading, and one
 * bounce of light); AddressSanitizer and UBSan turn any memory or arithmetic fault into a crash
 * libFuzzer saves. Loader errors are the expected outcome for most inputs: only crashes count. */
#include "../framework/dae.h"
#include "../framework/accel.h"
#include "../framework/render.h"
#include <stdint.h>
#include <string.h>

/* Small limits keep each execution fast; the limits' own checks are what is exercised. */
static const dae_limits fuzz_limits = {20000, 2000};

static void render_tiny(const scene *s, const accel *a, bool normals)
{
    options o = options_default();
    o.width = 4;
    o.height = 3;
    o.spp = 2;
    o.max_depth = 1;
    o.normals = normals;
    render_ctx ctx;
    render_ctx_init(&ctx, s, a, &o);
    image img = {0};
    render_stats stats;
    if (image_alloc(&img, o.width, o.height) == PL_OK) render_image(&ctx, &img, NULL, &stats, NULL);
    image_free(&img);
}

static void ignore_warning(void *user, const char *msg) { (void)user, (void)msg; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    pl_diag quiet = pl_diag_default();
    quiet.on_warning = ignore_warning;
    scene s;
    if (dae_load_memory_limited((const char *)data, size, "fuzz.dae", &fuzz_limits, &s, &quiet) != PL_OK) return 0;
    accel a;
    memset(&a, 0, sizeof a);
    if (accel_build(&a, &s, true, 4, &quiet) == PL_OK) {
        render_tiny(&s, &a, true);
        render_tiny(&s, &a, false);
    }
    accel_free(&a);
    scene_free(&s);
    return 0;
}
