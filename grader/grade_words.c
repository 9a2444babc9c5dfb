/* Grader machinery: not part of any assignment.
 * The words stage (grade_words.h): every sentence about a grading, from its facts. In order: why
 * something did not happen, the inspection, the protections, then a case's verdict, the unit tests
 * and the run. Each figure a render decides goes through public_figure (grade_figure.h) here, the
 * one place it is formatted. */
#include "grade_words.h"
#include "grade_figure.h"
#include "grade_fmt.h"
#include "grade_image.h"
#include "sandbox.h"
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

/* Channels by index, in the verdict's messages. */
static const char *const channel_names[3] = {"red", "green", "blue"};

/* ---- the figures shown: every number a render decides goes through grade_figure ---------------- */

/* A public case's figure (grade_figure.h: rounded to 3 significant digits, clamped to [lo, hi]). */
static double public_figure(double x, double lo, double hi)
{
    return grade_figure(x, GRADE_FIGURE_DIGITS, lo, hi);
}

static double shown_ratio(double ratio)
{
    return public_figure(ratio, 0.0, GRADE_RATIO_MAX);
}

static long case_pixels(const grade_case *k)
{
    return (long)k->width * k->height;
}

/* The run's time as shown: a render that sleeps chooses it to the millisecond, so it is a figure
 * too (3 significant digits, printed in whole seconds: about 10 bits a run instead of 17 a case). */
double grade_words_seconds(const grade_result *r)
{
    return public_figure(r->seconds, 0.0, GRADE_SECONDS_MAX);
}


/* ---- why something did not happen ---------------------------------------------------------------- */

/* A child's ending, in words: the kind of ending, never the exit status or signal number of a child
 * that ran student code (it chooses them), but for the course's own children. */
void grade_words_ending(const grade_run_result *r, char *out, size_t size)
{
    if (r->out_of_time) grade_msg(out, size, "%s", GRADE_WORDS_OUT_OF_TIME);
    else if (r->timed_out) grade_msg(out, size, "ran past %.0f s", r->seconds);
    else if (!r->exited && r->status == SIGXCPU) grade_msg(out, size, "ran past its CPU time");
    else if (!r->exited && r->status == SIGSYS) grade_msg(out, size, "made a system call the sandbox forbids");
    else if (!r->exited && (r->status == SIGSEGV || r->status == SIGBUS)) grade_msg(out, size, "crashed: a memory error");
    else if (!r->exited) grade_msg(out, size, "was killed by a signal");
    else grade_msg(out, size, "exited with an error status");
}

/* A build step and its file, as the words name them ("the compile of bvh.c", "the link of the suite"). */
static void step_words(const grade_why *w, char *out, size_t size)
{
    if (w->step == GRADE_STEP_COMPILE) grade_msg(out, size, "the compile of %s", w->file);
    else grade_msg(out, size, "the link of %s", w->step == GRADE_STEP_LINK_SUITE ? "the suite" : "the renderer");
}

/* The spec stage's whys: the submitted folder. */
static bool manifest_words(const grade_why *w, const char *folder, char *out, size_t size)
{
    static const char *const kinds[] = {"an entry", "a folder", "a symbolic link", "a special file"};
    switch (w->code) {
    case GRADE_WHY_NO_FOLDER: grade_msg(out, size, "the submission has no parts/%s folder", folder); return true;
    case GRADE_WHY_ENTRY_UNREADABLE: grade_msg(out, size, "parts/%s holds an entry that cannot be read", folder); return true;
    case GRADE_WHY_NOT_A_FILE:
        grade_msg(out, size, "parts/%s holds %s named like C code (.c or .h): submit the file itself", folder,
                  kinds[w->count >= 1 && w->count <= 3 ? w->count : 0]);
        return true;
    case GRADE_WHY_BAD_NAME:
        grade_msg(out, size, "parts/%s holds a .c or .h file whose name has characters other than a-z, 0-9 and _ (or "
                  "more than %d of them): only files named so are built; rename it", folder, GRADE_SOURCE_NAME - 2);
        return true;
    case GRADE_WHY_FILE_TOO_BIG:
        grade_msg(out, size, "parts/%s/%s is over %ld KiB: a part's file is far smaller", folder, w->file,
                  GRADE_SOURCE_BYTES >> 10);
        return true;
    case GRADE_WHY_TOO_MANY_FILES: grade_msg(out, size, "parts/%s holds over %d .c and .h files", folder, GRADE_SOURCE_FILES); return true;
    case GRADE_WHY_FILE_UNREADABLE: grade_msg(out, size, "parts/%s/%s cannot be read as a file", folder, w->file); return true;
    case GRADE_WHY_NOT_TEXT:
        grade_msg(out, size, "parts/%s/%s is not UTF-8 text (a NUL byte or an invalid byte sequence)", folder, w->file);
        return true;
    case GRADE_WHY_NO_C_FILE: grade_msg(out, size, "parts/%s holds no .c file", folder); return true;
    default: return false;
    }
}

/* The build's whys. */
static bool build_words(const grade_why *w, int part, const char *folder, char *out, size_t size)
{
    char step[128], ending[128], inspected[768];
    step_words(w, step, sizeof step);
    switch (w->code) {
    case GRADE_WHY_BUILD_OUT_OF_TIME: grade_msg(out, size, "part %d's build did not finish: %s (%s)", part, GRADE_WORDS_OUT_OF_TIME, step); return true;
    case GRADE_WHY_BUILD_TIMED_OUT: grade_msg(out, size, "part %d's build ran past %ld s: %s", part, w->limit, step); return true;
    case GRADE_WHY_BUILD_OUTPUT:
        grade_msg(out, size, "part %d's build printed more than %d KiB: %s", part, GRADE_LOG_MAX / 1024, step);
        return true;
    case GRADE_WHY_BUILD_MEMORY:
        grade_msg(out, size, "part %d's build ran past its memory limit (%ld MiB) or its CPU time: %s", part,
                  GRADE_COMPILER_MEMORY >> 20, step);
        return true;
    case GRADE_WHY_BUILD_FAILS:
        if (w->step == GRADE_STEP_COMPILE) grade_msg(out, size, "part %d does not compile: %s", part, w->file);
        else grade_msg(out, size, "part %d does not link: %s", part, w->step == GRADE_STEP_LINK_SUITE ? "the suite" : "the renderer");
        return true;
    case GRADE_WHY_NO_OBJECT: grade_msg(out, size, "the compiler made no usable object from %s", w->file); return true;
    case GRADE_WHY_INCLUDES:
        grade_msg(out, size, "parts/%s/%s: includes a file that is neither its part's own, a framework header nor a "
                  "part's header (an absolute path, or one outside the part's folder?): part code may include only those",
                  folder, w->file);
        return true;
    case GRADE_WHY_INSPECTION:
        grade_words_inspection(&w->inspect, inspected, sizeof inspected);
        grade_msg(out, size, "parts/%s/%s: %s", folder, w->file, inspected);
        return true;
    case GRADE_WHY_NOT_INSPECTED:
        grade_words_ending(&w->run, ending, sizeof ending);
        grade_msg(out, size, "parts/%s: its objects could not be inspected (the inspection %s)", folder, ending);
        return true;
    case GRADE_WHY_OWN_BUILD:
        if (w->run.exited) grade_msg(out, size, "the part does not build");
        else grade_words_ending(&w->run, out, size);
        return true;
    default: return false;
    }
}

/* The suite's and a test's whys. */
static bool suite_words(const grade_why *w, char *out, size_t size)
{
    char ending[128];
    switch (w->code) {
    case GRADE_WHY_SUITE_ENDED: grade_words_ending(&w->run, out, size); return true;
    case GRADE_WHY_SUITE_UNREADABLE: grade_msg(out, size, "the suite's results are not what it writes: %s", w->detail); return true;
    case GRADE_WHY_SUITE_NO_RESULTS: grade_msg(out, size, "the suite wrote no readable test results"); return true;
    case GRADE_WHY_SUITE_STOPPED: grade_msg(out, size, "the suite stopped after %ld of %ld tests", w->count, w->limit); return true;
    case GRADE_WHY_SUITE_TOO_MANY:
        grade_msg(out, size, "the suite reported %ld tests, but it has %ld: its results are not the suite's own", w->count, w->limit);
        return true;
    case GRADE_WHY_SUITE_STATUS:
        grade_msg(out, size, w->count == 1 ? "the suite exited with status 1 but reported no failure"
                                           : "the suite exited with an error status");
        return true;
    case GRADE_WHY_TEST_OUT_OF_TIME: grade_msg(out, size, "did not finish: %s", GRADE_WORDS_OUT_OF_TIME); return true;
    case GRADE_WHY_TEST_NOT_RUN: grade_msg(out, size, "did not run: the part's tests ran past their %ld s together", w->limit); return true;
    case GRADE_WHY_JUDGE_UNFINISHED:
        grade_words_ending(&w->run, ending, sizeof ending);
        grade_msg(out, size, "the course's judge of this test did not finish (it %s): please tell the course staff", ending);
        return true;
    default: return false;
    }
}

/* An image case's whys: its render, its film. */
static bool render_words(const grade_why *w, char *out, size_t size)
{
    static const char *const rules[] = {
#define RULE_WORDS(needle, words) words,
        GRADE_FRAMEWORK_RULES(RULE_WORDS)
#undef RULE_WORDS
    };
    long rules_count = (long)(sizeof rules / sizeof rules[0]);
    switch (w->code) {
    case GRADE_WHY_NOT_BUILT: grade_msg(out, size, "the part did not build"); return true;
    case GRADE_WHY_RENDER_OUT_OF_TIME: grade_msg(out, size, "the render did not finish: %s", GRADE_WORDS_OUT_OF_TIME); return true;
    case GRADE_WHY_RENDER_TIMED_OUT: grade_msg(out, size, "the render ran past its %ld s", w->limit); return true;
    case GRADE_WHY_RENDER_REFUSED:
        grade_msg(out, size, "the render stopped with an error: the framework refused the tree bvh_build made: %s "
                  "(framework/bvh.c, bvh_validate; render the case yourself for the node it names)",
                  w->count >= 0 && w->count < rules_count ? rules[w->count] : "its tree breaks one of bvh_validate's rules");
        return true;
    case GRADE_WHY_RENDER_BUILD_ERROR: grade_msg(out, size, "the render stopped with an error: bvh_build returned an error"); return true;
    case GRADE_WHY_RENDER_STUB:
        grade_msg(out, size, "the render stopped with an error: the render reached a task that is still a stub (\"not "
                  "implemented yet\")");
        return true;
    case GRADE_WHY_RENDER_STATUS: grade_msg(out, size, "the render exited with an error status (its log says why)"); return true;
    case GRADE_WHY_RENDER_CPU: grade_msg(out, size, "the render ran past its CPU time"); return true;
    case GRADE_WHY_RENDER_SYSCALL: grade_msg(out, size, "the render made a system call the sandbox forbids"); return true;
    case GRADE_WHY_RENDER_MEMORY_ERROR:
        grade_msg(out, size, "the render crashed: a memory error (a pointer or index out of bounds?)");
        return true;
    case GRADE_WHY_RENDER_SIGNAL: grade_msg(out, size, "the render was killed by a signal (an abort, a crash or a kill)"); return true;
    case GRADE_WHY_FILM_UNUSABLE: grade_msg(out, size, "the render sent no usable film: %s", w->detail); return true;
    case GRADE_WHY_FILM_TOO_BIG:
        grade_msg(out, size, "the render sent no usable film: it sent more than any film of the case takes");
        return true;
    case GRADE_WHY_FILM_COUNTS:
        if (w->count == 0) grade_msg(out, size, "the render sent no usable film: a pixel of the film took no samples, or "
                                     "more than the case's");
        else grade_msg(out, size, "the render sent no usable film: a pixel of the film did not take the case's %ld samples", w->count);
        return true;
    case GRADE_WHY_FILM_SUMS: grade_msg(out, size, "the render sent no usable film: a pixel of the film holds sums no samples can have"); return true;
    default: return false;
    }
}

void grade_words_why(const grade_why *w, int part, const char *folder, char *out, size_t size)
{
    out[0] = '\0';
    if (manifest_words(w, folder, out, size) || build_words(w, part, folder, out, size) || suite_words(w, out, size) ||
        render_words(w, out, size))
        return;
    if (w->code == GRADE_WHY_COURSE) grade_msg(out, size, "%s (the course's problem, not your submission's: please tell "
                                               "the course staff)", w->detail);
    else if (w->code == GRADE_WHY_GRADER) grade_msg(out, size, "the grader could not go on (%s): please tell the course staff", w->detail);
}

/* A case that did not run, in Markdown: its why's words, escaped. */
static void not_run_text(const grade_case_result *c, int part, const char *folder, char *out, size_t size)
{
    char why[1024], escaped[2100];
    grade_words_why(&c->why, part, folder, why, sizeof why);
    grade_md_escape(why, strlen(why), escaped, sizeof escaped);
    snprintf(out, size, "**did not run**: %s", escaped);
}

/* ---- the inspection ------------------------------------------------------------------------------- */

void grade_words_inspection(const grade_inspect_verdict *v, char *out, size_t size)
{
    bool named = v->name[0] != '\0';  /* a name the course knows (grade_inspect_keep_known); else described */
    switch (v->code) {
    case GRADE_INSPECT_BOUND:
        if (v->known == GRADE_NAME_BOUND && v->name[0] == 'a')
            grade_msg(out, size, "has %s over %ld bytes long: far more than plain C compiles to", v->name, v->bound);
        else if (v->known == GRADE_NAME_BOUND)
            grade_msg(out, size, "has over %ld %s: far more than a part's file compiles to", v->bound, v->name);
        else grade_msg(out, size, "could not be inspected within the grader's memory");
        break;
    case GRADE_INSPECT_BYTECODE: grade_msg(out, size, "holds link-time optimisation bytecode, not machine code"); break;
    case GRADE_INSPECT_BEFORE_MAIN:
        if (named) grade_msg(out, size, "has a %s section: code the C runtime runs outside the part's tasks (a constructor or "
                             "destructor), which part code may not have", v->name);
        else grade_msg(out, size, "has an array of functions the C runtime calls (a constructor or destructor), which part "
                       "code may not have");
        break;
    case GRADE_INSPECT_SECTION:
        grade_msg(out, size, "has a section of a kind plain C does not compile to (a section attribute, or assembly?): part "
                  "code may hold only code, data, read-only and zero-filled data, notes, unwind tables and debug information");
        break;
    case GRADE_INSPECT_IFUNC:
        grade_msg(out, size, "defines an indirect function (an IFUNC, whose resolver the program's loader runs before "
                  "main), which part code may not");
        break;
    case GRADE_INSPECT_SYMBOL_KIND: grade_msg(out, size, "has a symbol of a type or binding plain C does not make (assembly?)"); break;
    case GRADE_INSPECT_RESERVED:
        grade_msg(out, size, "defines a global name reserved to the C implementation (one that starts with an underscore, or "
                  "main, names the C runtime calls): make it static, or rename it");
        break;
    case GRADE_INSPECT_REDEFINES:
        if (v->known == GRADE_NAME_LIBRARY)
            grade_msg(out, size, "defines '%s', which a library of the program already defines: part code may not replace "
                      "library functions (rename it, or make it static)", v->name);
        else if (v->known == GRADE_NAME_FRAMEWORK)
            grade_msg(out, size, "defines '%s', which the framework or another part already defines (rename it, or make it "
                      "static)", v->name);
        else grade_msg(out, size, "defines a name the framework or a library already defines (rename it, or make it static)");
        break;
    case GRADE_INSPECT_CALL:
        if (v->known == GRADE_NAME_LIBRARY)
            grade_msg(out, size, "calls '%s', a C library function part code may not use (handout/README.md, \"What your "
                      "part may call\", lists what it may)", v->name);
        else if (v->known == GRADE_NAME_FRAMEWORK)
            grade_msg(out, size, "calls '%s', a framework function part code may not call (its declaration has no "
                      "PL_PART_API: it is the framework's own)", v->name);
        else grade_msg(out, size, "refers to a name that is on no list of what part code may call and that no other file of "
                       "the part defines as global (a static function of another file?)");
        break;
    default: grade_msg(out, size, "is not an object file of this machine that the course's compiler makes");
    }
}

/* ---- the protections ------------------------------------------------------------------------------ */

void grade_words_protections_missing(const grade_sandbox *s, char *out, size_t size)
{
    snprintf(out, size, "%s%s%s%s", s->as_other_user ? "" : "not root: student code ran as your own user, "
                                                          "and could read what you can; ",
             s->no_network ? "" : "no network namespace: student code had the network; ",
             s->filter ? "" : "no system-call filter: ", s->filter ? "" : s->filter_why);
    size_t n = strlen(out);
    if (n >= 2 && !strcmp(out + n - 2, "; ")) out[n - 2] = '\0';
}

void grade_words_protections_in_force(const grade_sandbox *s, char *out, size_t size)
{
    char filter[64], view[256];
    sandbox_filter_name(filter, sizeof filter);
    if (s->isolated)
        snprintf(view, sizeof view, "PID and mount namespaces: own /proc, all read-only but a stage's output, private "
                                    "/tmp, /var/tmp and /dev/shm of %ld MiB each, a /dev of null, zero and urandom",
                 GRADE_TMP_BYTES >> 20);
    else
        snprintf(view, sizeof view, "no PID or mount namespace: the shared /tmp, /var/tmp and /dev/shm are swept of "
                                    "the sandbox user's files after each stage, and bounded only per file");
    snprintf(out, size, "%s; %s; %s; %s; limits: wall, CPU, address space (%ld MiB code, %ld MiB compiler), "
                        "%ld processes, files of %ld MiB, output cut at %d KiB; orphans killed",
             s->as_other_user ? "student code as user nobody" : "student code as the grader's own user",
             s->no_network ? "network namespace" : "no network namespace", view,
             s->filter ? filter : "no system-call filter", GRADE_CODE_MEMORY >> 20, GRADE_COMPILER_MEMORY >> 20,
             (long)GRADE_PROCESSES, GRADE_FILE_BYTES >> 20, GRADE_LOG_MAX / 1024);
}


/* ---- an image case ---------------------------------------------------------------------------- */

/* A deterministic case's verdict: how many pixels are beyond the rounding tolerance, against the
 * ties allowed, and the largest difference. A pass within the tolerance is never called a failure. */
static int rounding_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    int len = snprintf(out, size, "%s: %ld pixels differ by more than the rounding tolerance %.1e (at most %ld may: "
                       "rays that graze an edge go either way); the largest difference is %.3g",
                       v->pass ? "**matches the reference** up to rounding" : "**differs from the reference**",
                       grade_figure_count(v->beyond_tolerance, case_pixels(k)), v->tolerance, v->tie_pixels,
                       public_figure(v->max_diff, 0.0, GRADE_RATIO_MAX));
    if (len >= 0 && (size_t)len < size && v->max_x >= 0)
        len += snprintf(out + len, size - len, ", in the %s channel at x=%d y=%d (from the bottom-left)",
                        channel_names[v->max_channel % 3], grade_figure_pixel(v->max_x, k->width),
                        grade_figure_pixel(v->max_y, k->height));
    if (len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, ". relMSE %.3g, mean ratio red %.3g green %.3g blue %.3g.",
                        public_figure(v->rel_mse, 0.0, GRADE_REL_MSE_MAX), shown_ratio(v->ratio[0]), shown_ratio(v->ratio[1]),
                        shown_ratio(v->ratio[2]));
    return len;
}

/* Whether case k's flags hold flag. */
static bool case_has_flag(const grade_case *k, const char *flag)
{
    for (int i = 0; i < k->num_flags; i++)
        if (!strcmp(k->flags[i], flag)) return true;
    return false;
}

/* An adaptive case's figures: its mean samples per pixel, and where it spends them (the map). */
static int adaptive_text(const grade_case_result *c, char *out, size_t size)
{
    bool ok = grade_image_spp_ok(c);
    int len = snprintf(out, size, " Samples per pixel: %.3g on average, the course's %.3g (%s %.0f%%).",
                       public_figure(c->spp, 0.0, GRADE_SPP_MAX), public_figure(c->course_spp, 0.0, GRADE_SPP_MAX),
                       ok ? "within" : "more than", 100.0 * GRADE_SPP_TOLERANCE);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " %s", c->spp > c->course_spp
                        ? "Pixels stop later than the course's: adaptive_converged says yes too late (is I = 1.96 "
                          "sqrt(var / n) the mean's error, with var / n and not var alone?)."
                        : "Pixels stop earlier than the course's: adaptive_converged says yes too early (check I = "
                          "1.96 sqrt(var / n) <= maxTolerance x mean, on the samples' luminance).");
    if (c->rate_distance < 0 || len < 0 || (size_t)len >= size) return len;
    ok = grade_image_rate_ok(c);
    len += snprintf(out + len, size - len, " Where the samples go (the sample-rate map, block by block): yours misses "
                    "%.2g%% of the course's variation from block to block (at most %.0f%%).",
                    public_figure(100.0 * c->rate_distance, 0.0, 1e6), 100.0 * GRADE_RATE_TOLERANCE);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " The course's render spends many samples where the image is noisy and "
                        "few where it is smooth; yours does not: does each pixel stop by its own confidence interval "
                        "(task 5.1), rather than after a number of samples?");
    return len;
}

/* A work_check case's figure: the render's CPU time against the baseline's (grade_image.c). */
static int work_text(const grade_case_result *c, char *out, size_t size)
{
    bool ok = grade_image_work_ok(c);
    int len = c->base_is_scan
        ? snprintf(out, size, " CPU time: %.3gx faster than the framework's linear scan on this case (at least %.0fx).",
                   public_figure(c->cpu > 0 ? c->base_cpu / c->cpu : 0.0, 0.0, GRADE_RATIO_MAX), GRADE_SCAN_FACTOR)
        : snprintf(out, size, " CPU time: %.3gx the course's BVH on this case (at most %.0fx).",
                   public_figure(c->base_cpu > 0 ? c->cpu / c->base_cpu : 0.0, 0.0, GRADE_RATIO_MAX), GRADE_WORK_FACTOR);
    if (!ok && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " The image is right, but the tree does not save work: check the SAH split, "
                        "the leaf size, the nearest-first traversal, skipping boxes entered beyond the nearest hit, and "
                        "stopping a shadow ray at its first hit (tasks 2.2 to 2.4).");
    return len;
}

/* The figures of a public case's own render beside its image (samples per pixel and where they go,
 * noise, CPU time), where the case judges them. A hidden case shows none: its verdict alone. */
static int figures_text(const grade_case_result *c, char *out, size_t size)
{
    int len = 0;
    if (c->course_spp > 0) len += adaptive_text(c, out, size);
    if (c->spec->noise_check && len >= 0 && (size_t)len < size) {
        bool ok = c->noise <= GRADE_NOISE_FACTOR;
        len += snprintf(out + len, size - len, " Noise per sample: %.3g x the course's (%s %.2fx).",
                        shown_ratio(c->noise), ok ? "within" : "more than", GRADE_NOISE_FACTOR);
        /* A cause only when the mean passed: an image whose mean is off is that first (where_text),
         * and its noise follows. A case that prescribes --no-rr says so, since then no roulette rule
         * (the handout allows several) can be the cause. */
        if (!ok && c->ran && c->v.pass && (size_t)len < size)
            len += snprintf(out + len, size - len, " The image is right on average but noisier than it should be%s: "
                            "does every one of the -l light samples draw its own random numbers, and are they spent "
                            "where the handout says?",
                            case_has_flag(c->spec, "--no-rr") ? " (the case renders with --no-rr, so roulette is not "
                            "the cause)" : "");
    }
    if (c->spec->work_check && c->ran && len >= 0 && (size_t)len < size) len += work_text(c, out + len, size - len);
    return len;
}

/* The mean of the lit channels' ratios (NaN when none is lit): a hidden case's one figure. */
static double mean_ratio(const verdict *v)
{
    return grade_result_mean_ratio(v);
}

/* The region a failed verdict differs in: its blocks' extent as pixels, and their brightness. Most of
 * the image (three blocks in four or more, as when a constant is missing on every surface but the
 * lights) is said as the whole image first: that is where to look. */
static int region_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    /* Blocks to pixels from the bottom-left, as the renderer and --trace-pixel count them. */
    int x0 = v->region_x0 * k->width / v->blocks_x, x1 = (v->region_x1 + 1) * k->width / v->blocks_x - 1;
    int y1 = k->height - 1 - v->region_y0 * k->height / v->blocks_y;
    int y0 = k->height - (v->region_y1 + 1) * k->height / v->blocks_y;
    int blocks = v->blocks_x * v->blocks_y;
    bool most = 4 * v->region_blocks >= 3 * blocks;
    char how[96];
    if (most) snprintf(how, sizeof how, "The whole image is %s, but not by one factor", v->region_ratio > 1.0 ? "too bright" : "too dark");
    else snprintf(how, sizeof how, "The image differs in a region");
    return snprintf(out, size, " %s: %d of its %d blocks, within x = %d..%d and y = %d..%d (from the bottom-left), are "
                    "%.3g times the reference's brightness together%s.", how, v->region_blocks, blocks,
                    grade_figure_pixel(x0, k->width), grade_figure_pixel(x1, k->width), grade_figure_pixel(y0, k->height),
                    grade_figure_pixel(y1, k->height), public_figure(v->region_ratio, 0.0, GRADE_RATIO_MAX),
                    most ? "; look for a factor that applies to most surfaces before a place"
                         : "; the rest matches: look at what that region shows (one object, one light, one material?)");
}

/* Where a statistical verdict failed: the first bad pixel, or the block (or the whole image) that
 * differs most, and the hint. */
static int where_text(const grade_case *k, const verdict *v, char *out, size_t size)
{
    int len = 0;
    if (v->bad_pixels)
        len = snprintf(out, size, " %ld pixels are NaN, infinite or negative; the first at x=%d y=%d (from the "
                       "bottom-left).", grade_figure_count(v->bad_pixels, case_pixels(k)),
                       grade_figure_pixel(v->bad_x, k->width), grade_figure_pixel(v->bad_y, k->height));
    /* In order of likelihood: bad pixels; then one factor everywhere (a mean off by more than 5%, far
     * beyond a case's noise, with the differing blocks agreeing on it); then a region (the blocks
     * that differ, named with their ratio); then the one block, or channel, that differs most. */
    else if (!v->pass && !v->deterministic && v->uniform_factor && fabs(mean_ratio(v) - 1.0) > 0.05)
        len = snprintf(out, size, " The whole image is %s: %.3g times the reference's brightness on average, and its "
                       "blocks agree, so look for a factor that applies everywhere before a place.",
                       mean_ratio(v) > 1.0 ? "too bright" : "too dark", public_figure(mean_ratio(v), 0.0, GRADE_RATIO_MAX));
    else if (!v->pass && !v->deterministic && v->region_blocks > 0)
        len = region_text(k, v, out, size);
    else if (!v->pass && !v->deterministic && v->worst_block_x >= 0)
        len = snprintf(out, size, " Most different: the %s channel of block (%d, %d) from the top-left (t = %+.3g: %s "
                       "than the reference).", channel_names[v->worst_channel % 3],
                       grade_figure_pixel(v->worst_block_x, v->blocks_x), grade_figure_pixel(v->worst_block_y, v->blocks_y),
                       public_figure(v->worst_t, -GRADE_T_MAX, GRADE_T_MAX), v->worst_t > 0 ? "brighter" : "darker");
    else if (!v->pass && !v->deterministic)  /* one block: the whole image (rounding_text says where for the rest) */
        len = snprintf(out, size, " The whole image's %s channel is %s than the reference (t = %+.3g).",
                       channel_names[v->worst_channel % 3], v->worst_t > 0 ? "brighter" : "darker",
                       public_figure(v->worst_t, -GRADE_T_MAX, GRADE_T_MAX));
    /* The hint's factor is measured where it is telling (verdict.c: pixels that see no light directly),
     * so it may differ from the whole image's ratio above: said so, or the two read as a contradiction. */
    if (!v->pass && v->hint[0] && len >= 0 && (size_t)len < size)
        len += snprintf(out + len, size - len, " Hint%s: %s.",
                        strncmp(v->hint, "about ", 6) ? "" : ", from the pixels that do not see a light directly", v->hint);
    return len;
}


/* A hidden case: its scene is the course's secret, and its render may have read it, so the student
 * sees its verdict alone, passed or failed: no figure, no pixel or block, no trace command, nothing
 * of what its render made (grading/README.md, "What reaches the student"). */
static void hidden_case_text(const grade_case_result *c, int part, const char *folder, char *out, size_t size)
{
    if (!c->ran) {
        not_run_text(c, part, folder, out, size);
        return;
    }
    snprintf(out, size, "%s (a hidden case: its verdict alone is shown).%s",
             c->pass ? "**passes**" : "**fails**",
             c->rendered_twice ? " It was rendered twice: a correct render fails a case by chance about once in a "
                                 "thousand gradings at most, so a first failure is rendered again, and only the second "
                                 "render is judged." : "");
}

void grade_words_case(const grade_case_result *c, int part, const char *folder, char *out, size_t size)
{
    const grade_case *k = c->spec;
    const verdict *v = &c->v;
    if (k->hidden) {
        hidden_case_text(c, part, folder, out, size);
        return;
    }
    /* Rendered twice (grade_image.h): say so first; what follows judges the second render. */
    int len = 0;
    if (c->rendered_twice)
        len = snprintf(out, size, "Rendered twice: the first render (seed %llu) differed from the reference (p-value "
                       "%.3g). A correct render fails a case by chance about once in a thousand gradings at most, so "
                       "the case was rendered again at seed %llu. %s ", c->first_seed, public_figure(c->first_p, 0.0, 1.0), c->seed,
                       c->pass ? "That render is judged here, and the first failure was chance, not your code:"
                       : c->ran ? "That render differs too, so the difference is your code's, not chance:"
                                : "That render");
    if (len < 0 || (size_t)len >= size) return;
    out += len, size -= (size_t)len;
    if (!c->ran) {
        not_run_text(c, part, folder, out, size);
        return;
    }
    len = v->deterministic ? rounding_text(k, v, out, size)
                           : snprintf(out, size, "%s. p-value %.3g (the case fails below %.0e), relMSE %.3g, "
                                      "mean ratio red %.3g green %.3g blue %.3g.",
                                      v->pass ? "**matches the reference**" : "**differs from the reference**",
                                      public_figure(v->p_value, 0.0, 1.0), v->alpha, public_figure(v->rel_mse, 0.0, GRADE_REL_MSE_MAX),
                                      shown_ratio(v->ratio[0]), shown_ratio(v->ratio[1]), shown_ratio(v->ratio[2]));
    if (len >= 0 && (size_t)len < size) len += where_text(k, v, out + len, size - len);
    if (len >= 0 && (size_t)len < size) figures_text(c, out + len, size - len);
}


/* A failing public case's cause in one line (the report's words): why it did not run; where its
 * image differs (bad pixels, the whole image's brightness, the block), hint apart; or, for an image
 * that matches, the figure that failed (samples per pixel, noise, work). */
void grade_words_case_cause(const grade_case_result *c, int part, const char *folder, char *out, size_t size)
{
    char text[2048] = "";
    if (!c->ran) {
        char why[1024];
        grade_words_why(&c->why, part, folder, why, sizeof why);
        snprintf(text, sizeof text, "did not run: %s", why);
    }
    else if (!c->v.pass) {
        verdict v = c->v;
        v.hint[0] = '\0';  /* printed on a line of its own */
        where_text(c->spec, &v, text, sizeof text);
        if (!text[0]) snprintf(text, sizeof text, "the image differs from the reference (see the report)");
    }
    else {
        int len = snprintf(text, sizeof text, "the image matches the reference, but a figure of its render does not:");
        if (len >= 0 && (size_t)len < sizeof text) figures_text(c, text + len, sizeof text - (size_t)len);
    }
    snprintf(out, size, "%s", text + (text[0] == ' '));
}

/* ---- the unit tests -------------------------------------------------------------------------------- */

/* How many of the part's tasks lost their share. */
int grade_words_tasks_failed(const grade_part_result *p)
{
    int n = 0;
    for (int t = 0; p->spec && t < p->spec->num_tasks; t++) n += p->task_score[t] < p->spec->tasks[t].points;
    return n;
}

/* When several tasks failed: one bug can fail another task's tests, since a task's tests call the
 * part's functions of the tasks before it. Said with this part's own: the first failed task, and the
 * functions of the tasks before it that its tests may be failing through. */
void grade_words_cascade(const grade_part_result *p, char *text, size_t size)
{
    text[0] = '\0';
    if (grade_words_tasks_failed(p) <= 1) return;
    int first = 0;
    while (first < p->spec->num_tasks && p->task_score[first] >= p->spec->tasks[first].points) first++;
    int len = snprintf(text, size, "Several tasks failed, but one bug can fail the tests of another task as "
                       "well: a task's tests run the part's functions of the tasks before it too");
    for (int t = first + 1, named = 0; t < p->spec->num_tasks && len >= 0 && (size_t)len < size; t++)
        if (p->task_score[t] < p->spec->tasks[t].points && !named++)
            len += snprintf(text + len, size - len, " (task %s's tests run your %s, whose task %s failed too)",
                            p->spec->tasks[t].task, p->spec->tasks[first].functions, p->spec->tasks[first].task);
    if (len >= 0 && (size_t)len < size)
        snprintf(text + len, size - len, ": fix the first failure the suite names, task %s's, then run it again.",
                 p->spec->tasks[first].task);
}


bool grade_words_unit_zero(const grade_part_result *p, char *out, size_t size)
{
    out[0] = '\0';
    if (!p->build.built) grade_words_why(&p->build.why, p->part, p->folder, out, size);
    else if (!p->suite.judged) grade_words_why(&p->suite.why, p->part, p->folder, out, size);
    else return false;
    if (!out[0]) grade_msg(out, size, "the part's tests could not be run");
    return true;
}

/* A test's name as Markdown code: the course's names are C identifiers (grade_suite.c names any
 * other by kind), so backticks hold it whole. */
void grade_words_failures(const grade_part_result *p, char *out, size_t size)
{
    size_t len = 0;
    out[0] = '\0';
    for (int i = 0; i < p->suite.num_tests && len + 1 < size; i++) {
        const grade_test_fact *t = &p->suite.tests[i];
        if (t->passed) continue;
        char text[2 * GRADE_MESSAGE_MAX + 64], escaped[4 * GRADE_MESSAGE_MAX + 128];
        if (t->why.code != GRADE_WHY_NONE) grade_words_why(&t->why, p->part, p->folder, text, sizeof text);
        else grade_figure_text(t->message[0] ? t->message : "failed (the test printed no message)", text, sizeof text);
        grade_md_escape(text, strlen(text), escaped, sizeof escaped);
        int n = snprintf(out + len, size - len, "- `%s`: %s\n", t->name, escaped);
        if (n < 0 || (size_t)n >= size - len) break;  /* a line that does not fit is left out whole */
        len += (size_t)n;
    }
}

int grade_words_tasks(const grade_part_result *p, char *out, size_t size)
{
    int len = 0;
    out[0] = '\0';
    for (int t = 0; p->spec && t < p->spec->num_tasks && len >= 0 && (size_t)len < size; t++) {
        const grade_task *k = &p->spec->tasks[t];
        len += snprintf(out + len, size - len, "- task %s (%s): %g / %g points, %d of %d tests passed%s\n", k->task,
                        k->functions, p->task_score[t], k->points, p->task_passed[t], k->tests,
                        p->task_score[t] < k->points ? " (a task's share is earned when all its tests pass)" : "");
    }
    if (grade_words_tasks_failed(p) > 1 && len >= 0 && (size_t)len < size) {
        char cascade[1024];
        grade_words_cascade(p, cascade, sizeof cascade);
        len += snprintf(out + len, size - len, "\n%s\n", cascade);
    }
    return len;
}

/* ---- the pixels to trace --------------------------------------------------------------------------- */

void grade_words_trace(const grade_case_result *c, char *out, size_t size)
{
    const grade_case *k = c->spec;
    char flags[512] = "";
    for (int f = 0, len = 0; f < k->num_flags && len >= 0 && len < (int)sizeof flags; f++)
        len += snprintf(flags + len, sizeof flags - len, "%s ", k->flags[f]);
    int len = 0;
    out[0] = '\0';
    for (int j = 0; !k->hidden && j < c->num_trace && len >= 0 && (size_t)len < size; j++) {
        int x = grade_figure_pixel(c->trace[j].x, k->width), y = grade_figure_pixel(c->trace[j].y, k->height);
        len += snprintf(out + len, size - len, "pixel (%d, %d), luminance off by %.3g: bin/pathtracer %s-r %d %d -s %d "
                        "--seed %llu --trace-pixel %d %d %s\n", x, y,
                        public_figure(c->trace[j].diff, 0.0, GRADE_RATIO_MAX), flags, k->width, k->height, k->samples,
                        c->seed, x, y, k->scene);
    }
}
