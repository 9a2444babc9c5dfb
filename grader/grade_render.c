/* Grader machinery: not part of any assignment.
 * The run stage of an image case (grade_render.h): the candidate's render, in a child (the student's
 * code never runs in the grader's process), its film streamed back through a pipe and checked for
 * shape; for a work_check case, the CPU time of the render and of a baseline in which no student code
 * runs, as the kernel counted them. What the render's process says of itself (its counters, its
 * log's numbers) is never kept: a failure is described by the kind of its ending. */
#include "grade_render.h"
#include "grade_fmt.h"
#include "../framework/exr.h"
#include "../framework/file.h"
#include "../framework/output.h"
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the scene a render reads --------------------------------------------------------------- */

/* A hidden case's scene sits in a folder the child may not enter: the render gets a copy of that
 * one file in its tree (the plan's scene), removed when the render ends. Other scenes are read where
 * they are, from the tree's own copy of scenes/ (a render sees nothing of the machine but its tree). */
static bool scene_copy(const grade_plan_case *pc, grade_why *why)
{
    if (!pc->scene_source[0]) return true;
    char *data = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    pl_status st = file_read_all(pc->scene_source, "scene", GRADE_SCENE_MAX, &data, &len, &diag);
    if (!st) st = file_write_atomic(pc->scene, data, len, &diag);
    free(data);
    if (st) {
        *why = grade_why_of(GRADE_WHY_COURSE);
        grade_msg(why->detail, sizeof why->detail, "the course's scene: %s", diag.error);
    }
    return st == PL_OK;
}

static void scene_drop(const grade_plan_case *pc)
{
    if (pc->scene_source[0]) remove(pc->scene);  /* a hidden scene stays in reach only while its render runs */
}

/* ---- why a render stopped ----------------------------------------------------------------------- */

/* The framework's reason in the render's log (written by the grader from the render's output): a tree
 * the framework refused (the index of bvh_validate's rule its line names), an error from bvh_build, a
 * task still a stub; GRADE_WHY_NONE when the log names no reason the grader knows. Nothing of the log
 * is kept: its line only selects a code. */
static grade_why log_reason(const char *log)
{
    static const char *const needles[] = {
#define NEEDLE(needle, words) needle,
        GRADE_FRAMEWORK_RULES(NEEDLE)
#undef NEEDLE
    };
    char *text = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    grade_why w = grade_why_of(GRADE_WHY_NONE);
    if (file_read_all(log, "render log", (size_t)GRADE_LOG_MAX + 4096, &text, &len, &diag) != PL_OK) return w;
    const char *tree = strstr(text, "bvh_build made a malformed tree: ");
    if (tree) {
        const char *line_end = strchr(tree, '\n');
        size_t line = line_end ? (size_t)(line_end - tree) : strlen(tree);
        w = grade_why_of(GRADE_WHY_RENDER_REFUSED);
        w.count = -1;  /* a rule the grader does not know */
        for (size_t i = 0; i < sizeof needles / sizeof needles[0] && w.count < 0; i++) {
            const char *hit = strstr(tree, needles[i]);
            if (hit && hit < tree + line) w.count = (long)i;
        }
    }
    else if (strstr(text, "bvh_build failed: ")) w = grade_why_of(GRADE_WHY_RENDER_BUILD_ERROR);
    else if (strstr(text, " is not implemented yet\n")) w = grade_why_of(GRADE_WHY_RENDER_STUB);
    free(text);
    return w;
}

grade_why grade_render_log_reason(const char *log)
{
    return log_reason(log);
}

/* Why a render failed: the kind of ending, never its exit status or signal number, which the render
 * chooses (8 bits through exit(), 6 through raise()); for an error status, the framework's reason
 * when its log names one the grader knows. */
static grade_why render_failure(const grade_run_result *rr, const char *log)
{
    grade_why reason = rr->exited ? log_reason(log) : grade_why_of(GRADE_WHY_NONE);
    grade_why_code code = rr->out_of_time ? GRADE_WHY_RENDER_OUT_OF_TIME
                        : rr->timed_out ? GRADE_WHY_RENDER_TIMED_OUT
                        : rr->exited && reason.code != GRADE_WHY_NONE ? reason.code
                        : rr->exited ? GRADE_WHY_RENDER_STATUS
                        : rr->status == SIGXCPU ? GRADE_WHY_RENDER_CPU
                        : rr->status == SIGSYS ? GRADE_WHY_RENDER_SYSCALL
                        : rr->status == SIGSEGV || rr->status == SIGBUS ? GRADE_WHY_RENDER_MEMORY_ERROR
                                                                         : GRADE_WHY_RENDER_SIGNAL;
    grade_why w = code == reason.code ? reason : grade_why_of(code);
    w.limit = GRADE_RENDER_SECONDS;
    return w;
}

/* ---- the film ---------------------------------------------------------------------------------- */

/* A streamed film's shape, beyond its size (output_film_receive): every pixel took the case's samples
 * (an adaptive case: 1 to that many), no more bad samples than samples, and sums a real set of
 * samples could have (sum of squares * n >= sum^2, per channel, up to the rounding of film.h). The
 * refusal names neither the pixel nor its values: which pixel is wrong is the render's choice,
 * 14 bits at 160x120 that it could fill with what it read (grade_figure.h). */
static bool film_shape_ok(const film *f, const grade_case *k, grade_why *why)
{
    bool adaptive = grade_spec_adaptive(k);
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
        if (!count_ok || !sums_ok) {
            *why = grade_why_of(count_ok ? GRADE_WHY_FILM_SUMS : GRADE_WHY_FILM_COUNTS);
            why->count = adaptive ? 0 : k->samples;
            return false;
        }
    }
    return true;
}

/* What the render sent on its pipe, as a film of the case's size and shape; false with why. */
static bool film_received(const grade_capture *pipe, const grade_case *k, film *out, grade_why *why)
{
    output_film_counts counts;  /* the render's own word about its work: never read */
    pl_diag diag = pl_diag_default();
    if (pipe->overflow) return *why = grade_why_of(GRADE_WHY_FILM_TOO_BIG), false;
    if (output_film_receive(pipe->data, (size_t)pipe->len, k->width, k->height, out, &counts, &diag) != PL_OK) {
        *why = grade_why_of(GRADE_WHY_FILM_UNUSABLE);
        grade_msg(why->detail, sizeof why->detail, "%s", diag.error);  /* the framework's words (no number of the film's) */
        return false;
    }
    if (film_shape_ok(out, k, why)) return true;
    film_free(out);
    return false;
}

/* The candidate's EXR, written by the grader from the film it received, for course staff (work/). */
static void write_film(const grade_plan *plan, const grade_plan_case *pc, unsigned long long seed, const film *f)
{
    exr_info info = {.seed = seed, .sample_end = pc->spec->samples, .sample_total = pc->spec->samples};
    snprintf(info.command, sizeof info.command, "bin/grade: part %d, case %s (streamed film)", plan->part, pc->spec->name);
    snprintf(info.version, sizeof info.version, "candidate");
    exr_image img = {f, &info};
    pl_diag diag = pl_diag_default();
    FILE *out = fopen(pc->film, "wb");
    if (!out || exr_encode(out, &img, &diag) != PL_OK) fprintf(stderr, "grade: %s: %s\n", pc->film, diag.error);
    if (out) fclose(out);
}

/* ---- renders -------------------------------------------------------------------------------------- */

/* One render of the case by program bin at seed, its film streamed to the grader (into film_pipe) and
 * its log written by the grader; with no_bvh, through the framework's linear scan. Contained as
 * student code is when the grading is a submission's and the program is not the course's own (course:
 * the grader's user, bounded, in the grader's own folder). */
static grade_run_result render_once(const grade_plan *plan, const grade_env *env, const grade_plan_case *pc,
                                    const char *bin, const char *cwd, bool no_bvh, bool course, unsigned long long seed,
                                    const char *log, grade_capture *film_pipe)
{
    char *argv[GRADE_MAX_FLAGS + 17];
    grade_case_text text;
    grade_plan_case_command(pc->spec, bin, pc->scene, NULL, seed, env->threads, no_bvh, &text, argv);
    *film_pipe = (grade_capture){.child_fd = GRADE_FILM_FD, .max = GRADE_FILM_MAX};
    grade_run_opts o = {.wall_seconds = GRADE_RENDER_SECONDS, .deadline = plan->deadline, .cwd = cwd, .log_path = log,
                        .log_max = GRADE_LOG_MAX, .untrusted = plan->submission && !course, .bounded = course,
                        .capture = film_pipe, .sandbox = &env->sandbox};
    return grade_run(argv, &o);
}

/* The least CPU time of `runs` renders of program bin (a busy machine only ever adds time); 0 when a
 * render failed. */
static double least_cpu(const grade_plan *plan, const grade_env *env, const grade_plan_case *pc, const char *bin,
                        const char *cwd, bool no_bvh, bool course, unsigned long long seed, const char *log, int runs)
{
    double best = 0.0;
    for (int run = 0; run < runs; run++) {
        grade_capture film_pipe;
        grade_run_result rr = render_once(plan, env, pc, bin, cwd, no_bvh, course, seed, log, &film_pipe);
        free(film_pipe.data);
        if (!rr.exited || rr.status != 0) return 0.0;
        if (run == 0 || rr.cpu_seconds < best) best = rr.cpu_seconds;
    }
    return best;
}

bool grade_render_case(const grade_plan *plan, const grade_env *env, const grade_plan_case *pc, unsigned long long seed,
                       film *out, grade_case_result *c)
{
    const grade_case *k = pc->spec;
    c->seed = seed;
    if (!scene_copy(pc, &c->why)) return false;
    /* The work check's baseline: the course's renderer with its part 2 (a submission's grading), or the
     * tree's own through the framework's linear scan, which calls no part 2 code (a student's tree). */
    if (k->work_check) {
        c->base_is_scan = !plan->submission;
        c->base_cpu = least_cpu(plan, env, pc, pc->baseline, pc->baseline_cwd, c->base_is_scan, plan->submission, seed,
                                pc->baseline_log, GRADE_BASELINE_RUNS);
    }
    grade_capture film_pipe;
    grade_run_result rr = render_once(plan, env, pc, plan->pathtracer, plan->tree, false, false, seed, pc->log, &film_pipe);
    c->cpu = rr.cpu_seconds;
    /* The candidate measured as the baseline is: its least time of as many renders. */
    if (k->work_check && rr.exited && rr.status == 0) {
        double again = least_cpu(plan, env, pc, plan->pathtracer, plan->tree, false, false, seed, pc->again_log,
                                 GRADE_BASELINE_RUNS - 1);
        if (again > 0 && again < c->cpu) c->cpu = again;
    }
    scene_drop(pc);
    bool ok = rr.exited && rr.status == 0;
    if (!ok) c->why = render_failure(&rr, pc->log);
    else ok = film_received(&film_pipe, k, out, &c->why);
    free(film_pipe.data);
    if (ok) write_film(plan, pc, seed, out);
    return ok;
}

unsigned long long grade_render_confirm_seed(unsigned long long seed)
{
    /* One step of splitmix64: every bit of the seed moves about half of the result's. */
    uint64_t z = (uint64_t)seed + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (unsigned long long)(z % 1000000000000ull);
}
