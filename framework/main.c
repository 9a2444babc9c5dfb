/* bin/pathtracer: load a scene, build the accelerator, render, write the image and its sidecar.
 * Exit status: 0 success, 2 bad input (flags, scene, camera file), 1 failure while rendering or writing. */
#include "cli.h"
#include "dae.h"
#include "camera_file.h"
#include "render.h"
#include "sidecar.h"
#include "colormap.h"
#include "heatmap.h"
#include "range.h"
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void print_progress(void *user, int done, int total)
{
    (void)user;
    int width = 40, filled = total ? done * width / total : width;
    fprintf(stderr, "\r  [%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
            total ? done * 100 / total : 100);
    if (done == total) fprintf(stderr, "\n");
    fflush(stderr);
}

typedef struct {
    const char *path;
    const int *samples;
    int width, height, spp;
    pl_diag diag;
    pl_status status;
} rate_job;

static void *write_rate_map(void *arg)
{
    rate_job *job = arg;
    job->status = rate_map_write(job->path, job->samples, job->width, job->height, job->spp, &job->diag);
    return NULL;
}

static int fail(const char *prog, pl_diag *d, int code)
{
    fprintf(stderr, "%s: %s\n", prog, d->error);
    return code;
}

/* Everything after the options are parsed; owns no memory the caller must free. */
static int run(const options *o, const char *prog)
{
    pl_diag diag = pl_diag_default();
    scene s;
    int code = 0;
    image img = {0};
    film fm = {0};
    int *samples = NULL;
    char *json = NULL, *rate = NULL;
    accel a;
    memset(&a, 0, sizeof a);

    double t0 = now_seconds();
    if (dae_load(o->scene_path, &s, &diag) != PL_OK) return fail(prog, &diag, 2);
    if (o->camera_file) {
        if (camera_file_load(o->camera_file, &s.camera, &diag) != PL_OK) {
            scene_free(&s);
            return fail(prog, &diag, 2);
        }
        s.has_camera = true;
    }
    double load_seconds = now_seconds() - t0;

    if (accel_build(&a, &s, !o->linear_scan, o->max_leaf_size, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }
    render_ctx ctx;
    render_ctx_init(&ctx, &s, &a, o);
    if (!o->quiet && isatty(STDERR_FILENO)) ctx.on_progress = print_progress;

    if (o->heatmap && render_heatmap(&ctx, o->heatmap, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }

    samples = calloc((size_t)o->width * (size_t)o->height, sizeof *samples);
    if (!samples || image_alloc(&img, o->width, o->height) != PL_OK || film_alloc(&fm, o->width, o->height) != PL_OK) {
        fprintf(stderr, "%s: out of memory for a %dx%d image\n", prog, o->width, o->height);
        code = 1;
        goto done;
    }
    render_stats stats;
    if (render_film(&ctx, &fm, &stats, &diag) != PL_OK || film_to_image(&fm, &img, samples, &diag) != PL_OK) {
        code = fail(prog, &diag, 1);
        goto done;
    }
    if (stats.bad_pixels)
        fprintf(stderr, "%s: warning: %d pixels have NaN, infinite or negative radiance (first at x=%d y=%d, "
                        "counted from the bottom-left)\n", prog, stats.bad_pixels, stats.first_bad_x, stats.first_bad_y);

    double t1 = now_seconds();
    if (o->output) {
        json = path_with_suffix(o->output, "", ".json");
        rate = path_with_suffix(o->output, "_rate", ".png");
        if (!json || !rate) { fprintf(stderr, "%s: out of memory\n", prog); code = 1; goto done; }
        /* PNG encoding is slow (stb's deflate): the rate map is encoded on a second thread. */
        rate_job job = {rate, samples, o->width, o->height, o->spp, pl_diag_default(), PL_OK};
        pthread_t writer;
        bool threaded = pthread_create(&writer, NULL, write_rate_map, &job) == 0;
        if (!threaded) write_rate_map(&job);
        size_t len = strlen(o->output);
        exr_info provenance;
        exr_image exr = {&fm, &provenance};
        pl_status image_status = len > 4 && !strcasecmp(o->output + len - 4, ".exr")
                                     ? range_info(o, &provenance, &diag) == PL_OK ? exr_write(o->output, &exr, &diag) : PL_ERR_IO
                                     : image_write(&img, o->output, &diag);
        if (threaded) pthread_join(writer, NULL);
        if (image_status != PL_OK || job.status != PL_OK) {
            code = fail(prog, image_status != PL_OK ? &diag : &job.diag, 1);
            goto done;
        }
        sidecar_info info = {load_seconds, a.build_seconds, now_seconds() - t1, &stats, o->adaptive ? samples : NULL};
        if (sidecar_write(json, &ctx, &info, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }
    }
    if (!o->quiet) {
        double secs = stats.seconds > 0 ? stats.seconds : 1e-9;
        printf("[pathlab] %d primitives (%d triangles, %d spheres), %d lights; loaded in %.4f s\n",
               scene_prim_count(&s), s.num_triangles, s.num_spheres, s.num_lights, load_seconds);
        if (a.use_bvh) {
            accel_shape shape = accel_bvh_shape(&a);
            printf("[pathlab] BVH: %d nodes built in %.4f s", shape.nodes, a.build_seconds);
            if (o->verbose) printf(" (%d leaves, depth %d, leaf size <= %d)", shape.leaves, shape.depth, o->max_leaf_size);
            printf("\n");
        }
        else
            printf("[pathlab] no BVH (%s): linear scan over every primitive\n",
                   o->linear_scan ? "--no-bvh" : "part 2 not implemented");
        printf("[pathlab] rendered %dx%d in %.4f s on %d threads: %llu rays, %.3f million rays/s, %.2f samples/pixel\n",
               o->width, o->height, stats.seconds, o->threads, (unsigned long long)stats.rays, stats.rays / secs * 1e-6,
               (double)stats.samples / ((double)o->width * o->height));
        if (o->output) printf("[pathlab] wrote %s, %s, %s\n", o->output, rate, json);
    }
done:
    free(json);
    free(rate);
    free(samples);
    image_free(&img);
    film_free(&fm);
    accel_free(&a);
    scene_free(&s);
    return code;
}

int main(int argc, char **argv)
{
    const char *prog = "pathtracer";
    if (argc > 1 && !strcmp(argv[1], "--merge")) return range_merge_main(argc, argv, prog);
    options o;
    cli_action action;
    pl_diag diag = pl_diag_default();
    if (cli_parse(argc, argv, &o, &action, &diag) != PL_OK) {
        fprintf(stderr, "%s: %s\nTry '%s -h' for help.\n", prog, diag.error, prog);
        return 2;
    }
    if (action == CLI_HELP) {
        cli_print_usage(stdout, prog);
        return 0;
    }
    if (o.output) {
        /* Check the name before a long render, not after. */
        size_t n = strlen(o.output);
        if (!(n > 4 && (!strcasecmp(o.output + n - 4, ".png") || !strcasecmp(o.output + n - 4, ".hdr") ||
                      !strcasecmp(o.output + n - 4, ".exr")))) {
            fprintf(stderr, "%s: -f %s: expected a file name ending in .png, .hdr or .exr\nTry '%s -h' for help.\n", prog, o.output, prog);
            cli_free(&o);
            return 2;
        }
        /* ... and that its folder takes files, so a long render is not lost at the end. */
        const char *slash = strrchr(o.output, '/');
        char folder[4096];
        snprintf(folder, sizeof folder, "%.*s", slash ? (int)(slash - o.output) + 1 : 1, slash ? o.output : ".");
        if (access(folder, W_OK) != 0) {
            fprintf(stderr, "%s: -f %s: cannot write into '%s': %s\n", prog, o.output, folder, strerror(errno));
            cli_free(&o);
            return 2;
        }
    }
    int code = run(&o, prog);
    cli_free(&o);
    return code;
}
