/* Handout figure (handout/part3.md, 3.4): shadow acne, made by bin/acne_figure for figures.sh.
 * Renders a scene's direct light twice, side by side in one PNG: on the left every shadow ray
 * starts at the raw hit point with min_t = EPS_F (CS184's convention), on the right it leaves
 * through spawn_ray_to_light (framework/spawn.h). figures.sh draws scenes/cornell_grazing.dae,
 * which sits 100 m from the origin: floats there are 7.6e-6 apart, so raw hit points lie inside
 * their surfaces by about EPS_F, and the left half is speckled with shadow the light never cast
 * (it prints how much light that loses: 4.4%). --shift D moves a scene D metres further along
 * (1, 1, 1) first. At the origin the same acne is there, only too faint to see (issue 22: 0.76%
 * on the Cornell box's spheres, where light grazes them).
 * The estimator is the framework's own Lambertian light sampling, not part 3's, so the picture
 * shows the same thing in every tree.
 *   bin/acne_figure [--shift D] [-s SPP] [-l N] [-r W H] scene.dae out.png */
#include "../framework/accel.h"
#include "../framework/dae.h"
#include "../framework/frame.h"
#include "../framework/image.h"
#include "../framework/light.h"
#include "../framework/options.h"
#include "../framework/render.h"
#include "../framework/sampler.h"
#include "../framework/spawn.h"
#include "../parts/part1_raygen/part1.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Direct light at h by sampling every light n times, shadow rays raw or spawned. */
static rgb direct_light(const render_ctx *ctx, const ray *r, const hit *h, int n, bool raw, rng *g)
{
    const scene *s = ctx->scene;
    frame f = shading_frame(r, h);
    rgb albedo = s->materials[h->material].albedo, L = rgb_gray(0.0f);
    for (int k = 0; k < s->num_lights; k++)
        for (int j = 0; j < n; j++) {
            light_sample ls;
            float c = 0.0f;
            if (!light_sample_L(&s->lights[k], h->p, rng_uniform2(g), &ls) || !(ls.pdf > 0.0f) ||
                !((c = vec3_dot(ls.wi, f.n)) > 0.0f))
                continue;
            ray shadow = raw ? ray_make(ray_at(r, h->t), ls.wi, EPS_F, ls.dist - EPS_F)
                             : spawn_ray_to_light(r, h, &s->lights[k], &ls);
            if (!render_occluded(ctx, &shadow))
                L = rgb_add(L, rgb_scale(rgb_mul(ls.L, albedo), c * PL_INV_PI / (ls.pdf * (float)n)));
        }
    return L;
}

/* One pixel's mean over spp jittered samples: emission seen directly plus direct light. */
static rgb pixel(const render_ctx *ctx, int x, int y, vec3 shift, int spp, int n, bool raw)
{
    rgb sum = rgb_gray(0.0f);
    for (int k = 0; k < spp; k++) {
        rng g = render_rng(ctx, x, y, k);
        ray r = pixel_sample_ray(&ctx->camera, x, y, ctx->width, ctx->height, rng_uniform2(&g));
        r.o = vec3_add(r.o, shift);
        hit h = {0};
        if (!render_intersect(ctx, &r, &h)) continue;
        if (vec3_dot(h.n, r.d) < 0.0f) sum = rgb_add(sum, ctx->scene->materials[h.material].Le);
        sum = rgb_add(sum, direct_light(ctx, &r, &h, n, raw, &g));
    }
    return rgb_scale(sum, 1.0f / (float)spp);
}

/* Everything in the scene moved by t; the camera follows through the ray origins (pixel). */
static void move_scene(scene *s, vec3 t)
{
    for (int i = 0; i < s->num_triangles; i++) {
        triangle *tr = &s->triangles[i];
        tr->p0 = vec3_add(tr->p0, t), tr->p1 = vec3_add(tr->p1, t), tr->p2 = vec3_add(tr->p2, t);
    }
    for (int i = 0; i < s->num_spheres; i++) s->spheres[i].center = vec3_add(s->spheres[i].center, t);
    for (int i = 0; i < s->num_lights; i++) s->lights[i].position = vec3_add(s->lights[i].position, t);
}

static int usage(void)
{
    fprintf(stderr, "usage: bin/acne_figure [--shift D] [-s SPP] [-l N] [-r W H] scene.dae out.png\n");
    return 2;
}

int main(int argc, char **argv)
{
    float d = 0.0f;
    int spp = 16, n = 4, w = 320, hgt = 240, i = 1;
    for (; i < argc && argv[i][0] == '-'; i++) {
        bool more = i + 1 < argc;
        if (!strcmp(argv[i], "--shift") && more) d = strtof(argv[++i], NULL);
        else if (!strcmp(argv[i], "-s") && more) spp = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-l") && more) n = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-r") && i + 2 < argc) w = atoi(argv[++i]), hgt = atoi(argv[++i]);
        else return usage();
    }
    if (argc - i != 2 || spp < 1 || n < 1 || w < 1 || hgt < 1 || w > 4096 || hgt > 4096 || !(d >= 0.0f)) return usage();
    pl_diag diag = pl_diag_default();
    scene s;
    accel a;
    image img = {0};
    if (dae_load(argv[i], &s, &diag) != PL_OK) {
        fprintf(stderr, "acne_figure: %s\n", diag.error);
        return 2;
    }
    vec3 shift = vec3_make(d, d, d);
    move_scene(&s, shift);
    options o = options_default();
    o.width = w, o.height = hgt;
    render_ctx ctx;
    if (accel_build(&a, &s, true, 4, &diag) != PL_OK || image_alloc(&img, 2 * w, hgt) != PL_OK) {
        fprintf(stderr, "acne_figure: %s\n", diag.error[0] ? diag.error : "out of memory");
        return 1;
    }
    render_ctx_init(&ctx, &s, &a, &o);
    double sum[2] = {0, 0};  /* the mean luminance of each half, printed: how much light acne steals */
    for (int y = 0; y < hgt; y++)  /* pixel y counts from the bottom, image rows from the top */
        for (int x = 0; x < w; x++)
            for (int half = 0; half < 2; half++) {
                rgb c = pixel(&ctx, x, y, shift, spp, n, half == 0);
                image_set(&img, half * w + x, hgt - 1 - y, c);
                sum[half] += rgb_luminance(c);
            }
    printf("acne_figure: mean luminance %g from the raw hit point, %g spawned (%.2f%% darker)\n", sum[0] / ((double)w * hgt),
           sum[1] / ((double)w * hgt), sum[1] > 0 ? 100.0 * (1.0 - sum[0] / sum[1]) : 0.0);
    int rc = image_write_png(&img, argv[i + 1], &diag) == PL_OK ? 0 : 1;
    if (rc) fprintf(stderr, "acne_figure: %s\n", diag.error);
    image_free(&img);
    accel_free(&a);
    scene_free(&s);
    return rc;
}
