/* bin/pathtracer: load a scene, build the accelerator, render, write the image and its sidecar.
 * Exit status: 0 success, 2 bad input (flags, scene, camera file, output names), 1 failure while
 * rendering or writing.
 *
 * Read this file top to bottom as the story of one run: main parses the command line (cli.c),
 * run plans the outputs before anything slow happens (output.c: a wrong -f fails in milliseconds,
 * not after an hour's render), loads the scene (dae.c), builds the accelerator (accel.c: the
 * student's BVH once part 2 is done), renders every pixel (render.c, which calls the parts), and
 * writes every file at once or none (output.c). Every step that can fail returns a pl_status with
 * a message in a pl_diag (status.h); this file turns the first one into the exit status. */
#include "camera.h"
#include "cli.h"
#include "clock.h"
#include "dae.h"
#include "envmap.h"
#include "light.h"
#include "camera_file.h"
#include "render.h"
#include "sidecar.h"
#include "colormap.h"
#include "heatmap.h"
#include "output.h"
#include "file.h"
#include "range.h"
#include "trace.h"
#include "visible_light.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- what the user sees while it runs ----------------------------------------------------------- */

/* The progress bar on stderr (only on a terminal: a log file would fill with carriage returns). */
static void print_progress(void *user, int done, int total)
{
    (void)user;
    int width = 40, filled = total ? done * width / total : width;
    fprintf(stderr, "\r  [%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
            total ? done * 100 / total : 100);
    if (done == total) fprintf(stderr, "\n");
    fflush(stderr);
}

/* Prints the step's message, prefixed by the program's name, and returns the exit status to use. */
static int fail(const char *prog, pl_diag *d, int code)
{
    fprintf(stderr, "%s: %s\n", prog, d->error);
    return code;
}

/* ---- the steps of a run ------------------------------------------------------------------------ */

static const char *self_path;  /* argv[0], when it names a file: the binary that runs */

/* A trace shows the code the binary holds: a part file edited since it was built (run from the
 * repository's root, as the grader's commands are) is not in it yet, and the student would read an
 * old story as the new one. A warning on stderr, by dates: make itself decides by content. */
static void warn_if_stale(const char *prog)
{
    struct stat bin, src;
    DIR *parts = self_path && strchr(self_path, '/') && stat(self_path, &bin) == 0 ? opendir("parts") : NULL;
    for (struct dirent *d; parts && (d = readdir(parts));) {
        char dir[512];
        snprintf(dir, sizeof dir, "parts/%s", d->d_name);
        DIR *part = d->d_name[0] != '.' ? opendir(dir) : NULL;
        for (struct dirent *f; part && (f = readdir(part));) {
            size_t n = strlen(f->d_name);
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", dir, f->d_name);
            if (n > 2 && (!strcmp(f->d_name + n - 2, ".c") || !strcmp(f->d_name + n - 2, ".h")) && stat(path, &src) == 0 &&
                src.st_mtime > bin.st_mtime) {
                fprintf(stderr, "%s: warning: %s changed after %s was built: the trace shows the code the binary "
                        "holds; run make first\n", prog, path, self_path);
                closedir(part);
                closedir(parts);
                return;
            }
        }
        if (part) closedir(part);
    }
    if (parts) closedir(parts);
}

/* --trace-pixel: the pixel's paths on stdout instead of a render (framework/trace.h). */
static int trace_run(const render_ctx *ctx, const options *o, const char *prog)
{
    warn_if_stale(prog);
    trace_request req = {o->trace_x, o->trace_y, o->trace_first, o->trace_last, o->trace_json};
    pl_diag diag = pl_diag_default();
    double t0 = clock_seconds();
    if (trace_pixel(ctx, &req, stdout, NULL, &diag) != PL_OK) return fail(prog, &diag, 1);
    /* -v: the cost of the trace itself, on stderr so the trace stays the same from run to run. */
    if (o->verbose) fprintf(stderr, "[pathlab] traced pixel (%d, %d) in %.4f s (BVH built in %.4f s)\n", o->trace_x,
                            o->trace_y, clock_seconds() - t0, ctx->accel->build_seconds);
    return 0;
}

/* The scene file and, with -c, its camera: exit status 2 for bad input, else 0. */
static int load(const options *o, scene *s, const char *prog)
{
    pl_diag diag = pl_diag_default();
    dae_limits limits = dae_limits_default();
    limits.max_primitives = o->max_primitives;
    limits.max_instances = o->max_instances;
    if (dae_load_limited(o->scene_path, &limits, s, &diag) != PL_OK) return fail(prog, &diag, 2);
    if (o->camera_file) {
        if (camera_file_load(o->camera_file, &s->camera, &diag) != PL_OK) {
            scene_free(s);
            return fail(prog, &diag, 2);
        }
        /* Its position is in the file's coordinates; the scene's are relative to its origin. */
        s->camera.position = vec3_make((float)(s->camera.position.x - s->origin[0]),
                                       (float)(s->camera.position.y - s->origin[1]),
                                       (float)(s->camera.position.z - s->origin[2]));
        s->has_camera = true;
    }
    /* -e: the map is the scene's (scene_free releases it), so every later step finds it there. */
    if (o->envmap) {
        s->env = calloc(1, sizeof *s->env);
        pl_status st = s->env ? envmap_load(o->envmap, s->env, &diag)
                              : pl_fail(&diag, PL_ERR_NOMEM, "-e %s: out of memory", o->envmap);
#ifdef PL_HAS_PART8
        /* With part 8 the map is also a light; its tables are built now, once for the render. */
        if (st == PL_OK) st = light_add_environment(s, o->env_uniform, &diag);
#endif
        if (st != PL_OK) {
            scene_free(s);
            return fail(prog, &diag, 2);
        }
    }
    return 0;
}

/* The summary lines of a render (not with -q). */
static void print_summary(const options *o, const scene *s, const accel *a, const render_stats *stats,
                          const output_set *out, double load_seconds, double write_seconds)
{
    double secs = stats->seconds > 0 ? stats->seconds : 1e-9;
    printf("[pathlab] %d primitives (%d triangles, %d spheres), %d lights; loaded in %.4f s\n",
           scene_prim_count(s), s->num_triangles, s->num_spheres, s->num_lights, load_seconds);
    if (a->use_bvh) {
        accel_shape shape = accel_bvh_shape(a);
        printf("[pathlab] BVH: %d nodes built in %.4f s", shape.nodes, a->build_seconds);
        if (o->verbose) printf(" (%d leaves, depth %d, leaf size <= %d)", shape.leaves, shape.depth, o->max_leaf_size);
        printf("\n");
    }
    else
        printf("[pathlab] no BVH (%s): linear scan over every primitive\n",
               o->linear_scan ? "--no-bvh" : "part 2 not implemented");
    int w = o->crop ? o->crop_x1 - o->crop_x0 : o->width, h = o->crop ? o->crop_y1 - o->crop_y0 : o->height;
    printf("[pathlab] rendered %dx%d in %.4f s on %d threads: %llu rays, %.3f million rays/s, %.2f samples/pixel\n",
           w, h, stats->seconds, o->threads, (unsigned long long)stats->rays, stats->rays / secs * 1e-6,
           (double)stats->samples / ((double)w * h));
    if (o->output)
        printf("[pathlab] wrote %s, %s, %s%s%s in %.4f s\n", out->path[OUTPUT_IMAGE], out->path[OUTPUT_RATE_MAP],
               out->path[OUTPUT_SIDECAR], o->heatmap ? ", " : "", o->heatmap ? o->heatmap : "", write_seconds);
    else if (o->heatmap)
        printf("[pathlab] wrote %s\n", o->heatmap);
}

/* Image, rate map, heat map and sidecar: encoded in parallel, renamed into place together (the
 * sidecar last), or none. */
static pl_status write_outputs(output_set *out, const options *o, const sidecar_info *info, const rate_map *rates,
                               const exr_image *exr_out, const image *img, const heatmap *heat, pl_diag *diag)
{
    if (o->output) {
        output_bind_image(out, img, exr_out);
        output_bind(out, OUTPUT_RATE_MAP, rate_map_encode, rates);
        output_bind(out, OUTPUT_SIDECAR, sidecar_encode, info);
    }
    if (o->heatmap) output_bind(out, OUTPUT_HEATMAP, heatmap_encode, heat);
    return output_write(out, OUTPUT_IMAGE, OUTPUT_SIDECAR, diag);
}

/* A render's pixels: the image, and the film (every pixel's accumulators) when they are kept. */
typedef struct {
    bool exr;           /* the film is kept: an EXR output, or the grader's --film-fd */
    int w, h;           /* the window (--crop), else the image */
    image img;
    film fm;
    int *samples;       /* camera samples per pixel: the rate map */
    render_stats stats;
} frame;

static void frame_free(frame *fr)
{
    free(fr->samples);
    image_free(&fr->img);
    film_free(&fr->fm);
}

/* Renders every pixel of the window into fr (freed by the caller, whatever happens); 0 or the exit
 * code. The film is kept only for an EXR (the format the output plan decided), which stores it:
 * other renders resolve each pixel into the image as it finishes (render_image): the same pixels,
 * 144 bytes a pixel less. */
static int render_frame(render_ctx *ctx, const options *o, const output_set *out, const char *prog, frame *fr,
                        pl_diag *diag)
{
    fr->exr = (o->output && out->format == IMAGE_FORMAT_EXR) || o->film_fd >= 0;
    fr->w = ctx->x1 - ctx->x0;
    fr->h = ctx->y1 - ctx->y0;
    fr->samples = calloc((size_t)fr->w * (size_t)fr->h, sizeof *fr->samples);
    if (!fr->samples || image_alloc(&fr->img, fr->w, fr->h) != PL_OK || (fr->exr && film_alloc(&fr->fm, fr->w, fr->h) != PL_OK)) {
        fprintf(stderr, "%s: out of memory for a %dx%d image\n", prog, fr->w, fr->h);
        return 1;
    }
    pl_status rendered = fr->exr ? render_film(ctx, &fr->fm, &fr->stats, diag)
                                 : render_image(ctx, &fr->img, fr->samples, &fr->stats, diag);
    if (rendered != PL_OK || (fr->exr && film_to_image(&fr->fm, &fr->img, fr->samples, diag) != PL_OK))
        return fail(prog, diag, 1);
    /* --film-fd: the film to the grader's pipe, and no file at all. */
    const render_stats *st = &fr->stats;
    output_film_counts counts = {st->rays, st->node_visits, st->prim_tests, st->samples};
    if (o->film_fd >= 0 && output_film_send(o->film_fd, &fr->fm, &counts, diag) != PL_OK) return fail(prog, diag, 1);
    if (st->bad_pixels)
        fprintf(stderr, "%s: warning: %d pixels have NaN, infinite or negative radiance (first at x=%d y=%d, "
                        "counted from the bottom-left)\n", prog, st->bad_pixels, st->first_bad_x, st->first_bad_y);
    return 0;
}

/* Everything after the options are parsed; owns no memory the caller must free. The story of a
 * render: plan the outputs, load, build, render (or trace one pixel), write them as one unit. */
static int run(const options *o, const char *prog)
{
    pl_diag diag = pl_diag_default();
    output_set out;
    scene s;
    int code = output_plan(&out, o, &diag) != PL_OK ? fail(prog, &diag, 2) : 0;
    double t0 = clock_seconds();
    if (code || (code = load(o, &s, prog)) != 0) {
        output_free(&out);
        return code;
    }
    /* What the scene and flags do not do that they might seem to, on stderr; which framing the
     * camera uses and which lights the loader made visible, on the status lines (not in a trace,
     * whose output is the pixel's story alone). */
    cli_warn_noops(o, &s, &diag);
    if (!o->quiet && !o->trace) {
        char line[256];
        camera_framing_line(o, &s, line, sizeof line);
        printf("[pathlab] %s\n", line);
        visible_light_status_line(&s, line, sizeof line);
        if (line[0]) printf("[pathlab] %s\n", line);
        fflush(stdout);
    }
    double load_seconds = clock_seconds() - t0;
    frame fr = {0};
    heatmap heat = {0};
    accel a;
    memset(&a, 0, sizeof a);
    if (accel_build(&a, &s, !o->linear_scan, o->max_leaf_size, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }
    render_ctx ctx;
    render_ctx_init(&ctx, &s, &a, o);
    if (!o->quiet && isatty(STDERR_FILENO)) ctx.on_progress = print_progress;
    if (o->trace) { code = trace_run(&ctx, o, prog); goto done; }

    /* The heat map is drawn now (it reads the BVH's visit counter) but written with the other files. */
    if (o->heatmap && heatmap_render(&ctx, out.path[OUTPUT_HEATMAP], &heat, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }

    if ((code = render_frame(&ctx, o, &out, prog, &fr, &diag)) != 0) goto done;
    double t1 = clock_seconds();
    rate_map rates = {fr.samples, fr.w, fr.h, o->spp};
    sidecar_info info = {&ctx, load_seconds, a.build_seconds, &fr.stats, o->adaptive ? fr.samples : NULL};
    exr_info provenance;
    exr_image exr_out = {&fr.fm, &provenance};
    if (fr.exr && range_info(o, &provenance, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }
    if (write_outputs(&out, o, &info, &rates, &exr_out, &fr.img, &heat, &diag) != PL_OK) { code = fail(prog, &diag, 1); goto done; }
    if (!o->quiet) print_summary(o, &s, &a, &fr.stats, &out, load_seconds, clock_seconds() - t1);
done:
    frame_free(&fr);
    heatmap_free(&heat);
    accel_free(&a);
    scene_free(&s);
    output_free(&out);
    return code;
}

/* ---- main ---------------------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    const char *prog = "pathtracer";
    self_path = argc > 0 ? argv[0] : NULL;
    for (int i = 1; i < argc; i++)  /* a mode of its own, wherever its flag is */
        if (!strcmp(argv[i], "--merge")) return range_merge_main(argc, argv, prog);
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
    int code = run(&o, prog);
    cli_free(&o);
    return code;
}
