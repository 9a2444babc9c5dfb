/* Grader machinery: not part of any assignment. One image case. */
#include "grade_image.h"
#include "grade_figure.h"
#include "grade_guard.h"
#include "grade_rate.h"
#include "grade_refs.h"
#include "../framework/file.h"
#include "../framework/image.h"
#include "../framework/exr.h"
#include "../framework/film.h"
#include "../framework/output.h"
#include <jansson.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define Z_SCALE 5.0f  /* the z-map saturates at |t| = 5 */

/* What the verdict reads of a film: the mean image (R, G, B, top row first), optionally each mean's
 * variance (var: same layout; NULL to skip), the mean sample count per pixel, and the pixels with
 * bad samples. The film adds a NaN, infinite or negative sample as black and counts it in `bad`:
 * such a pixel is made NaN here, so the verdict fails the case naming it. */
static pl_status film_inputs(const film *f, image *out, image *var, long *bad, double *mean_n, pl_diag *diag)
{
    *bad = 0;
    *mean_n = 0.0;
    pl_status st = PL_OK;
    if (image_alloc(out, f->width, f->height) != PL_OK || (var && image_alloc(var, f->width, f->height) != PL_OK))
        st = pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d image", f->width, f->height);
    if (!st) st = film_to_image(f, out, NULL, diag);
    long pixels = (long)f->width * f->height;
    for (long i = 0; !st && i < pixels; i++) {
        const film_pixel *p = &f->pixels[i];
        *mean_n += (double)p->n / (double)pixels;
        if (var)
            var->pixels[i] = rgb_make((float)film_pixel_variance_of_mean(p, 0), (float)film_pixel_variance_of_mean(p, 1),
                                      (float)film_pixel_variance_of_mean(p, 2));
        if (p->bad) {
            out->pixels[i] = rgb_make(NAN, NAN, NAN);
            ++*bad;
        }
    }
    return st;
}

/* The reference, from the course's EXR. */
static pl_status read_reference(const char *path, image *out, image *var, long *bad, double *mean_n, pl_diag *diag)
{
    film f = {0};
    exr_info info;
    pl_status st = exr_read(path, &f, &info, diag);
    if (!st) st = film_inputs(&f, out, var, bad, mean_n, diag);
    film_free(&f);
    return st;
}

/* A streamed film's shape, beyond its size (output_film_receive): every pixel took the case's samples
 * (an adaptive case: 1 to that many), no more bad samples than samples, and sums a real set of
 * samples could have (sum of squares * n >= sum^2, per channel, up to the rounding of film.h).
 * The refusal names neither the pixel nor its values: which pixel is wrong is the render's choice,
 * 14 bits at 160x120 that it could fill with what it read (grade_figure.h). */
static bool film_shape_ok(const film *f, const grade_case *k, bool adaptive, char *why, size_t size)
{
    long pixels = (long)f->width * f->height;
    for (long i = 0; i < pixels; i++) {
        const film_pixel *p = &f->pixels[i];
        bool count_ok = adaptive ? p->n >= 1 && p->n <= (uint32_t)k->samples : p->n == (uint32_t)k->samples;
        bool sums_ok = p->bad <= p->n;
        for (int c = 0; c < 4 && sums_ok; c++) {
            double s = film_sum_value(p->sum[c]), q = film_sum_value(p->sum_sq[c]);
            /* Each square was rounded to 2^-32 on its own, so the sum of squares may fall short of the
             * exact one by up to n * 2^-33. */
            sums_ok = s >= 0 && (q + p->n * 0x1p-32) * p->n >= s * s * (1.0 - 1e-9);
        }
        if (!count_ok && adaptive)
            return grade_msg(why, size, "a pixel of the film took no samples, or more than the case's %d", k->samples), false;
        if (!count_ok)
            return grade_msg(why, size, "a pixel of the film did not take the case's %d samples", k->samples), false;
        if (!sums_ok) return grade_msg(why, size, "a pixel of the film holds sums no samples can have"), false;
    }
    return true;
}

/* An adaptive case: the candidate's flags hold -a. */
static bool adaptive_case(const grade_case *k)
{
    for (int f = 0; f < k->num_flags; f++)
        if (!strcmp(k->flags[f], "-a")) return true;
    return false;
}

/* The signed t of every block, blue below the reference, red above, white at 0, at image size. */
static pl_status write_z_map(const verdict *v, int width, int height, const char *path, pl_diag *diag)
{
    uint8_t *px = malloc((size_t)width * height * 3);
    if (!px) return pl_fail(diag, PL_ERR_NOMEM, "out of memory");
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            int bx = (int)((long)x * v->blocks_x / width), by = (int)((long)y * v->blocks_y / height);
            float t = 0.0f;  /* the channel with the largest |t| */
            for (int ch = 0; ch < 3; ch++) {
                float tc = v->t[((long)by * v->blocks_x + bx) * 3 + ch];
                if (fabsf(tc) > fabsf(t)) t = tc;
            }
            float a = fminf(fabsf(t) / Z_SCALE, 1.0f);
            uint8_t fade = (uint8_t)(255.0f * (1.0f - a) + 0.5f);
            uint8_t *p = px + 3 * ((long)y * width + x);
            p[0] = t > 0 ? 255 : fade;
            p[1] = fade;
            p[2] = t < 0 ? 255 : fade;
        }
    pl_status st = image_write_png_rgb8(px, width, height, path, diag);
    free(px);
    return st;
}

/* A scene under grading/ (a hidden case's) sits in a folder the child may not enter: the render
 * gets a copy of that one file in its tree, removed when the render ends (drop_scene_copy). Other
 * scenes are read where they are. */
static bool scene_for_child(const grade_env *env, const char *tree, const grade_case *k, char *path, size_t size,
                            pl_diag *diag)
{
    /* A public scene is read from the tree's own copy of scenes/: a render sees nothing of the
     * machine but its tree (grade_run.c: its private view may hide the course's root). */
    bool hidden = !strncmp(k->scene, "grading/", 8);
    grade_path(path, size, "%s/%s", hidden ? env->root : tree, k->scene);
    if (!hidden) return true;
    char *data = NULL;
    size_t len = 0;
    const char *base = strrchr(k->scene, '/') + 1;
    pl_status st = file_read_all(path, "scene", GRADE_SCENE_MAX, &data, &len, diag);
    grade_path(path, size, "%s/%s", tree, base);
    if (!st) st = file_write_atomic(path, data, len, diag);
    free(data);
    return st == PL_OK;
}

/* Removes the copy scene_for_child made (a hidden scene stays in reach only while its render runs). */
static void drop_scene_copy(const grade_case *k, const char *scene)
{
    if (!strncmp(k->scene, "grading/", 8)) remove(scene);
}

/* The framework's reasons for refusing what a part made, as the render's log states them, and what
 * the grader says for each: the framework checks a student's tree before any ray uses it
 * (framework/bvh.c, bvh_validate). The log is the render's, so never echoed: its line only selects
 * one of these fixed sentences (the figures in it, node and primitive numbers, stay out). */
static const struct { const char *needle, *says; } framework_reasons[] = {
    {"leaf holds", "a leaf holds more primitives than the leaf size allows"},
    {"leaf covers slots", "a leaf's slots run past the end of prim_index"},
    {"belongs to two leaves", "a slot of prim_index belongs to two leaves"},
    {"is not a primitive", "prim_index holds a number that is not a primitive's"},
    {"is in two leaves", "a primitive is in two leaves"},
    {"reached twice", "a node is reached twice from the root (a cycle or a shared child)"},
    {"exceeds BVH_MAX_DEPTH", "the tree is deeper than BVH_MAX_DEPTH"},
    {"leaf box is not", "a leaf's box does not bound its primitives"},
    {"pokes out", "a child's box pokes out of its parent's"},
    {"not tight", "a node's box is larger than the union of its children's"},
    {"not reachable", "a node is not reachable from the root (num_nodes too large?)"},
    {"is in no leaf", "a primitive is in no leaf"},
    {"num_prims is", "num_prims is not the scene's number of primitives"},
    {"empty scene", "an empty scene must give num_nodes 0"},
    {"num_nodes is", "num_nodes is not in 1 .. 2n - 1"},
    {"count", "a node's count is negative"},
    {"child", "a child's index is not a node of the tree"},
};

/* grade_image.h */
void grade_image_log_reason(const char *log, char *out, size_t size)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    out[0] = '\0';
    if (file_read_all(log, "render log", (size_t)GRADE_LOG_MAX + 4096, &text, &len, &diag) != PL_OK) return;
    const char *tree = strstr(text, "bvh_build made a malformed tree: ");
    if (tree) {
        const char *line_end = strchr(tree, '\n');
        size_t line = line_end ? (size_t)(line_end - tree) : strlen(tree);
        const char *says = "its tree breaks one of bvh_validate's rules";
        for (size_t i = 0; i < sizeof framework_reasons / sizeof framework_reasons[0]; i++) {
            const char *hit = strstr(tree, framework_reasons[i].needle);
            if (hit && hit < tree + line && framework_reasons[i].says) {
                says = framework_reasons[i].says;
                break;
            }
        }
        grade_msg(out, size, "the framework refused the tree bvh_build made: %s (framework/bvh.c, bvh_validate; "
                  "render the case yourself for the node it names)", says);
    }
    else if (strstr(text, "bvh_build failed: "))
        grade_msg(out, size, "bvh_build returned an error, and the render stopped");
    else if (strstr(text, " is not implemented yet\n"))
        grade_msg(out, size, "the render reached a task that is still a stub (\"not implemented yet\")");
    free(text);
}

/* Why a render failed, in the grader's words: the kind of ending, never its exit status or signal
 * number, which the render chooses (8 bits through exit(), 6 through raise()); for an error status,
 * the framework's reason when its log names one the grader knows (grade_image_log_reason). */
static void render_failure(const grade_run_result *rr, const char *log, char *why, size_t size)
{
    char reason[256];
    if (rr->out_of_time) grade_msg(why, size, "the render did not finish: %s", GRADE_OUT_OF_TIME);
    else if (rr->timed_out) grade_msg(why, size, "the render ran past its %d s", GRADE_RENDER_SECONDS);
    else if (rr->exited && (grade_image_log_reason(log, reason, sizeof reason), reason[0]))
        grade_msg(why, size, "the render stopped with an error: %s", reason);
    else if (rr->exited) grade_msg(why, size, "the render exited with an error status (its log says why)");
    else if (rr->status == SIGXCPU) grade_msg(why, size, "the render ran past its CPU time");
    else if (rr->status == SIGSYS) grade_msg(why, size, "the render made a system call the sandbox forbids");
    else if (rr->status == SIGSEGV || rr->status == SIGBUS)
        grade_msg(why, size, "the render crashed: a memory error (a pointer or index out of bounds?)");
    else grade_msg(why, size, "the render was killed by a signal (an abort, a crash or a kill)");
}

/* One render of case k by program bin at `seed`, its film streamed to the grader (into film_pipe)
 * and its log written by the grader; with no_bvh, through the framework's linear scan. Contained as
 * student code is when the grading is a submission's and the program is not the course's own
 * (course: the grader's user, bounded, in the grader's own folder). */
static grade_run_result render_once(const grade_env *env, const char *bin, const char *cwd, const char *scene,
                                    const grade_case *k, bool no_bvh, bool course, const char *log,
                                    grade_capture *film_pipe)
{
    char *argv[GRADE_MAX_FLAGS + 17];
    grade_case_text text;
    grade_case_command(k, bin, scene, NULL, env->seed, env->threads, &text, argv);
    if (no_bvh) {  /* the flag after the program's name; the rest shifted along, NULL included */
        int n = 0;
        while (argv[n]) n++;
        memmove(argv + 2, argv + 1, (size_t)n * sizeof *argv);
        argv[1] = "--no-bvh";
    }
    *film_pipe = (grade_capture){.child_fd = GRADE_FILM_FD, .max = GRADE_FILM_MAX};
    grade_run_opts o = {.wall_seconds = GRADE_RENDER_SECONDS, .deadline = env->deadline, .cwd = cwd, .log_path = log,
                        .log_max = GRADE_LOG_MAX, .untrusted = env->submission != NULL && !course, .bounded = course,
                        .capture = film_pipe};
    return grade_run(argv, &o);
}

/* The work check's baseline: the CPU time of the case rendered where no student code runs, the
 * least of GRADE_BASELINE_RUNS renders (a busy machine only ever adds time). Grading a submission,
 * the course's own renderer with its part 2 (built before any student file was read); in a
 * student's own tree, which holds no course part 2, their renderer through the framework's linear
 * scan, which calls no part 2 code. 0 when a render failed. */
#define GRADE_BASELINE_RUNS 2
static double baseline_cpu(const grade_env *env, const char *tree, int part, const char *scene, grade_case_result *c)
{
    char bin[4200], cwd[4200], log[4200];
    c->base_is_scan = env->submission == NULL;
    if (c->base_is_scan) grade_path(cwd, sizeof cwd, "%s", tree);
    else grade_path(cwd, sizeof cwd, "%s/course", env->work);
    grade_path(bin, sizeof bin, "%s/bin/pathtracer", cwd);
    grade_path(log, sizeof log, "%s/part%d/%s.baseline.log", env->work, part, c->spec->name);
    double best = 0.0;
    for (int run = 0; run < GRADE_BASELINE_RUNS; run++) {
        grade_capture film_pipe;
        grade_run_result rr = render_once(env, bin, cwd, scene, c->spec, c->base_is_scan, !c->base_is_scan, log, &film_pipe);
        free(film_pipe.data);
        if (!rr.exited || rr.status != 0) return 0.0;
        if (run == 0 || rr.cpu_seconds < best) best = rr.cpu_seconds;
    }
    return best;
}

/* The candidate's render, in a child: the student's code never runs in the grader's process, and
 * its film comes back through a pipe, checked for shape, into out; a work_check case also measures
 * the baseline's CPU time and the candidate's. False with c->reason. */
static bool render_candidate(const grade_env *env, const char *tree, int part, grade_case_result *c, film *out)
{
    const grade_case *k = c->spec;
    char log[4096], bin[4096], scene[4096];
    pl_diag diag = pl_diag_default();
    grade_path(log, sizeof log, "%s/part%d/%s.log", env->work, part, k->name);
    grade_path(bin, sizeof bin, "%s/bin/pathtracer", tree);
    if (!scene_for_child(env, tree, k, scene, sizeof scene, &diag)) {
        grade_msg(c->reason, sizeof c->reason, "the course's scene: %s", diag.error);
        return false;
    }
    if (k->work_check) c->base_cpu = baseline_cpu(env, tree, part, scene, c);
    grade_capture film_pipe;
    grade_run_result rr = render_once(env, bin, tree, scene, k, false, false, log, &film_pipe);
    c->cpu = rr.cpu_seconds;
    /* A slow candidate is measured once more: its best time counts, as the baseline's does. */
    if (k->work_check && rr.exited && rr.status == 0 && c->base_cpu > 0 && !grade_case_work_ok(c)) {
        grade_capture again;
        char log2[4200];
        grade_path(log2, sizeof log2, "%s.again", log);
        grade_run_result r2 = render_once(env, bin, tree, scene, k, false, false, log2, &again);
        free(again.data);
        if (r2.exited && r2.status == 0 && r2.cpu_seconds < c->cpu) c->cpu = r2.cpu_seconds;
    }
    drop_scene_copy(k, scene);
    output_film_counts counts;  /* the render's own word about its work: never read */
    bool ok = rr.exited && rr.status == 0;
    if (!ok) render_failure(&rr, log, c->reason, sizeof c->reason);
    else if (film_pipe.overflow || output_film_receive(film_pipe.data, (size_t)film_pipe.len, k->width, k->height, out,
                                                       &counts, &diag) != PL_OK) {
        grade_msg(c->reason, sizeof c->reason, "the render sent no usable film: %s",
                 film_pipe.overflow ? "it sent more than any film of the case takes" : diag.error);
        ok = false;
    }
    else if (!(ok = film_shape_ok(out, k, adaptive_case(k), c->reason, sizeof c->reason)))
        film_free(out);
    free(film_pipe.data);
    return ok;
}

/* The reference, checked before the render: a broken one is the course's fault, never the student's. */
static bool load_reference(const char *ref, image *img, image *var, grade_case_result *c)
{
    long bad = 0;
    double n;
    pl_diag diag = pl_diag_default();
    if (read_reference(ref, img, var, &bad, &n, &diag) == PL_OK && !bad) return true;
    if (bad) grade_msg(c->reason, sizeof c->reason, "the reference %s has %ld bad pixels (run make references)", ref, bad);
    else grade_msg(c->reason, sizeof c->reason, "the course's reference: %s (run make references FORCE=1 CASES=%s)",
                  diag.error, c->spec->name);
    image_free(img);
    image_free(var);
    return false;
}

/* The candidate's EXR, written by the grader from the film it received, for course staff (work/). */
static void write_candidate_exr(const grade_env *env, int part, const grade_case *k, const film *f)
{
    char path[4096];
    grade_path(path, sizeof path, "%s/part%d/%s.exr", env->work, part, k->name);
    exr_info info = {.seed = env->seed, .sample_end = k->samples, .sample_total = k->samples};
    snprintf(info.command, sizeof info.command, "bin/grade: part %d, case %s (streamed film)", part, k->name);
    snprintf(info.version, sizeof info.version, "candidate");
    exr_image img = {f, &info};
    pl_diag diag = pl_diag_default();
    FILE *out = fopen(path, "wb");
    if (!out || exr_encode(out, &img, &diag) != PL_OK) fprintf(stderr, "grade: %s: %s\n", path, diag.error);
    if (out) fclose(out);
}

/* The course's figures, each from the candidate's film or from what the kernel measured of its
 * render, never from what the render's process says of itself (grading/README.md lists them):
 * - an adaptive part 5 spends about the samples the course's does (one that never stops renders the
 *   reference's image at full cost) and where the course's does: its sample-rate map, block by
 *   block (grade_rate.h: a fixed count is not adaptive, however close its mean);
 * - a part 2 BVH saves work: its render's CPU time at most GRADE_WORK_FACTOR times the course's own
 *   part's (a degenerate tree, a tree the traversal ignores, or none, loses its points). */
static bool figures_ok(const char *ref, const grade_case *k, const film *f, double cand_n, grade_case_result *c)
{
    grade_course_figures *course = malloc(sizeof *course);  /* a map of blocks: not for the stack */
    pl_diag diag = pl_diag_default();
    bool ok = course && grade_refs_figures(ref, k, course, &diag) == PL_OK;  /* checked before grading */
    if (!ok) grade_msg(c->reason, sizeof c->reason, "the course's reference: %s", course ? diag.error : "out of memory");
    c->rate_distance = -1.0;
    if (ok && adaptive_case(k)) {
        grade_rate_map *map = malloc(sizeof *map);
        c->spp = cand_n;
        c->course_spp = course->spp;
        if (map) grade_rate_map_of(f, map);
        c->rate_distance = map ? grade_rate_map_distance(map, &course->map) : INFINITY;
        ok = grade_case_spp_ok(c) && grade_case_rate_ok(c);
        free(map);
    }
    if (ok && k->work_check) ok = grade_case_work_ok(c);
    free(course);
    return ok;
}

/* The pixels to trace: one in each of the GRADE_TRACE_PIXELS blocks that differ most by their
 * statistic (the verdict's |t| or z, not the raw difference, which follows the noise: the bright
 * blocks are the noisy ones), each the pixel of its block that differs most for its noise and does
 * not see an emitter. As lines "pixel (x, y) ...: bin/pathtracer <the case's flags> --trace-pixel x y
 * <scene>", x and y from the bottom-left: the command replays exactly the samples the render took. */
#define GRADE_TRACE_PIXELS 3

/* The blocks of v by their largest |t| over the channels, the largest first, into best (up to n). */
static int worst_blocks(const verdict *v, int *best, int n)
{
    int found = 0;
    float top[GRADE_TRACE_PIXELS];
    for (int b = 0; b < v->blocks_x * v->blocks_y; b++) {
        float t = fmaxf(fabsf(v->t[3 * b]), fmaxf(fabsf(v->t[3 * b + 1]), fabsf(v->t[3 * b + 2])));
        if (!(t > 0.0f) || (found == n && t <= top[n - 1])) continue;
        int at = found < n ? found++ : n - 1;  /* a new entry, or the smallest one replaced */
        top[at] = t, best[at] = b;
        for (; at > 0 && top[at - 1] < top[at]; at--) {  /* bubbled up to its place */
            float tt = top[at]; top[at] = top[at - 1], top[at - 1] = tt;
            int bb = best[at]; best[at] = best[at - 1], best[at - 1] = bb;
        }
    }
    return found;
}

/* In block b of the image, the pixel that differs most for the noise its mean should have there (the
 * reference's per-sample variance at the candidate's samples), passing over those that see an
 * emitter (within a quarter of the reference's brightest: their value is the light's own Le, which
 * shows little of the student's estimator); a NaN pixel first. -1 when none. */
static long block_pixel(const grade_case *k, const verdict *v, int b, const image *cand, const image *ref,
                        const image *refvar, float brightest, float *diff)
{
    int bx = b % v->blocks_x, by = b / v->blocks_x, w = cand->width, h = cand->height;
    bool have_var = refvar && refvar->pixels && refvar->width == w && refvar->height == h;
    long best = -1;
    float score = -1.0f;
    for (int y = by * h / v->blocks_y; y < (by + 1) * h / v->blocks_y; y++)
        for (int x = bx * w / v->blocks_x; x < (bx + 1) * w / v->blocks_x; x++) {
            long i = (long)y * w + x;
            float d = fabsf(rgb_luminance(cand->pixels[i]) - rgb_luminance(ref->pixels[i]));
            if (!(d >= 0.0f)) return *diff = d, i;
            if (rgb_luminance(ref->pixels[i]) > 0.25f * brightest) continue;
            double sd = have_var ? sqrt(fmax(0.0, (double)rgb_luminance(refvar->pixels[i])) * k->reference_samples /
                                        k->samples) : 0.0;
            float s = (float)(d / (sd + 1e-3));
            if (s > score) score = s, best = i, *diff = d;
        }
    return best;
}

static void point_at_pixels(const grade_env *env, const grade_case *k, const image *cand, const image *ref,
                            const image *refvar, grade_case_result *c)
{
    if (cand->width != ref->width || cand->height != ref->height || !c->v.t) return;
    float brightest = 0.0f;
    for (long i = 0; i < (long)ref->width * ref->height; i++)
        if (isfinite(rgb_luminance(ref->pixels[i]))) brightest = fmaxf(brightest, rgb_luminance(ref->pixels[i]));
    char flags[512] = "";
    for (int f = 0, len = 0; f < k->num_flags && len < (int)sizeof flags; f++)
        len += snprintf(flags + len, sizeof flags - len, "%s ", k->flags[f]);
    int blocks[GRADE_TRACE_PIXELS], n = worst_blocks(&c->v, blocks, GRADE_TRACE_PIXELS), len = 0;
    for (int j = 0; j < n && len < (int)sizeof c->trace; j++) {
        float diff = 0.0f;
        long i = block_pixel(k, &c->v, blocks[j], cand, ref, refvar, brightest, &diff);
        if (i < 0) continue;
        int x = grade_figure_pixel((int)(i % cand->width), k->width);
        int y = grade_figure_pixel(cand->height - 1 - (int)(i / cand->width), k->height);
        len += snprintf(c->trace + len, sizeof c->trace - len,
                        "pixel (%d, %d), luminance off by %.3g: bin/pathtracer %s-r %d %d -s %d --seed %llu "
                        "--trace-pixel %d %d %s\n", x, y, grade_figure((double)diff, GRADE_FIGURE_DIGITS, 0.0,
                        GRADE_RATIO_MAX), flags, k->width, k->height, k->samples, (unsigned long long)env->seed, x, y,
                        k->scene);
    }
}

/* Pictures for the report: candidate, reference, z-map. */
static void write_pictures(const grade_env *env, int part, grade_case_result *c, const image *cand, const image *ref)
{
    static const char *const kinds[3] = {"candidate", "reference", "z"};
    pl_diag diag = pl_diag_default();
    for (int i = 0; i < 3; i++) {
        char path[4096];
        snprintf(c->images[i], sizeof c->images[i], "part%d_%s_%s.png", part, c->spec->name, kinds[i]);
        grade_path(path, sizeof path, "%s/%s", env->report, c->images[i]);
        pl_status st = i == 0 ? image_write_png(cand, path, &diag)
                     : i == 1 ? image_write_png(ref, path, &diag)
                              : write_z_map(&c->v, cand->width, cand->height, path, &diag);
        if (st != PL_OK) c->images[i][0] = '\0';
    }
}

/* The verdict, in this process, from the film the grader received and the course's reference. */
static void judge(const grade_env *env, const grade_spec *spec, int part, const char *ref, const image *refimg,
                  const image *refvar, const film *f, grade_case_result *c)
{
    const grade_case *k = c->spec;
    image cand = {0}, candvar = {0};
    long bad;
    double cand_n;
    pl_diag diag = pl_diag_default();
    if (film_inputs(f, &cand, &candvar, &bad, &cand_n, &diag) != PL_OK) {
        grade_msg(c->reason, sizeof c->reason, "%s", diag.error);
        image_free(&cand);
        image_free(&candvar);
        return;
    }
    /* The candidate's own variance too: where the reference's samples never varied, coverage is a
     * Bernoulli event it did not see (verdict.h). */
    verdict_image vc = {cand.width, cand.height, (const float *)cand.pixels, (const float *)candvar.pixels};
    verdict_image vr = {refimg->width, refimg->height, (const float *)refimg->pixels, (const float *)refvar->pixels};
    verdict_params vp = verdict_params_default(k->samples);
    vp.known_variance = k->known_variance;
    vp.deterministic = k->rounding;
    vp.grazing = k->grazing;
    vp.relative_tolerance = k->tolerance;
    vp.reference_spp = k->reference_samples;
    if (k->block_side > 0) {
        vp.min_block_pixels = k->block_side * k->block_side;
        vp.min_block_samples = 0;
    }
    vp.family_alpha = spec->family_alpha;
    if (verdict_compute(&vc, &vr, &vp, &c->v, &diag) != PL_OK) grade_msg(c->reason, sizeof c->reason, "%s", diag.error);
    else {
        c->ran = true;
        bool figures = figures_ok(ref, k, f, cand_n, c);
        if (k->noise_check) {  /* as noisy as the course's render, not more (verdict_noise_ratio) */
            c->noise = verdict_noise_ratio(&vc, &vr, k->samples, k->reference_samples);
            figures = figures && c->noise <= GRADE_NOISE_FACTOR;
        }
        c->pass = figures && c->v.pass;
        c->chance_failure = figures && !c->v.pass && !c->v.deterministic && c->v.bad_pixels == 0;
        if (!c->pass && !k->hidden) point_at_pixels(env, k, &cand, refimg, refvar, c);  /* a hidden case: no pixels */
        write_pictures(env, part, c, &cand, refimg);
    }
    image_free(&cand);
    image_free(&candvar);
}

/* One render of the case at env->seed, judged into c. */
static void render_and_judge(const grade_env *env, const grade_spec *spec, const char *tree, int part, const char *ref,
                             const image *refimg, const image *refvar, grade_case_result *c)
{
    film f = {0};
    c->seed = env->seed;
    if (render_candidate(env, tree, part, c, &f)) {
        write_candidate_exr(env, part, c->spec, &f);
        judge(env, spec, part, ref, refimg, refvar, &f, c);
    }
    film_free(&f);
}

unsigned long long grade_confirm_seed(unsigned long long seed)
{
    /* One step of splitmix64: every bit of the seed moves about half of the result's. */
    uint64_t z = (uint64_t)seed + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (unsigned long long)(z % 1000000000000ull);
}

void grade_image_case(const grade_env *env, const grade_spec *spec, const char *tree, int part, grade_case_result *c)
{
    const grade_case *k = c->spec;
    char ref[4096];
    grade_refs_path(env->root, k, part, ref, sizeof ref);
    image refimg = {0}, refvar = {0};
    if (!load_reference(ref, &refimg, &refvar, c)) return;
    render_and_judge(env, spec, tree, part, ref, &refimg, &refvar, c);
    /* Why a second render, and not a smaller alpha: the tests' p-values are exact only as far as a
     * block's sum of samples is normal, and at the 5 to 6 sigma that Sidak's correction asks of each
     * block, the rare bright paths of a path tracer make its tail heavier than the normal's (measured:
     * 8 failures of the solution in 14,000 gradings where 1.4 were due). Two renders at independent
     * seeds both fail with the square of one's chance, whatever the shape of that tail; a biased
     * render fails both. The first failure costs nothing but time. */
    if (c->chance_failure) {
        grade_env again = *env;
        again.seed = grade_confirm_seed(env->seed);
        grade_case_result second;
        memset(&second, 0, sizeof second);
        second.spec = k;
        render_and_judge(&again, spec, tree, part, ref, &refimg, &refvar, &second);
        second.rendered_twice = true;
        second.first_seed = c->seed;
        second.first_p = c->v.p_value;
        verdict_free(&c->v);
        *c = second;
    }
    image_free(&refimg);
    image_free(&refvar);
}
