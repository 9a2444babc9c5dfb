/* Grader machinery: not part of any assignment.
 * The verdict stage of an image case (grade_image.h): the film the grader received against the
 * course's reference, in the grader's own process. Its facts: the verdict (per block and channel the
 * statistic, the whole image's ratios, the bad pixels, the region that differs), the figures judged
 * beside the image (samples per pixel and where they go, noise, CPU time), the pixels to trace, and
 * the two images, which the report turns into pictures. Nothing here is in words. */
#include "grade_image.h"
#include "grade_fmt.h"
#include "grade_rate.h"
#include "grade_refs.h"
#include "../framework/exr.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

pl_status grade_image_reference(const char *path, image *out, image *var, grade_why *why)
{
    film f = {0};
    exr_info info;
    long bad = 0;
    double n;
    pl_diag diag = pl_diag_default();
    pl_status st = exr_read(path, &f, &info, &diag);
    if (!st) st = film_inputs(&f, out, var, &bad, &n, &diag);
    film_free(&f);
    if (!st && !bad) return PL_OK;
    /* A broken reference is the course's fault, never the student's. */
    *why = grade_why_of(GRADE_WHY_COURSE);
    if (bad) snprintf(why->detail, sizeof why->detail, "the reference %s has %ld bad pixels (run make references)", path, bad);
    else grade_msg(why->detail, sizeof why->detail, "the course's reference: %s", diag.error);
    image_free(out);
    image_free(var);
    return st ? st : PL_ERR_INVALID;
}

/* ---- the figures judged beside the image ----------------------------------------------------- */

bool grade_image_spp_ok(const grade_case_result *c)
{
    return !(c->course_spp > 0) || fabs(c->spp / c->course_spp - 1.0) <= GRADE_SPP_TOLERANCE;
}

bool grade_image_rate_ok(const grade_case_result *c)
{
    return c->rate_distance < 0 || c->rate_distance <= GRADE_RATE_TOLERANCE;
}

bool grade_image_work_ok(const grade_case_result *c)
{
    if (!c->spec->work_check) return true;
    if (!(c->base_cpu > 0) || !(c->cpu > 0)) return false;  /* not measured: nothing to stand on */
    return c->base_is_scan ? c->cpu * GRADE_SCAN_FACTOR <= c->base_cpu : c->cpu <= GRADE_WORK_FACTOR * c->base_cpu;
}

bool grade_image_noise_ok(const grade_case_result *c)
{
    return !c->spec->noise_check || c->noise <= GRADE_NOISE_FACTOR;
}

/* The course's figures, each from the candidate's film or from what the kernel measured of its render,
 * never from what the render's process says of itself (grading/README.md lists them):
 * - an adaptive part 5 spends about the samples the course's does (one that never stops renders the
 *   reference's image at full cost) and where the course's does: its sample-rate map, block by block
 *   (grade_rate.h: a fixed count is not adaptive, however close its mean);
 * - a part 2 BVH saves work: its render's CPU time at most GRADE_WORK_FACTOR times the course's own
 *   part's (a degenerate tree, a tree the traversal ignores, or none, loses its points);
 * - where the case checks its noise, its samples are as noisy as the course's, not more. */
static bool figures_ok(const grade_plan_case *pc, const film *f, double cand_n, const verdict_image *vc,
                       const verdict_image *vr, grade_case_result *c)
{
    const grade_case *k = pc->spec;
    grade_course_figures *course = malloc(sizeof *course);  /* a map of blocks: not for the stack */
    pl_diag diag = pl_diag_default();
    bool ok = course && grade_refs_figures(pc->reference, k, course, &diag) == PL_OK;  /* checked before grading */
    c->rate_distance = -1.0;
    if (ok && grade_spec_adaptive(k)) {
        grade_rate_map *map = malloc(sizeof *map);
        c->spp = cand_n;
        c->course_spp = course->spp;
        if (map) grade_rate_map_of(f, map);
        c->rate_distance = map ? grade_rate_map_distance(map, &course->map) : INFINITY;
        free(map);
    }
    if (k->noise_check) c->noise = verdict_noise_ratio(vc, vr, k->samples, k->reference_samples);
    free(course);
    return ok && grade_image_spp_ok(c) && grade_image_rate_ok(c) && grade_image_work_ok(c) && grade_image_noise_ok(c);
}

/* ---- the pixels to trace ---------------------------------------------------------------------- */

/* One pixel in each of the GRADE_TRACE_PIXELS blocks that differ most by their statistic (the
 * verdict's |t| or z, not the raw difference, which follows the noise: the bright blocks are the noisy
 * ones), each the pixel of its block that differs most for its noise and does not see an emitter. */
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

static void point_at_pixels(const grade_case *k, const image *cand, const image *ref, const image *refvar,
                            grade_case_result *c)
{
    if (cand->width != ref->width || cand->height != ref->height || !c->v.t) return;
    float brightest = 0.0f;
    for (long i = 0; i < (long)ref->width * ref->height; i++)
        if (isfinite(rgb_luminance(ref->pixels[i]))) brightest = fmaxf(brightest, rgb_luminance(ref->pixels[i]));
    int blocks[GRADE_TRACE_PIXELS], n = worst_blocks(&c->v, blocks, GRADE_TRACE_PIXELS);
    for (int j = 0; j < n; j++) {
        float diff = 0.0f;
        long i = block_pixel(k, &c->v, blocks[j], cand, ref, refvar, brightest, &diff);
        if (i < 0) continue;
        /* From the bottom-left, as the renderer and --trace-pixel count them. */
        c->trace[c->num_trace++] = (grade_pixel_fact){(int)(i % cand->width), cand->height - 1 - (int)(i / cand->width), diff};
    }
}

/* ---- the verdict ------------------------------------------------------------------------------ */

void grade_image_judge(const grade_spec *spec, const grade_plan_case *pc, const film *f, const image *refimg,
                       const image *refvar, grade_case_result *c)
{
    const grade_case *k = pc->spec;
    image cand = {0}, candvar = {0};
    long bad;
    double cand_n;
    pl_diag diag = pl_diag_default();
    if (film_inputs(f, &cand, &candvar, &bad, &cand_n, &diag) != PL_OK) {
        c->why = grade_why_of(GRADE_WHY_GRADER);
        grade_msg(c->why.detail, sizeof c->why.detail, "%s", diag.error);
        image_free(&cand), image_free(&candvar);
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
    if (verdict_compute(&vc, &vr, &vp, &c->v, &diag) != PL_OK) {
        c->why = grade_why_of(GRADE_WHY_GRADER);
        grade_msg(c->why.detail, sizeof c->why.detail, "%s", diag.error);
    }
    else {
        c->ran = true;
        bool figures = figures_ok(pc, f, cand_n, &vc, &vr, c);
        c->pass = figures && c->v.pass;
        c->chance_failure = figures && !c->v.pass && !c->v.deterministic && c->v.bad_pixels == 0;
        if (!c->pass && !k->hidden) point_at_pixels(k, &cand, refimg, refvar, c);  /* a hidden case: no pixels */
        /* The two images, for the report's pictures: the candidate's is kept, the reference copied. */
        c->candidate = cand;
        cand = (image){0};
        if (image_alloc(&c->reference, refimg->width, refimg->height) == PL_OK)
            memcpy(c->reference.pixels, refimg->pixels, sizeof *refimg->pixels * (size_t)refimg->width * refimg->height);
        for (int i = 0; i < 3; i++) snprintf(c->images[i], sizeof c->images[i], "%s", pc->images[i]);
    }
    image_free(&cand);
    image_free(&candvar);
}
