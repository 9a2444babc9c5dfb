/* Grader machinery: not part of any assignment. One image case. */
#include "grade_image.h"
#include "grade_guard.h"
#include "../framework/file.h"
#include "../framework/image.h"
#include "../framework/exr.h"
#include "../framework/film.h"
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define RENDER_SECONDS 120
#define LOG_MAX (256 * 1024)
#define Z_SCALE 5.0f  /* the z-map saturates at |t| = 5 */
#define RENDER_MAX (256L << 20)    /* a candidate EXR: far above any case's size */
#define SCENE_MAX (64L << 20)

/* What the grader reads of an EXR the renderer wrote, in this process: the mean image (R, G, B,
 * top row first), optionally each mean's variance (var: same layout; NULL to skip), the mean
 * sample count per pixel, and the pixels with bad samples. The film adds a NaN, infinite or
 * negative sample as black and counts it in `bad`: such a pixel is made NaN here, so the verdict
 * fails the case naming it. */
static pl_status read_film(const char *path, image *out, image *var, long *bad, double *mean_n, pl_diag *diag)
{
    film f = {0};
    exr_info info;
    *bad = 0;
    *mean_n = 0.0;
    pl_status st = exr_read(path, &f, &info, diag);
    if (!st && (image_alloc(out, f.width, f.height) != PL_OK || (var && image_alloc(var, f.width, f.height) != PL_OK)))
        st = pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", path);
    if (!st) st = film_to_image(&f, out, NULL, diag);
    long pixels = (long)f.width * f.height;
    for (long i = 0; !st && i < pixels; i++) {
        const film_pixel *p = &f.pixels[i];
        *mean_n += (double)p->n / (double)pixels;
        if (var)
            var->pixels[i] = rgb_make((float)film_pixel_variance_of_mean(p, 0), (float)film_pixel_variance_of_mean(p, 1),
                                      (float)film_pixel_variance_of_mean(p, 2));
        if (p->bad) {
            out->pixels[i] = rgb_make(NAN, NAN, NAN);
            ++*bad;
        }
    }
    film_free(&f);
    return st;
}

/* The course's figures for the case's own render (recorded by make references): from the
 * reference's provenance JSON, beside its EXR. */
static void read_course_figures(const char *ref_exr, double *spp, double *work)
{
    char path[4200];
    snprintf(path, sizeof path, "%.*s.json", (int)strlen(ref_exr) - 4, ref_exr);
    json_t *j = json_load_file(path, 0, NULL), *r = json_object_get(j, "case_render");
    *spp = json_number_value(json_object_get(r, "mean_samples_per_pixel"));
    *work = json_number_value(json_object_get(r, "work_per_ray"));
    json_decref(j);
}

/* The candidate's work per camera ray (framework-counted node visits plus primitive tests), from
 * the JSON sidecar its render wrote: opened without following a link, read through that descriptor. */
static double read_candidate_work(const char *exr)
{
    char path[4200];
    snprintf(path, sizeof path, "%.*s.json", (int)strlen(exr) - 4, exr);
    int fd = grade_guard_open_child_file(path, 1L << 20);
    if (fd < 0) return -1.0;
    json_t *j = json_loadfd(fd, 0, NULL);
    close(fd);
    double rays = json_number_value(json_object_get(j, "rays_traced"));
    double work = json_number_value(json_object_get(j, "node_visits")) + json_number_value(json_object_get(j, "primitive_tests"));
    json_decref(j);
    return rays > 0 ? work / rays : -1.0;
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
 * gets a copy of that one file, in the part's folder. Other scenes are read where they are. */
static bool scene_for_child(const grade_env *env, int part, const grade_case *k, char *path, size_t size,
                            pl_diag *diag)
{
    snprintf(path, size, "%s/%s", env->root, k->scene);
    if (strncmp(k->scene, "grading/", 8) != 0) return true;
    char *data = NULL;
    size_t len = 0;
    const char *base = strrchr(k->scene, '/') + 1;
    pl_status st = file_read_all(path, "scene", SCENE_MAX, &data, &len, diag);
    snprintf(path, size, "%s/part%d/%s", env->work, part, base);
    if (!st) st = file_write_atomic(path, data, len, diag);
    free(data);
    return st == PL_OK;
}

void grade_image_case(const grade_env *env, const grade_spec *spec, const char *tree, int part, grade_case_result *c)
{
    const grade_case *k = c->spec;
    char out[4096], log[4096], bin[4096], scene[4096], ref[4096];
    pl_diag diag = pl_diag_default();
    snprintf(out, sizeof out, "%s/part%d/renders/%s.exr", env->work, part, k->name);
    snprintf(log, sizeof log, "%s/part%d/%s.log", env->work, part, k->name);
    snprintf(bin, sizeof bin, "%s/bin/pathtracer", tree);
    if (!scene_for_child(env, part, k, scene, sizeof scene, &diag)) {
        snprintf(c->reason, sizeof c->reason, "the course's scene: %s", diag.error);
        return;
    }
    snprintf(ref, sizeof ref, "%s/reference_images/%spart%d/%s.exr", env->root, k->hidden ? "hidden/" : "", part,
             k->name);

    /* The render, in a child: the student's code never runs in the grader's process. */
    char *argv[GRADE_MAX_FLAGS + 16];
    grade_case_text text;
    grade_case_command(k, bin, scene, out, env->seed, env->threads, &text, argv);
    remove(out);
    grade_run_opts o = {RENDER_SECONDS, tree, log, LOG_MAX, NULL, env->submission != NULL};
    grade_run_result rr = grade_run(argv, &o);
    if (!rr.exited || rr.status != 0) {
        char why[128];
        grade_run_describe(&rr, why, sizeof why);
        snprintf(c->reason, sizeof c->reason, "the render %s (its output: %s)", why, log);
        return;
    }

    /* The verdict, from the two files, in this process. */
    image cand = {0}, candvar = {0}, refimg = {0}, refvar = {0};
    long bad;
    double cand_n, ref_n;
    if (read_film(ref, &refimg, &refvar, &bad, &ref_n, &diag) != PL_OK || bad) {
        /* A broken reference is the course's fault, never the student's: say so, not "differs". */
        if (bad) snprintf(c->reason, sizeof c->reason, "the reference %s has %ld bad pixels (run make references)", ref, bad);
        else snprintf(c->reason, sizeof c->reason, "no reference: %s (run make references)", diag.error);
        image_free(&refimg);
        image_free(&refvar);
        return;
    }
    /* The render's file, opened once without following a link (it could name a reference) and read
     * through that descriptor. */
    int fd = grade_guard_open_child_file(out, RENDER_MAX);
    char by_fd[64];
    snprintf(by_fd, sizeof by_fd, "/proc/self/fd/%d", fd);
    pl_status st = fd < 0 ? pl_fail(&diag, PL_ERR_IO, "%s: missing, a link, not a regular file, or over %ld MiB",
                                    out, RENDER_MAX >> 20)
                          : read_film(by_fd, &cand, &candvar, &bad, &cand_n, &diag);
    if (fd >= 0) close(fd);
    if (st != PL_OK) {
        snprintf(c->reason, sizeof c->reason, "the render wrote no readable image: %s", diag.error);
        image_free(&refimg);
        image_free(&refvar);
        image_free(&cand);
        image_free(&candvar);
        return;
    }
    verdict_image vc = {cand.width, cand.height, (const float *)cand.pixels, (const float *)candvar.pixels};
    verdict_image vr = {refimg.width, refimg.height, (const float *)refimg.pixels, (const float *)refvar.pixels};
    verdict_params vp = verdict_params_default(k->samples);
    vp.known_variance = k->known_variance;
    vp.deterministic = k->rounding;
    vp.reference_spp = k->reference_samples;
    if (k->block_side > 0) {
        vp.min_block_pixels = k->block_side * k->block_side;
        vp.min_block_samples = 0;
    }
    vp.family_alpha = spec->family_alpha;
    if (verdict_compute(&vc, &vr, &vp, &c->v, &diag) != PL_OK) {
        snprintf(c->reason, sizeof c->reason, "%s", diag.error);
    }
    else {
        c->ran = true;
        /* The course's figures: an adaptive part 5 must spend about the samples the course's does
         * (one that never stops renders the reference's image at full cost), and a part 2 BVH may
         * do at most GRADE_WORK_FACTOR times the course's work per ray (a correct but degenerate
         * tree, or none, loses its speed points). Both come from files, never from what code printed. */
        double course_spp, course_work;
        read_course_figures(ref, &course_spp, &course_work);
        bool figures_ok = true;
        if (adaptive_case(k) && course_spp > 0) {
            c->spp = cand_n;
            c->course_spp = course_spp;
            figures_ok = fabs(cand_n / course_spp - 1.0) <= GRADE_SPP_TOLERANCE;
        }
        if (k->work_per_ray && course_work > 0) {
            c->work = read_candidate_work(out);
            c->course_work = course_work;
            figures_ok = figures_ok && c->work >= 0 && c->work <= GRADE_WORK_FACTOR * course_work;
        }
        if (k->noise_check) {  /* as noisy as the course's render, not more (verdict_noise_ratio) */
            c->noise = verdict_noise_ratio(&vc, &vr, k->samples, k->reference_samples);
            figures_ok = figures_ok && c->noise <= GRADE_NOISE_FACTOR;
        }
        c->pass = c->v.pass && figures_ok;
        c->score = c->pass ? k->points : 0.0;
        /* Pictures for the report: candidate, reference, z-map. */
        static const char *const kinds[3] = {"candidate", "reference", "z"};
        for (int i = 0; i < 3; i++) {
            char path[4096];
            snprintf(c->images[i], sizeof c->images[i], "part%d_%s_%s.png", part, k->name, kinds[i]);
            snprintf(path, sizeof path, "%s/%s", env->report, c->images[i]);
            st = i == 0 ? image_write_png(&cand, path, &diag)
               : i == 1 ? image_write_png(&refimg, path, &diag)
                        : write_z_map(&c->v, cand.width, cand.height, path, &diag);
            if (st != PL_OK) c->images[i][0] = '\0';
        }
    }
    image_free(&cand);
    image_free(&candvar);
    image_free(&refimg);
    image_free(&refvar);
}
