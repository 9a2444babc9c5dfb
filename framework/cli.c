/* The command line: CS184's short flags (some take two values) and pathlab's long options.
 * Parsed by hand because getopt cannot take the two-value flags -r W H and -a B T.
 *
 * The order of work: defaults (CS184's, so a CS184 command line means what it meant there),
 * then one pass over argv in which every flag's value is checked as it is read (type, range, and
 * a message naming the flag), then the checks that need several flags at once (check_options).
 * Nothing is loaded or opened here: file names are only remembered, and output.c checks them. */
#include "cli.h"
#include "dae.h"
#include "camera.h"
#include "envmap.h"
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

/* ---- defaults and the help text ----------------------------------------------------------- */

/* CS184's defaults, then pathlab's (the seed 0, leaf size 4, the loader's guards). */
options options_default(void)
{
    options o;
    memset(&o, 0, sizeof o);
    o.spp = 1;
    o.light_samples = 1;
    o.threads = 1;
    o.max_depth = 1;
    o.accumulate = true;
    o.lens_radius = CAMERA_DEFAULT_LENS_RADIUS;
    o.focal_distance = CAMERA_DEFAULT_FOCAL_DISTANCE;
    o.film_fd = -1;             /* no grader pipe */
    o.width = 800;
    o.height = 600;
    o.adaptive_batch = 32;
    o.adaptive_tol = 0.05f;
    o.max_leaf_size = 4;
    o.trace_last = -1;          /* --trace-sample not given: every sample of the pixel */
    o.max_primitives = DAE_DEFAULT_MAX_PRIMITIVES;  /* the constants, not dae_limits_default(): the grader */
    o.max_instances = DAE_DEFAULT_MAX_INSTANCES;    /* links this file without the scene loader */
    return o;
}

void cli_print_usage(FILE *f, const char *prog)
{
    fprintf(f,
            "usage: %s [options] scene.dae\n"
            "  -s N        camera rays per pixel (1)\n"
            "  -l N        samples per area light (1)\n"
            "  -t N        render threads (1); also --threads N\n"
            "  -m N        max ray depth: 0 emission only, 1 direct light, ... (1)\n"
            "  -o 0|1      1: add up all bounces; 0: only the bounce at depth -m (1)\n"
#ifdef PL_HAS_PART8
            "  -e FILE     environment map: a latitude-longitude OpenEXR image lighting the scene from afar (part 8)\n"
#else
            "  -e FILE     environment map: a latitude-longitude OpenEXR image, seen where rays leave the scene\n"
#endif
#ifdef PL_HAS_PART9
            "  -b R        lens radius (0: a pinhole, or the -c file's): the thin lens of part 9\n"
            "  -d D        focal distance: the plane of focus lies D in front of the camera (4.7, or the -c file's)\n"
#else
            "  -b R        lens radius (0, or the -c file's; accepted, not used: this course has no thin lens part)\n"
            "  -d D        focal distance (4.7, or the -c file's; likewise not used)\n"
#endif
            "  -f FILE     write the render: .png (tone-mapped), .hdr or .exr (linear), plus FILE.json\n"
            "  -r W H      image size in pixels (800 600)\n"
            "  -c FILE     CS184 camera settings file\n"
            "  -a B T      adaptive sampling: check every B samples, tolerance T (32 0.05)\n"
            "  -H          direct light by uniform hemisphere sampling instead of light sampling\n"
            "  -v          print BVH and traversal statistics\n"
            "  -q          no progress bar or summary\n"
            "  -h, --help  this text\n"
            "  --seed N          seed of every random stream (0)\n"
            "  --normals         shade by surface normal (parts 1 and 2)\n"
            "  --camera literal|cs184  the file's camera as written, or CS184's framing (an orbit on the\n"
            "                    scene's bounds, from the side where the last camera's matrix puts the point\n"
            "                    (0,0,-1)). Default: cs184 for a file in the course's profile (CGL extensions,\n"
            "                    not pathlab's own), else literal\n"
            "  --cs184-camera    the same as --camera cs184\n"
            "  --no-bvh          intersect by linear scan even when part 2 is implemented\n"
            "  --no-rr           no Russian roulette: every path runs to -m bounces (part 4)\n"
#ifdef PL_HAS_PART8
            "  --env-uniform     sample -e's map uniformly over the sphere (task 8.1), not by importance\n"
#endif
            "  --leaf-size N     BVH max primitives per leaf (4)\n"
            "  --max-primitives N  refuse scenes with more triangles + spheres (2000000; guards memory)\n"
            "  --max-instances N   refuse scenes whose nodes expand to more instances (1000000; guards time)\n"
            "  --heatmap FILE    write a PNG of BVH nodes visited per pixel\n"
            "  --film-fd N       send the film to descriptor N (the grader's pipe) and write no file\n"
            "  --samples A:B     render only samples A..B-1 of -s N (fixed rate; -f x.exr keeps what --merge needs)\n"
            "  --trace-pixel X Y   print every path of pixel (X, Y) (0 0 = bottom-left), as the render computes it\n"
            "  --trace-sample K    with --trace-pixel: print only sample K (or samples A:B, B excluded)\n"
            "  --trace-format F    text (default) or json (schema: framework/trace.schema.json)\n"
            "  --crop X0 Y0 X1 Y1  render only pixels X0 <= x < X1, Y0 <= y < Y1 (0 0 = bottom-left)\n"
            "  --merge -f OUT.(exr|png|hdr) IN.exr...  merge --samples ranges that tile 0..N into OUT\n"
            "                    (its options in any order: --merge IN.exr... -f OUT also works)\n",
            prog);
}

/* ---- values ---------------------------------------------------------------------------------- */

/* Value parsers: each checks the whole string and the range, and names the flag when it fails.
 * strtol alone would take "12abc" as 12 and "" as 0: a typo would render something else silently. */
static pl_status parse_int(const char *flag, const char *text, int lo, int hi, int *out, pl_diag *d)
{
    char *end;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || *text == '\0' || *end != '\0' || errno || v < lo || v > hi)
        return pl_fail(d, PL_ERR_INVALID, "%s: expected an integer from %d to %d, got '%s'", flag, lo, hi,
                       text ? text : "nothing");
    *out = (int)v;
    return PL_OK;
}

/* A float >= lo; NaN and infinity are refused (a NaN passes every comparison test written as
 * "v < lo", hence the !(v >= lo) form). */
static pl_status parse_float(const char *flag, const char *text, float lo, float *out, pl_diag *d)
{
    char *end;
    errno = 0;
    float v = text ? strtof(text, &end) : 0.0f;
    if (!text || *text == '\0' || *end != '\0' || errno || !(v >= lo) || !isfinite(v))
        return pl_fail(d, PL_ERR_INVALID, "%s: expected a number >= %g, got '%s'", flag, lo, text ? text : "nothing");
    *out = v;
    return PL_OK;
}

/* --seed: strtoull would take "-1" as 2^64 - 1, so a sign is refused before it parses. */
static pl_status parse_u64(const char *flag, const char *text, uint64_t *out, pl_diag *d)
{
    char *end;
    errno = 0;
    unsigned long long v = text ? strtoull(text, &end, 10) : 0;
    if (!text || *text == '\0' || *text == '-' || *end != '\0' || errno)
        return pl_fail(d, PL_ERR_INVALID, "%s: expected a non-negative integer, got '%s'", flag, text ? text : "nothing");
    *out = (uint64_t)v;
    return PL_OK;
}

/* The command line as one string, for the sidecar (sidecar.c) and the trace's header: a render can
 * then be made again from its own output. */
static char *join_args(int argc, char **argv)
{
    size_t n = 1;
    for (int i = 0; i < argc; i++) n += strlen(argv[i]) + 1;
    char *s = malloc(n);
    if (!s) return NULL;
    s[0] = '\0';
    for (int i = 0; i < argc; i++) {
        if (i) strcat(s, " ");
        strcat(s, argv[i]);
    }
    return s;
}

/* ---- flags: each parser takes the flag at argv[i] and the values after it ---------------------- */

/* VALUE(k): the k-th value after the flag at argv[i], or NULL when the command line ends first (the
 * parsers then say "expected ..." instead of reading past argv). */
#define VALUE(k) (i + (k) < argc ? argv[i + (k)] : NULL)

/* CS184's flags (-s, -l, -t, -m, -o, -e, -b, -d, -f, -c, -r, -a, -H, -v, -q): the number of values
 * the flag argv[i] takes, or -1 when it is none of them; *s says whether they parsed. */
static int parse_cs184_flag(int argc, char **argv, int i, options *o, pl_status *s, pl_diag *d)
{
    const char *a = argv[i];
    int taken = 0;
    if (!strcmp(a, "-s")) *s = parse_int(a, VALUE(1), 1, 1 << 24, &o->spp, d), taken = 1;
    else if (!strcmp(a, "-l")) *s = parse_int(a, VALUE(1), 1, 1 << 20, &o->light_samples, d), taken = 1;
    else if (!strcmp(a, "-t") || !strcmp(a, "--threads")) *s = parse_int(a, VALUE(1), 1, 1024, &o->threads, d), taken = 1;
    else if (!strcmp(a, "-m")) *s = parse_int(a, VALUE(1), 0, 100000, &o->max_depth, d), taken = 1;
    else if (!strcmp(a, "-o")) {
        int v = 0;
        *s = parse_int(a, VALUE(1), 0, 1, &v, d), taken = 1;
        o->accumulate = v == 1;
    }
    else if (!strcmp(a, "-e")) { if (!VALUE(1)) *s = pl_fail(d, PL_ERR_INVALID, "-e: expected a file name"); o->envmap = VALUE(1); taken = 1; }
    else if (!strcmp(a, "-b")) {  /* only a given lens replaces the camera's (camera.h) */
        *s = parse_float(a, VALUE(1), 0.0f, &o->lens_radius, d), taken = 1;
        o->lens_radius_given = true;
    }
    else if (!strcmp(a, "-d")) {
        *s = parse_float(a, VALUE(1), 0.0f, &o->focal_distance, d), taken = 1;
        o->focal_distance_given = true;
    }
    else if (!strcmp(a, "-f")) { if (!VALUE(1)) *s = pl_fail(d, PL_ERR_INVALID, "-f: expected an output file name"); o->output = VALUE(1); taken = 1; }
    else if (!strcmp(a, "-c")) { if (!VALUE(1)) *s = pl_fail(d, PL_ERR_INVALID, "-c: expected a camera settings file"); o->camera_file = VALUE(1); taken = 1; }
    else if (!strcmp(a, "-r")) {
        *s = parse_int("-r W", VALUE(1), 1, 1 << 15, &o->width, d);
        if (*s == PL_OK) *s = parse_int("-r H", VALUE(2), 1, 1 << 15, &o->height, d);
        taken = 2;
    }
    else if (!strcmp(a, "-a")) {
        *s = parse_int("-a B", VALUE(1), 2, 1 << 24, &o->adaptive_batch, d);
        if (*s == PL_OK) *s = parse_float("-a T", VALUE(2), 0.0f, &o->adaptive_tol, d);
        o->adaptive = true;
        taken = 2;
    }
    else if (!strcmp(a, "-H")) o->hemisphere = true;
    else if (!strcmp(a, "-v")) o->verbose = true;
    else if (!strcmp(a, "-q")) o->quiet = true;
    else taken = -1;
    return taken;
}

/* pathlab's long options (all but --threads, --trace-* and --crop): the number of values the flag
 * argv[i] takes, or -1 when it is none of them; *s says whether they parsed. */
static int parse_long_flag(int argc, char **argv, int i, options *o, pl_status *s, pl_diag *d)
{
    const char *a = argv[i];
    int taken = 0;
    if (!strcmp(a, "--seed")) *s = parse_u64(a, VALUE(1), &o->seed, d), taken = 1;
    else if (!strcmp(a, "--normals")) o->normals = true;
    else if (!strcmp(a, "--cs184-camera")) o->framing = FRAMING_CS184;  /* the older spelling, kept */
    else if (!strcmp(a, "--camera")) {
        const char *v = VALUE(1);
        if (v && !strcmp(v, "literal")) o->framing = FRAMING_LITERAL;
        else if (v && !strcmp(v, "cs184")) o->framing = FRAMING_CS184;
        else *s = pl_fail(d, PL_ERR_INVALID, "--camera: expected literal or cs184, got '%s'", v ? v : "nothing");
        taken = 1;
    }
    else if (!strcmp(a, "--no-bvh")) o->linear_scan = true;
    else if (!strcmp(a, "--no-rr")) o->no_roulette = true;
    else if (!strcmp(a, "--env-uniform")) o->env_uniform = true;
    else if (!strcmp(a, "--leaf-size")) *s = parse_int(a, VALUE(1), 1, 255, &o->max_leaf_size, d), taken = 1;
    else if (!strcmp(a, "--max-primitives")) {
        int v = 0;
        *s = parse_int(a, VALUE(1), 1, 1 << 30, &v, d), taken = 1;
        o->max_primitives = v;
    }
    else if (!strcmp(a, "--max-instances")) {
        int v = 0;
        *s = parse_int(a, VALUE(1), 1, 1 << 30, &v, d), taken = 1;
        o->max_instances = v;
    }
    else if (!strcmp(a, "--samples")) {
        char extra;
        if (!VALUE(1) || sscanf(VALUE(1), "%d:%d%c", &o->sample_begin, &o->sample_end, &extra) != 2 ||
            o->sample_begin < 0 || o->sample_begin >= o->sample_end)
            *s = pl_fail(d, PL_ERR_INVALID, "--samples: expected A:B with 0 <= A < B, got '%s'", VALUE(1) ? VALUE(1) : "nothing");
        taken = 1;
    }
    else if (!strcmp(a, "--heatmap")) { if (!VALUE(1)) *s = pl_fail(d, PL_ERR_INVALID, "--heatmap: expected a .png file name"); o->heatmap = VALUE(1); taken = 1; }
    else if (!strcmp(a, "--film-fd")) *s = parse_int(a, VALUE(1), 3, 1023, &o->film_fd, d), taken = 1;
    else taken = -1;
    return taken;
}

/* --trace-pixel, --trace-sample, --trace-format and --crop (framework/trace.h): the number of
 * values the flag argv[i] takes, or -1 when it is none of them; *s says whether they parsed. */
static int parse_trace_flag(int argc, char **argv, int i, options *o, pl_status *s, pl_diag *d)
{
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--trace-pixel")) {
        *s = parse_int("--trace-pixel X", v, 0, 1 << 15, &o->trace_x, d);
        if (*s == PL_OK) *s = parse_int("--trace-pixel Y", i + 2 < argc ? argv[i + 2] : NULL, 0, 1 << 15, &o->trace_y, d);
        o->trace = true;
        return 2;
    }
    if (!strcmp(a, "--trace-sample")) {
        char extra;
        int n = v ? sscanf(v, "%d:%d%c", &o->trace_first, &o->trace_last, &extra) : 0;
        if (n == 1) o->trace_last = o->trace_first;
        else if (n == 2) o->trace_last--;  /* A:B excludes B, like --samples */
        if ((n != 1 && n != 2) || o->trace_first < 0 || o->trace_last < o->trace_first)
            *s = pl_fail(d, PL_ERR_INVALID, "--trace-sample: expected K or A:B with 0 <= A < B, got '%s'", v ? v : "nothing");
        return 1;
    }
    if (!strcmp(a, "--trace-format")) {
        if (!v || (strcmp(v, "text") && strcmp(v, "json")))
            *s = pl_fail(d, PL_ERR_INVALID, "--trace-format: expected text or json, got '%s'", v ? v : "nothing");
        o->trace_json = v && !strcmp(v, "json");
        return 1;
    }
    if (strcmp(a, "--crop")) return -1;
    int *box[4] = {&o->crop_x0, &o->crop_y0, &o->crop_x1, &o->crop_y1};
    const char *names[4] = {"--crop X0", "--crop Y0", "--crop X1", "--crop Y1"};
    for (int k = 0; k < 4 && *s == PL_OK; k++)
        *s = parse_int(names[k], i + 1 + k < argc ? argv[i + 1 + k] : NULL, 0, 1 << 15, box[k], d);
    o->crop = true;
    return 4;
}

/* The trace and crop options against the rest: each one a located refusal. */
static pl_status check_trace_flags(const options *o, pl_diag *d)
{
    if (o->trace && (o->trace_x >= o->width || o->trace_y >= o->height))
        return pl_fail(d, PL_ERR_INVALID, "--trace-pixel %d %d: outside the %dx%d image (x 0..%d, y 0..%d from the bottom-left)",
                       o->trace_x, o->trace_y, o->width, o->height, o->width - 1, o->height - 1);
    if (!o->trace && (o->trace_first || o->trace_last >= 0 || o->trace_json))
        return pl_fail(d, PL_ERR_INVALID, "--trace-sample and --trace-format need --trace-pixel X Y");
    if (o->crop && (o->crop_x0 >= o->crop_x1 || o->crop_y0 >= o->crop_y1 || o->crop_x1 > o->width || o->crop_y1 > o->height))
        return pl_fail(d, PL_ERR_INVALID, "--crop %d %d %d %d: expected X0 < X1 <= %d and Y0 < Y1 <= %d (-r %d %d)", o->crop_x0,
                       o->crop_y0, o->crop_x1, o->crop_y1, o->width, o->height, o->width, o->height);
    if (o->crop && o->heatmap) return pl_fail(d, PL_ERR_INVALID, "--crop: --heatmap draws the whole image; use one or the other");
    return PL_OK;
}

/* The options against each other, once all are read. */
/* ---- checks across flags ------------------------------------------------------------------- */

/* What no single flag can check: combinations that would render something other than asked. */
static pl_status check_options(const options *o, pl_diag *d)
{
    if (o->sample_end && o->adaptive)
        return pl_fail(d, PL_ERR_INVALID, "--samples %d:%d: sample ranges are for fixed-rate renders; -a decides per pixel "
                       "how many samples to take, so its renders cannot be split", o->sample_begin, o->sample_end);
    if (o->sample_end > o->spp)
        return pl_fail(d, PL_ERR_INVALID, "--samples %d:%d: B must be at most -s %d", o->sample_begin, o->sample_end, o->spp);
    if (check_trace_flags(o, d) != PL_OK) return PL_ERR_INVALID;
    if (o->film_fd >= 0 && (o->output || o->heatmap))
        return pl_fail(d, PL_ERR_INVALID, "--film-fd %d: the film goes to the descriptor; no -f or --heatmap with it", o->film_fd);
    return PL_OK;
}

/* The one allocation parsing makes: the joined command line. */
void cli_free(options *o)
{
    if (!o) return;
    free((char *)o->command_line);
    o->command_line = NULL;
}

/* ---- the pass over argv ---------------------------------------------------------------------- */

/* Non-flag arguments are the scene (exactly one); "-" alone counts as a name, not a flag. The
 * first value that does not parse stops the pass with its message. */
pl_status cli_parse(int argc, char **argv, options *out, cli_action *action, pl_diag *d)
{
    options o = options_default();
    *action = CLI_RUN;
    pl_status s = PL_OK;
    int i, taken;
    for (i = 1; i < argc && s == PL_OK; i++) {
        const char *a = argv[i];
        if (a[0] != '-' || a[1] == '\0') {
            if (o.scene_path) return pl_fail(d, PL_ERR_INVALID, "expected one scene file, got '%s' and '%s'", o.scene_path, a);
            o.scene_path = a;
            continue;
        }
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) { *action = CLI_HELP; *out = o; return PL_OK; }
        else if ((taken = parse_cs184_flag(argc, argv, i, &o, &s, d)) >= 0) i += taken;
        else if ((taken = parse_long_flag(argc, argv, i, &o, &s, d)) >= 0) i += taken;
        else if ((taken = parse_trace_flag(argc, argv, i, &o, &s, d)) >= 0) i += taken;
        else return pl_fail(d, PL_ERR_INVALID, "unknown option '%s'", a);
    }
    if (s != PL_OK) return s;
    if (!o.scene_path) return pl_fail(d, PL_ERR_INVALID, "expected a scene file (.dae)");
    if (check_options(&o, d) != PL_OK) return PL_ERR_INVALID;
    o.command_line = join_args(argc, argv);
    if (!o.command_line) return pl_fail(d, PL_ERR_NOMEM, "out of memory");
    *out = o;
    return PL_OK;
}

/* ---- what the run says about the scene --------------------------------------------------------- */

/* Whether any primitive of s has an emissive material (something a camera or bounce ray can see). */
static bool has_emitters(const scene *s)
{
    for (int i = 0; i < scene_prim_count(s); i++) {
        int m = i < s->num_triangles ? s->triangles[i].material : s->spheres[i - s->num_triangles].material;
        if (m >= 0 && m < s->num_materials && rgb_max(s->materials[m].Le) > 0.0f) return true;
    }
    return false;
}

int cli_warn_noops(const options *o, const scene *s, pl_diag *d)
{
    int said = 0;
    /* No lights: light sampling has nothing to sample. Shading by normals needs none, and a map (-e)
     * is seen where rays leave the scene: the warning below says what it lights. */
    if (s->num_lights == 0 && !o->normals && !s->env) {
        const char *name = s->path[0] ? s->path : "the scene";
        if (!has_emitters(s))
            pl_warn(d, "%s has no lights: the image will be black (it has no <light> and nothing emissive)", name);
        else
            pl_warn(d, "%s has no lights: the image will be black but for its emitters seen directly, and what "
                       "-H or bounces (-m 2 and more) gather from them; light sampling has nothing to sample", name);
        said++;
    }
#ifndef PL_HAS_PART8
    /* -e: the framework shows the map where rays leave the scene; lighting by it is part 8's. */
    if (s->env && !o->normals) {
        pl_warn(d, "-e %s: this course has no environment light part, so the map is seen where rays leave the scene "
                   "but lights nothing", s->env->path);
        said++;
    }
#else
    /* -H finds light only by hitting emitters; a map is reached by light sampling alone. */
    if (s->env && o->hemisphere && !o->normals && o->max_depth >= 1) {
        pl_warn(d, "-H with -e %s: hemisphere sampling finds light only where its rays hit an emitter, so the map lights "
                   "nothing (without -H it lights through light sampling)", s->env->path);
        said++;
    }
#endif
    if (o->env_uniform && !s->env) {
        pl_warn(d, "--env-uniform has no effect: there is no environment map (-e map.exr)");
        said++;
    }
#ifdef PL_HAS_PART9
    /* -d focuses a lens; with no lens (radius 0: no -b, and none from a -c file) the camera is a
     * pinhole, sharp at every distance, and the focal distance changes nothing. */
    camera lens = s->has_camera ? s->camera : (camera){.lens_radius = CAMERA_DEFAULT_LENS_RADIUS};
    camera_apply_lens_flags(&lens, o);
    if (o->focal_distance_given && !(lens.lens_radius > 0.0f)) {
        pl_warn(d, "-d %g has no effect: the lens radius is 0, a pinhole camera, sharp at every distance (-b R gives it a "
                   "lens)", (double)o->focal_distance);
        said++;
    }
#else
    /* -b / -d: CS184's flags, parsed and checked, but this course has no thin lens part. */
    if (o->lens_radius_given || o->focal_distance_given) {
        char given[96] = "";
        if (o->lens_radius_given) snprintf(given, sizeof given, "-b %g", (double)o->lens_radius);
        if (o->focal_distance_given)
            snprintf(given + strlen(given), sizeof given - strlen(given), "%s-d %g", o->lens_radius_given ? " and " : "",
                     (double)o->focal_distance);
        pl_warn(d, "%s accepted but not used: this course has no thin lens part, so this render is a pinhole camera's", given);
        said++;
    }
#endif
    return said;
}
