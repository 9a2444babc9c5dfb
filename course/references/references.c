/* Instructor tooling: not part of any assignment.
 * bin/references: renders the reference image of every grading case (grading/cases.json) with the
 * solution, as sample ranges merged exactly (framework/range.h; grading/README.md), into
 *   reference_images/part<N>/<case>.exr   mean, variance of the mean, sample count, provenance
 *   reference_images/part<N>/<case>.png   a preview
 *   reference_images/part<N>/<case>.json  the provenance: the key it was made from, command, seed,
 *                                         and the course's figures for the case's own render
 *                                         (samples per pixel, an adaptive case's sample-rate map:
 *                                         probe_case)
 * (hidden cases under reference_images/hidden/, which the student release leaves out)
 * A case is rendered again only when its key changed: the scene file, the case's flags, resolution
 * and samples, or the code (framework/ and parts/ sources). Ranges are files of their own
 * (build/references/part<N>/<case>/<A>-<B>.exr), each complete or absent, so an interrupted run
 * resumes from the finished ranges, and the same ranges can run as a Slurm job array.
 *
 *   bin/references [--force] [--jobs N] [--range S] [CASE...]         render locally
 *   bin/references --slurm [--range S] [--sbatch "ARGS"] [CASE...]   submit ranges + merge job
 *   bin/references --status [CASE...]                                 what is done, missing, stale
 *   bin/references --merge-only [CASE...]                             merge finished ranges (the
 *                                                                     Slurm array's last job)
 *   --out DIR (reference_images) and --work DIR (build/references) move the results and the ranges.
 * CASE is a case name or part<N>; none means every case. */
#include "../../grader/grade_limits.h"
#include "../../grader/grade_plan.h"
#include "../../grader/grade_run.h"
#include "../../grader/grade_spec.h"
#include "../../grader/grade_rate.h"
#include "../../framework/film.h"
#include "../../framework/clock.h"
#include "../../framework/exr.h"
#include "../../framework/file.h"
#include "../../framework/parallel.h"
#include "../shared/key.h"
#include "../shared/slurm.h"
#include <dirent.h>
#include <errno.h>
#include <jansson.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define RANGE_SAMPLES 256        /* samples per range: one range is a few seconds to a minute */
#define REFERENCE_SEED 1000000000000ull  /* above every grading seed (grade draws them below 10^12) */
#define RENDER_SECONDS 3600.0

/* ---- the key: what a reference was made from (course/shared/key.h) ------------------------------- */

/* The flags a case's reference renders with. */
static char *const *ref_flags(const grade_case *c, int *count)
{
    *count = c->num_reference_flags ? c->num_reference_flags : c->num_flags;
    return c->num_reference_flags ? c->reference_flags : c->flags;
}

static void case_key(const grade_case *c, uint64_t code, char out[17])
{
    uint64_t h = key_file(code, c->scene);
    int n;
    char *const *flags = ref_flags(c, &n);
    for (int i = 0; i < n; i++) h = key_str(h, flags[i]);
    /* The case's own render too: the provenance records the course's figures for it (probe_case). */
    for (int i = 0; i < c->num_flags; i++) h = key_str(h, c->flags[i]);
    int numbers[4] = {c->width, c->height, c->reference_samples, c->samples};
    key_hex(key_bytes(h, numbers, sizeof numbers), out);
}

/* ---- one case's jobs -------------------------------------------------------------------------- */

typedef struct {
    const grade_case *spec;
    int part;
    unsigned long long seed;   /* REFERENCE_SEED + a hash of the case's name: stable as cases come and go */
    char key[17];
    char range_dir[512];       /* build/references/part<N>/<case> */
    char out_base[512];        /* reference_images/part<N>/<case> */
    int num_ranges;
} ref_case;

static void range_path(const ref_case *rc, int r, char *out, size_t size)
{
    int a = r * RANGE_SAMPLES, b = a + RANGE_SAMPLES;
    if (b > rc->spec->reference_samples) b = rc->spec->reference_samples;
    snprintf(out, size, "%s/%06d-%06d.exr", rc->range_dir, a, b);
}

/* The command that renders range r, as an argv (owned strings in a static-lifetime buffer). */
typedef struct { char *argv[GRADE_MAX_FLAGS + 24]; char buf[8][1100]; } command;

static void range_command(const ref_case *rc, int r, command *cmd)
{
    int n = 0, nf;
    char *const *flags = ref_flags(rc->spec, &nf);
    int a = r * RANGE_SAMPLES, b = a + RANGE_SAMPLES;
    if (b > rc->spec->reference_samples) b = rc->spec->reference_samples;
    snprintf(cmd->buf[0], sizeof cmd->buf[0], "%d", rc->spec->width);
    snprintf(cmd->buf[1], sizeof cmd->buf[1], "%d", rc->spec->height);
    snprintf(cmd->buf[2], sizeof cmd->buf[2], "%d", rc->spec->reference_samples);
    snprintf(cmd->buf[3], sizeof cmd->buf[3], "%d:%d", a, b);
    snprintf(cmd->buf[4], sizeof cmd->buf[4], "%llu", rc->seed);
    range_path(rc, r, cmd->buf[5], sizeof cmd->buf[5]);
    cmd->argv[n++] = "bin/pathtracer";
    for (int i = 0; i < nf; i++) cmd->argv[n++] = flags[i];
    char *rest[] = {"-r", cmd->buf[0], cmd->buf[1], "-s", cmd->buf[2], "--samples", cmd->buf[3], "--seed", cmd->buf[4],
                    "-t", "1", "-q", "-f", cmd->buf[5], (char *)rc->spec->scene, NULL};
    for (char **p = rest; *p; p++) cmd->argv[n++] = *p;
    cmd->argv[n] = NULL;
}

static bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static int ranges_done(const ref_case *rc)
{
    int done = 0;
    for (int r = 0; r < rc->num_ranges; r++) {
        char path[1200];
        range_path(rc, r, path, sizeof path);
        done += exists(path);
    }
    return done;
}

/* The key recorded beside the reference, or "" when there is none. */
static void recorded_key(const ref_case *rc, char out[17])
{
    char path[600];
    snprintf(path, sizeof path, "%s.json", rc->out_base);
    out[0] = '\0';
    json_t *j = json_load_file(path, JSON_REJECT_DUPLICATES, NULL);
    const char *k = json_string_value(json_object_get(j, "key"));
    if (k) snprintf(out, 17, "%s", k);
    json_decref(j);
}

static bool run_logged(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = RENDER_SECONDS, .log_path = log, .log_max = 1 << 20};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* A reference must hold no bad sample (NaN, infinite or negative radiance): the grader would read
 * such a pixel as a failure of every candidate. A bad sample is the solution's bug, so the merged
 * file is removed and the pixel named, for the instructor to fix the solution. */
static bool reference_clean(const ref_case *rc, const char *path)
{
    film f = {0};
    exr_info info;
    pl_diag d = pl_diag_default();
    if (exr_read(path, &f, &info, &d) != PL_OK) {
        fprintf(stderr, "references: %s: %s\n", rc->spec->name, d.error);
        remove(path);
        return false;
    }
    long bad = 0, first = -1;
    for (long i = 0; i < (long)f.width * f.height; i++)
        if (f.pixels[i].bad && bad++ == 0) first = i;
    if (bad)
        fprintf(stderr, "references: %s: the solution gave %ld pixels bad samples (NaN, infinite or negative "
                        "radiance; the first at x=%ld y=%ld, counted from the bottom-left): fix the solution\n",
                rc->spec->name, bad, first % f.width, f.height - 1 - first / f.width);
    film_free(&f);
    if (bad) remove(path);
    return bad == 0;
}

/* The course's figures for the case's own render (its flags, resolution and samples, not the
 * reference's): the mean samples per pixel and, for an adaptive case, where it spends them, block
 * by block (grader/grade_rate.h: the mean map of GRADE_RATE_RUNS renders at seeds from the
 * reference's). The grader compares a candidate's film with these. */
static json_t *probe_case(const ref_case *rc)
{
    char out[700], log[700];
    snprintf(out, sizeof out, "%s/probe.exr", rc->range_dir);
    snprintf(log, sizeof log, "%s/probe.log", rc->range_dir);
    bool adaptive = false;
    for (int i = 0; i < rc->spec->num_flags; i++) adaptive = adaptive || !strcmp(rc->spec->flags[i], "-a");
    int runs = adaptive ? GRADE_RATE_RUNS : 1;
    static grade_rate_map map, one;
    double spp = 0.0;
    for (int run = 0; run < runs; run++) {
        char *argv[GRADE_MAX_FLAGS + 16];
        grade_case_text text;
        grade_plan_case_command(rc->spec, "bin/pathtracer", rc->spec->scene, out, rc->seed + (unsigned long long)run, 1, false,
                                &text, argv);
        film f = {0};
        exr_info info;
        pl_diag d = pl_diag_default();
        if (!run_logged(argv, log) || exr_read(out, &f, &info, &d) != PL_OK) {
            film_free(&f);
            return NULL;
        }
        grade_rate_map_of(&f, &one);
        if (run == 0) map = one, memset(map.mean, 0, sizeof map.mean);
        grade_rate_map_add(&map, &one, 1.0 / runs);
        for (long i = 0; i < (long)f.width * f.height; i++) spp += (double)f.pixels[i].n / ((double)f.width * f.height * runs);
        film_free(&f);
    }
    json_t *probe = json_pack("{s:f}", "mean_samples_per_pixel", spp);
    if (probe && adaptive && json_object_set_new(probe, "rate_map", grade_rate_map_json(&map)) != 0) {
        json_decref(probe);
        probe = NULL;
    }
    return probe;
}

/* Merges the ranges into the EXR and the preview, then writes the provenance last. */
static bool merge_case(const ref_case *rc)
{
    char *argv[4096 / RANGE_SAMPLES * 64 + 8];
    static char paths[1024][1200];
    if (rc->num_ranges > 1024) return false;
    for (int r = 0; r < rc->num_ranges; r++) range_path(rc, r, paths[r], sizeof paths[r]);
    char out[600], log[600];
    snprintf(log, sizeof log, "%s/merge.log", rc->range_dir);
    static const char *const ext[2] = {".exr", ".png"};
    for (int k = 0; k < 2; k++) {
        int n = 0;
        snprintf(out, sizeof out, "%s%s", rc->out_base, ext[k]);
        argv[n++] = "bin/pathtracer";
        argv[n++] = "--merge";
        argv[n++] = "-f";
        argv[n++] = out;
        for (int r = 0; r < rc->num_ranges; r++) argv[n++] = paths[r];
        argv[n] = NULL;
        if (!run_logged(argv, log)) {
            fprintf(stderr, "references: %s: the merge failed; see %s\n", rc->spec->name, log);
            return false;
        }
        if (k == 0 && !reference_clean(rc, out)) return false;
    }
    command cmd;
    range_command(rc, 0, &cmd);
    /* The render's command without its output file: the same text wherever the ranges were kept. */
    char line[4096] = "";
    for (char **a = cmd.argv; *a; a++) {
        if (!strcmp(*a, "-f") && a[1]) {
            a++;
            continue;
        }
        strncat(line, *a, sizeof line - strlen(line) - 2);
        strcat(line, " ");
    }
    json_t *probe = probe_case(rc);
    if (!probe) {
        fprintf(stderr, "references: %s: the probe render (the case's own flags) failed; see %s/probe.log\n",
                rc->spec->name, rc->range_dir);
        return false;
    }
    json_t *j = json_pack("{s:s, s:s, s:i, s:i, s:I, s:s, s:o}", "key", rc->key, "case", rc->spec->name, "part",
                          rc->part, "samples", rc->spec->reference_samples, "seed", (json_int_t)rc->seed,
                          "command_of_the_first_range", line,  /* without -f */
                          "case_render", probe);
    char *text = json_dumps(j, JSON_INDENT(2) | JSON_SORT_KEYS);
    json_decref(j);
    snprintf(out, sizeof out, "%s.json", rc->out_base);
    pl_diag d = pl_diag_default();
    bool ok = text && file_write_atomic(out, text, strlen(text), &d) == PL_OK;
    free(text);
    return ok;
}

/* ---- local runs: every missing range of every case, on parallel_for_threads ------------------ */

/* One range to render, and the run they share: the list is made before any starts (a range is
 * missing or not when the run begins), the progress line and the verdict under the lock. */
typedef struct {
    const ref_case *rc;
    int range;
} ref_range;

typedef struct {
    ref_range *todo;
    int done, total;
    double start;
    bool failed;
    pthread_mutex_t lock;
} pool;

static void render_one(void *arg, int i)
{
    pool *p = arg;
    const ref_case *rc = p->todo[i].rc;
    int r = p->todo[i].range;
    command cmd;
    range_command(rc, r, &cmd);
    char log[1300];
    snprintf(log, sizeof log, "%s/%d.log", rc->range_dir, r);
    bool ok = run_logged(cmd.argv, log);
    pthread_mutex_lock(&p->lock);
    p->done++;
    if (!ok) {
        p->failed = true;
        fprintf(stderr, "\nreferences: %s range %d failed; see %s\n", rc->spec->name, r, log);
    }
    double elapsed = clock_seconds() - p->start, eta = elapsed / p->done * (p->total - p->done);
    fprintf(stderr, "\r  %d/%d ranges (%s), %.0f s, about %.0f s to go   ", p->done, p->total, rc->spec->name, elapsed, eta);
    pthread_mutex_unlock(&p->lock);
}

/* ---- Slurm ------------------------------------------------------------------------------------ */

/* One task per missing range (course/shared/slurm.h); the final job merges when every task has
 * succeeded. */
static int submit_slurm(ref_case *cases, int n, const char *sbatch_args, const char *out_dir, const char *work_dir)
{
    char dir[600];
    slurm_array array;
    snprintf(dir, sizeof dir, "%s/slurm", work_dir);
    if (!slurm_begin(&array, dir)) return 1;
    for (int i = 0; i < n; i++)
        for (int r = 0; r < cases[i].num_ranges; r++) {
            char path[1200];
            range_path(&cases[i], r, path, sizeof path);
            if (exists(path)) continue;
            command cmd;
            range_command(&cases[i], r, &cmd);
            if (!slurm_add(&array, cmd.argv)) return fprintf(stderr, "references: cannot write %s\n", dir), 1;
        }
    char *merge[GRADE_MAX_PART * GRADE_MAX_CASES + 8] = {"bin/references", "--merge-only", "--out", (char *)out_dir,
                                                          "--work", (char *)work_dir};
    for (int i = 0; i < n; i++) merge[6 + i] = (char *)cases[i].spec->name;
    merge[6 + n] = NULL;
    slurm_ids ids;
    if (!slurm_submit(&array, "pl-ref", merge, "pl-ref-merge", sbatch_args, &ids)) return 1;
    printf("submitted %d range task(s) as job array %s, and the merge as job %s\n", array.count,
           ids.array_id[0] ? ids.array_id : "(none)", ids.final_id);
    printf("follow it with: bin/references --status\n");
    return 0;
}

/* ---- main ------------------------------------------------------------------------------------- */

static bool wanted(const grade_case *c, int part, int argc, char **names)
{
    if (argc == 0) return true;
    for (int i = 0; i < argc; i++) {
        char p[16];
        snprintf(p, sizeof p, "part%d", part);
        if (!strcmp(names[i], c->name) || !strcmp(names[i], p)) return true;
    }
    return false;
}

static int usage(void)
{
    fprintf(stderr, "usage: references [--force] [--jobs N] [--slurm [--sbatch \"ARGS\"]] [--status] [--merge-only] "
                    "[CASE|partN ...]\n");
    return 2;
}

/* ---- the command ---------------------------------------------------------------------------------- */

typedef struct {
    bool force, slurm, status, merge_only;
    int jobs;
    const char *sbatch_args, *out_dir, *work_dir;
    int num_names;       /* the CASE|partN arguments ... */
    char **names;        /* ... (none: every case) */
} ref_options;

/* Flags first, then case or part names; false on anything else. */
static bool parse_args(int argc, char **argv, ref_options *o)
{
    *o = (ref_options){false, false, false, false, (int)sysconf(_SC_NPROCESSORS_ONLN), "", "reference_images",
                       "build/references", 0, NULL};
    int first = 1;
    for (; first < argc && argv[first][0] == '-'; first++) {
        const char *a = argv[first];
        if (!strcmp(a, "--force")) o->force = true;
        else if (!strcmp(a, "--slurm")) o->slurm = true;
        else if (!strcmp(a, "--status")) o->status = true;
        else if (!strcmp(a, "--merge-only")) o->merge_only = true;
        else if (!strcmp(a, "--jobs") && first + 1 < argc) o->jobs = atoi(argv[++first]);
        else if (!strcmp(a, "--sbatch") && first + 1 < argc) o->sbatch_args = argv[++first];
        else if (!strcmp(a, "--out") && first + 1 < argc) o->out_dir = argv[++first];
        else if (!strcmp(a, "--work") && first + 1 < argc) o->work_dir = argv[++first];
        else return false;
    }
    if (o->jobs < 1) o->jobs = 1;
    o->num_names = argc - first;
    o->names = argv + first;
    return true;
}

/* One case asked for, with its key, seed, folders and ranges. */
static void ref_case_init(ref_case *rc, const grade_case *c, int part, uint64_t code, const ref_options *o)
{
    memset(rc, 0, sizeof *rc);
    rc->spec = c;
    rc->part = part;
    rc->seed = REFERENCE_SEED + key_str(KEY_START, c->name) % 1000000ull;
    case_key(c, code, rc->key);
    snprintf(rc->range_dir, sizeof rc->range_dir, "%s/part%d/%s/%s", o->work_dir, rc->part, c->name, rc->key);
    snprintf(rc->out_base, sizeof rc->out_base, "%s/%spart%d/%s", o->out_dir, c->hidden ? "hidden/" : "", rc->part,
             c->name);
    rc->num_ranges = (c->reference_samples + RANGE_SAMPLES - 1) / RANGE_SAMPLES;
}

/* The cases asked for that need rendering (all of them with --force) into cases, their folders
 * made; with --status each is printed instead. Returns how many, or -1 when a folder cannot be made. */
static int cases_to_render(const grade_spec *spec, const ref_options *o, ref_case *cases)
{
    uint64_t code = key_sources(key_sources(KEY_START, "framework"), "parts");
    int n = 0;
    for (int k = 0; k < GRADE_MAX_PART; k++)
        for (int i = 0; i < spec->parts[k].num_cases; i++) {
            const grade_case *c = &spec->parts[k].cases[i];
            if (!wanted(c, k + 1, o->num_names, o->names)) continue;
            ref_case *rc = &cases[n];
            ref_case_init(rc, c, k + 1, code, o);
            char have[17];
            recorded_key(rc, have);
            if (o->status) {
                printf("part%d/%-26s %s  ranges %d/%d\n", rc->part, c->name,
                       !strcmp(have, rc->key) ? "up to date" : have[0] ? "stale     " : "missing   ", ranges_done(rc),
                       rc->num_ranges);
                continue;
            }
            if (!o->force && !strcmp(have, rc->key)) continue;
            char mk[700];
            snprintf(mk, sizeof mk, "mkdir -p '%s' '%s/%spart%d'", rc->range_dir, o->out_dir,
                     c->hidden ? "hidden/" : "", rc->part);
            if (system(mk) != 0) return -1;
            n++;
        }
    return n;
}

/* Every missing range of the n cases, rendered `jobs` at a time; false if any failed. */
static bool render_ranges(ref_case *cases, int n, int jobs)
{
    pool p = {NULL, 0, 0, clock_seconds(), false, PTHREAD_MUTEX_INITIALIZER};
    for (int i = 0; i < n; i++) p.total += cases[i].num_ranges - ranges_done(&cases[i]);
    fprintf(stderr, "references: %d case(s), %d range(s) of %d samples to render on %d job(s)\n", n, p.total,
            RANGE_SAMPLES, jobs);
    p.todo = calloc((size_t)(p.total > 0 ? p.total : 1), sizeof *p.todo);
    if (!p.todo) {
        fprintf(stderr, "references: out of memory\n");
        return false;
    }
    int count = 0;
    for (int i = 0; i < n; i++)
        for (int r = 0; r < cases[i].num_ranges && count < p.total; r++) {
            char path[1200];
            range_path(&cases[i], r, path, sizeof path);
            if (!exists(path)) p.todo[count++] = (ref_range){&cases[i], r};
        }
    p.total = count;
    parallel_for_threads(jobs, count, render_one, &p);
    free(p.todo);
    fprintf(stderr, "\n");
    return !p.failed;
}

/* Each case whose ranges are all there, merged into its reference; 1 if any could not be. */
static int merge_all(ref_case *cases, int n)
{
    int code_exit = 0;
    for (int i = 0; i < n; i++) {
        if (ranges_done(&cases[i]) != cases[i].num_ranges) {
            fprintf(stderr, "references: %s: %d of %d ranges missing; not merged\n", cases[i].spec->name,
                    cases[i].num_ranges - ranges_done(&cases[i]), cases[i].num_ranges);
            code_exit = 1;
            continue;
        }
        if (!merge_case(&cases[i])) code_exit = 1;
        else printf("references: wrote %s.exr, .png, .json\n", cases[i].out_base);
    }
    return code_exit;
}

int main(int argc, char **argv)
{
    ref_options o;
    if (!parse_args(argc, argv, &o)) return usage();
    pl_diag diag = pl_diag_default();
    grade_spec spec;
    if (grade_spec_load(GRADE_CASES, GRADE_HIDDEN_CASES, &spec, &diag) != PL_OK) {
        fprintf(stderr, "references: %s\n", diag.error);
        return 2;
    }
    /* The cases asked for, with their keys; the ones up to date are left alone. */
    static ref_case cases[GRADE_MAX_PART * GRADE_MAX_CASES];
    int n = cases_to_render(&spec, &o, cases), code_exit = 0;
    if (n < 0) code_exit = 1;
    /* On a cluster, what the scheduler still holds: a range neither done nor queued has failed, and
     * --slurm submits it again. */
    else if (o.status) slurm_print_queue("pl-ref,pl-ref-merge");
    else if (n == 0) printf("references: every reference is up to date (--force renders them again)\n");
    else if (o.slurm) code_exit = submit_slurm(cases, n, o.sbatch_args, o.out_dir, o.work_dir);
    else if (!o.merge_only && !render_ranges(cases, n, o.jobs)) code_exit = 1;
    else code_exit = merge_all(cases, n);
    grade_spec_free(&spec);
    return code_exit;
}
