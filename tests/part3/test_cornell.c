/* Test machinery: not part of any assignment.
 * A statistical image test: on a Cornell box (tests/common/tiny_scenes.c), direct light by
 * uniform hemisphere sampling (-H) and by light importance sampling must render the same image in
 * expectation. The 16 x 12 image is cut into 4 x 4 pixel blocks; each block's mean luminance under
 * the two estimators is compared by Welch's t test, Sidak-corrected over the blocks.
 * alpha: the whole image test is one check at PART3_CHECK_ALPHA (part3_alpha.h, family 1e-3).
 * Seed fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part1_raygen/part1.h"
#include "part3_alpha.h"
#include <stdlib.h>

#define SEED mc_seed(0x5eed3004ull)
#define W 16
#define H 12
#define BLOCK 4
#define SPP 1024

static void render_blocks(tiny_world *w, bool hemisphere, uint64_t seed, stats_acc *blocks)
{
    w->o.hemisphere = hemisphere;
    w->o.max_depth = 1;
    w->o.light_samples = 1;
    w->o.width = W;
    w->o.height = H;
    tiny_world_refresh(w);
    for (int b = 0; b < (W / BLOCK) * (H / BLOCK); b++)
        blocks[b] = stats_acc_make();
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int s = 0; s < SPP; s++) {
                /* Seeded as the renderer seeds a pixel's sample (mc_assert.c says why not rng_seeded). */
                rng g = rng_for_sample(seed, (uint64_t)(y * W + x), (uint64_t)s);
                vec2 j = rng_uniform2(&g);
                ray r = camera_generate_ray(&w->ctx.camera, (x + j.x) / W, (y + j.y) / H);
                rgb L = radiance_estimate(&w->ctx, &r, &g);
                assert_implemented();
                char where[64];
                snprintf(where, sizeof where, "pixel (%d, %d), sample %d", x, y, s);
                assert_radiance_valid(L, hemisphere ? "radiance_estimate -H" : "radiance_estimate", where);
                stats_acc_add(&blocks[(y / BLOCK) * (W / BLOCK) + x / BLOCK], rgb_luminance(L));
            }
}
#define render_blocks(...) PL_AT(render_blocks(__VA_ARGS__))  /* failures name the calling test's line */

static void test_direct__hemisphere_and_importance_sampling_agree_on_cornell_box(void **state)
{
    (void)state;
    tiny_world *w = tiny_world_new();
    assert_non_null(w);
    assert_true(tiny_scene_cornell(&w->s));
    assert_int_equal(PL_OK, tiny_world_finish(w));
    mc_print_seed("cornell -H vs importance", SEED);
    enum { NB = (W / BLOCK) * (H / BLOCK) };
    stats_acc hemi[NB], imp[NB];
    render_blocks(w, true, SEED, hemi);
    render_blocks(w, false, SEED + 1, imp);
    tiny_world_destroy(w);

    double alpha_block = stats_sidak(PART3_CHECK_ALPHA, NB);
    int failed = 0, first = -1;
    stats_result first_r = {0};
    for (int b = 0; b < NB; b++) {
        stats_result r = stats_ttest_two(&hemi[b], &imp[b], alpha_block);
        if (r.reject && failed++ == 0) first = b, first_r = r;
    }
    /* One sentence, naming the first block that differs: it is what the report shows (cut at its length). */
    if (failed)
        PL_FAIL("wrong: direct_hemisphere (-H) and direct_importance disagree on %d of %d blocks of %d x %d pixels; first at "
                "block (%d, %d) from the bottom-left: hemisphere mean %.5g +- %.2g, importance mean %.5g +- %.2g; t = %.2f, "
                "p = %.3g < %.3g: the two estimators must converge to the same direct light", failed, NB, BLOCK, BLOCK,
                first % (W / BLOCK), first / (W / BLOCK), hemi[first].mean, stats_acc_sem(&hemi[first]), imp[first].mean,
                stats_acc_sem(&imp[first]), first_r.stat, first_r.p, alpha_block);
}

int cornell_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_direct__hemisphere_and_importance_sampling_agree_on_cornell_box, test_setup),
    };
    return cmocka_run_group_tests_name("part3: Cornell box image test", tests, NULL, NULL);
}
