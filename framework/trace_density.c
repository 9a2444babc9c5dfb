/* --trace-pixel's density checks: where a part samples (a BSDF at a path's vertex, the environment
 * map, the lens), the sampler's pdf against the distribution of its own samples, drawn there.
 *
 * Why: a sampler and its pdf can each look plausible, and every replay of the referee agree with
 * them, while the pdf is not the density of the directions drawn (a microfacet pdf without its
 * Jacobian, half the azimuths of h, a row search one off, a lens half its radius). Such an
 * estimator is consistent with itself and wrong. Measured: DENSITY_SAMPLES fresh samples of the
 * sampler at the vertex, each from a stream of its own (rng_for_sample), so nothing depends on the
 * order in which the part draws its numbers; the pdf integrated over fine cells of the sphere (or
 * the map's texels, or the lens's disc); cells gathered in order into DENSITY_BINS bins of equal
 * predicted probability, plus one bin for samples that give no usable direction; and Pearson's
 * chi-square test of the counts against the predictions at level TRACE_DENSITY_ALPHA (trace.h).
 * The cells are the bins' units, so a bin's prediction is exactly the sum of its cells': only the
 * integration's own error (below 0.5% where the check runs: DENSITY_SHARPEST) separates a correct
 * pdf from its prediction, against a statistical error of 12% a bin.
 *
 * The cost bounds how often: each check draws 4096 samples and evaluates the pdf some 40,000
 * times for a BSDF (4 ms), four times a texel for the map (30 ms for a 512 x 256 sky); a trace makes
 * at most TRACE_DENSITY_CHECKS of them: eight BSDF checks (two a material), the environment map's
 * once, the lens's once.
 * Test machinery: not part of any assignment. */
#include "trace_internal.h"
#include "envmap.h"
#include "stats.h"
#include "todo.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DENSITY_SAMPLES 4096
#define DENSITY_BINS 64            /* of about 64 samples each: the chi-square's approximation holds */
#define DENSITY_SEED 0x64656e7369747900ull  /* "density": the checks' streams, apart from the render's */
#define DENSITY_BSDF_CHECKS 8
#define DENSITY_PER_MATERIAL 2

/* Sample k of a check's own stream: one stream per (render seed, pixel, camera sample, vertex, kind
 * of check), so checks at other pixels and vertices draw other samples (a cosine lobe looks alike
 * at every vertex: the same samples would give the same statistic everywhere). */
static rng density_stream(const trace_log *t, int kind, int k)
{
    uint64_t pixel = (uint64_t)t->req.y * (uint64_t)t->ctx->width + (uint64_t)t->req.x;
    uint64_t where = ((uint64_t)t->sample << 16) | ((uint64_t)(t->path.bounce & 0xff) << 8) | (uint64_t)kind;
    return rng_for_sample(DENSITY_SEED ^ t->ctx->opts->seed, pixel * 0x9E3779B97F4A7C15ull ^ where, (uint64_t)k);
}

/* ---- cells and bins --------------------------------------------------------------------------- */

/* The predicted probability of each cell of a partition of the samples' space, the bin each cell
 * falls in, and the counts. */
typedef struct {
    int cells;
    double *mass;           /* the pdf integrated over each cell */
    int *bin_of;            /* the bin of each cell */
    double total;           /* the sum of mass: the pdf's integral over the usable directions */
    double observed[DENSITY_BINS + 1], expected[DENSITY_BINS + 1];  /* the last: no usable sample */
} density_grid;

static bool grid_alloc(density_grid *g, int cells)
{
    memset(g, 0, sizeof *g);
    g->cells = cells;
    g->mass = calloc((size_t)cells, sizeof *g->mass);
    g->bin_of = calloc((size_t)cells, sizeof *g->bin_of);
    return g->mass && g->bin_of;
}

static void grid_free(density_grid *g)
{
    free(g->mass);
    free(g->bin_of);
}

/* Gathers the cells, in their order, into DENSITY_BINS runs of about equal predicted probability,
 * and sets each bin's expected count out of DENSITY_SAMPLES (the last bin: what the pdf leaves to
 * unusable samples, 1 - total). A total a little above 1 (the integration's error) is scaled to 1. */
static void grid_bins(density_grid *g)
{
    double sum = 0.0, norm = g->total > 1.0 ? 1.0 / g->total : 1.0;
    for (int c = 0; c < g->cells; c++) {
        double mid = (sum + 0.5 * g->mass[c]) / (g->total > 0.0 ? g->total : 1.0);
        int b = (int)(mid * DENSITY_BINS);
        g->bin_of[c] = b < 0 ? 0 : b >= DENSITY_BINS ? DENSITY_BINS - 1 : b;
        g->expected[g->bin_of[c]] += g->mass[c] * norm * DENSITY_SAMPLES;
        sum += g->mass[c];
    }
    g->expected[DENSITY_BINS] = fmax(0.0, 1.0 - g->total) * DENSITY_SAMPLES;
}

/* A sample in cell c (c < 0: no usable sample). */
static void grid_count(density_grid *g, int c)
{
    g->observed[c < 0 ? DENSITY_BINS : g->bin_of[c]] += 1.0;
}

/* The test, its line, and a mark naming the bin most off when it fails. where(cell) says in words
 * where a bin lies (its first cell), for the mark. */
typedef void (*cell_words)(const void *user, int cell, char *out, size_t size);

static void grid_verdict(trace_log *t, density_grid *g, const char *sampler, const char *pdf, const char *rule,
                         cell_words where, const void *user)
{
    stats_result r = stats_chi2_test(g->observed, g->expected, DENSITY_BINS + 1, 5.0, TRACE_DENSITY_ALPHA);
    trace_emit(t, "density",
               json_pack("{s:s, s:i, s:o, s:o, s:o, s:o, s:o}", "sampler", sampler, "samples", DENSITY_SAMPLES, "total",
                         trace_jnum(g->total), "chi_square", trace_jnum(r.stat), "dof", trace_jnum(r.dof), "p",
                         trace_jnum(r.p), "alpha", trace_jnum(TRACE_DENSITY_ALPHA)),
               "density check: %d samples of %s drawn here against %s (total %.4g where usable), in %d bins of "
               "equal predicted probability: chi-square %.1f with %.0f degrees of freedom, p = %.2g (marked below %.0e)",
               DENSITY_SAMPLES, sampler, pdf, g->total, DENSITY_BINS, r.stat, r.dof, r.p, TRACE_DENSITY_ALPHA);
    if (g->total > 1.02) {
        trace_mark(t, "%s integrates to %.4g over what %s may return: a density integrates to 1 (%s)", pdf, g->total,
                   sampler, rule);
        return;
    }
    if (!r.reject) return;
    /* The bin furthest from its prediction, in standard errors, and where its first cell lies. */
    int worst = 0;
    double worst_z = -1.0;
    for (int b = 0; b <= DENSITY_BINS; b++) {
        double z = fabs(g->observed[b] - g->expected[b]) / sqrt(fmax(g->expected[b], 1.0));
        if (z > worst_z) worst_z = z, worst = b;
    }
    char place[160];
    snprintf(place, sizeof place, "of samples with no usable direction (pdf 0 or f black), %.3g of them by the pdf's total",
             fmax(0.0, 1.0 - g->total));
    for (int c = 0; c < g->cells && worst < DENSITY_BINS; c++)
        if (g->bin_of[c] == worst) {
            where(user, c, place, sizeof place);
            break;
        }
    trace_mark(t, "the samples of %s do not follow %s (chi-square %.1f, %.0f degrees of freedom, p = %.2g): the bin "
               "%s holds %.0f samples where it predicts %.1f (%s)", sampler, pdf, r.stat, r.dof, r.p, place,
               g->observed[worst], g->expected[worst], rule);
}

/* ---- a BSDF at a vertex ---------------------------------------------------------------------- */

/* The sphere of directions in the shading frame, in cells of equal angle: theta in BSDF_ROWS rows
 * (pi / 2 a row boundary: the horizon, where f may jump to 0), phi in BSDF_COLUMNS. A cell whose
 * one-point estimate, or a neighbour's, exceeds BSDF_HEAVY is integrated on BSDF_SPLIT x BSDF_SPLIT
 * points; a lobe so sharp that one of those holds DENSITY_SHARPEST of the whole is not checked:
 * the integration would be the error, not the sampler. */
#define BSDF_ROWS 128
#define BSDF_COLUMNS 256
#define BSDF_HEAVY 5e-4
#define BSDF_SPLIT 8
#define DENSITY_SHARPEST 5e-3

typedef struct {
    const material *m;
    vec3 wo;
} bsdf_at;

static vec3 direction_of(double theta, double phi)
{
    double s = sin(theta);
    return vec3_make((float)(s * cos(phi)), (float)(s * sin(phi)), (float)cos(theta));
}

/* The pdf where the direction is usable (the pdf positive and f not black), else 0, times the solid
 * angle of a cell of dtheta x dphi around it. */
static double usable_mass(const bsdf_at *at, double theta, double phi, double dtheta, double dphi)
{
    vec3 w = direction_of(theta, phi);
    double pdf = material_pdf(at->m, at->wo, w);
    if (!(pdf > 0.0) || !isfinite(pdf) || rgb_is_black(material_f(at->m, at->wo, w))) return 0.0;
    return pdf * sin(theta) * dtheta * dphi;
}

/* The cell's mass on BSDF_SPLIT^2 points; false when one point holds DENSITY_SHARPEST or more. */
static bool split_mass(const bsdf_at *at, int row, int col, double *mass)
{
    const double dt = PL_PI / BSDF_ROWS, dp = 2.0 * PL_PI / BSDF_COLUMNS;
    double sum = 0.0;
    for (int a = 0; a < BSDF_SPLIT; a++)
        for (int b = 0; b < BSDF_SPLIT; b++) {
            double m = usable_mass(at, (row + (a + 0.5) / BSDF_SPLIT) * dt, (col + (b + 0.5) / BSDF_SPLIT) * dp,
                                   dt / BSDF_SPLIT, dp / BSDF_SPLIT);
            if (m >= DENSITY_SHARPEST) return false;
            sum += m;
        }
    *mass = sum;
    return true;
}

/* Integrates the usable pdf over every cell; false when the lobe is too sharp to integrate here. */
static bool bsdf_integrate(const bsdf_at *at, density_grid *g)
{
    const double dt = PL_PI / BSDF_ROWS, dp = 2.0 * PL_PI / BSDF_COLUMNS;
    for (int row = 0; row < BSDF_ROWS; row++)
        for (int col = 0; col < BSDF_COLUMNS; col++)
            g->mass[row * BSDF_COLUMNS + col] = usable_mass(at, (row + 0.5) * dt, (col + 0.5) * dp, dt, dp);
    /* Heavy cells and their neighbours (phi wraps around), marked first, then split. */
    unsigned char *split = calloc(BSDF_ROWS * BSDF_COLUMNS, 1);
    if (!split) return false;
    for (int row = 0; row < BSDF_ROWS; row++)
        for (int col = 0; col < BSDF_COLUMNS; col++)
            if (g->mass[row * BSDF_COLUMNS + col] > BSDF_HEAVY)
                for (int i = row - 1; i <= row + 1; i++)
                    for (int j = col - 1; j <= col + 1; j++)
                        if (i >= 0 && i < BSDF_ROWS) split[i * BSDF_COLUMNS + (j + BSDF_COLUMNS) % BSDF_COLUMNS] = 1;
    bool ok = true;
    for (int c = 0; c < BSDF_ROWS * BSDF_COLUMNS && ok; c++)
        if (split[c]) ok = split_mass(at, c / BSDF_COLUMNS, c % BSDF_COLUMNS, &g->mass[c]);
    free(split);
    for (int c = 0; c < g->cells; c++) g->total += g->mass[c];
    return ok;
}

/* The cell of local direction w, or -1 for none. */
static int bsdf_cell(vec3 w)
{
    double len = vec3_length(w);
    if (!(len > 0.0) || !isfinite(len)) return -1;
    double theta = acos(fmin(1.0, fmax(-1.0, w.z / len))), phi = atan2(w.y, w.x);
    if (phi < 0.0) phi += 2.0 * PL_PI;
    int row = (int)(theta / PL_PI * BSDF_ROWS), col = (int)(phi / (2.0 * PL_PI) * BSDF_COLUMNS);
    row = row >= BSDF_ROWS ? BSDF_ROWS - 1 : row;
    col = col >= BSDF_COLUMNS ? BSDF_COLUMNS - 1 : col;
    return row * BSDF_COLUMNS + col;
}

static void bsdf_words(const void *user, int cell, char *out, size_t size)
{
    (void)user;
    double theta = (cell / BSDF_COLUMNS + 0.5) * 180.0 / BSDF_ROWS, phi = (cell % BSDF_COLUMNS + 0.5) * 360.0 / BSDF_COLUMNS;
    snprintf(out, size, "starting at theta = %.1f, phi = %.1f degrees (local, +z the normal)", theta, phi);
}

/* Which part writes the sampler of m, for the marks. */
static const char *bsdf_rule(const material *m)
{
    return m->kind == MATERIAL_MICROFACET ? "part 7, tasks 7.5 and 7.6: microfacet_pdf must be the density of "
                                            "microfacet_sample_f's directions, per unit solid angle of wi"
                                          : "part 3, task 3.2: bsdf_pdf must be the density of bsdf_sample_f's "
                                            "directions, per unit solid angle";
}

void density_check_bsdf(trace_log *t, const material *m, vec3 wo)
{
    int index = (int)(m - t->ctx->scene->materials) % 8;
    if (t->density.bsdf >= DENSITY_BSDF_CHECKS || t->density.bsdf_of[index] >= DENSITY_PER_MATERIAL) return;
    t->density.bsdf++, t->density.bsdf_of[index]++;
    bsdf_at at = {m, wo};
    density_grid g;
    int stubs = pl_todo_count();
    trace_replaying = true;
    bool allocated = grid_alloc(&g, BSDF_ROWS * BSDF_COLUMNS), ok = allocated && bsdf_integrate(&at, &g);
    if (allocated && !ok)
        trace_emit(t, "density", NULL, "density check of this vertex's sampler skipped: its lobe is too narrow for the "
                   "check's cells (one holds %.1g of it)", DENSITY_SHARPEST);
    if (ok) {
        grid_bins(&g);
        for (int k = 0; k < DENSITY_SAMPLES; k++) {
            rng r = density_stream(t, 0, k);
            vec3 wi = vec3_make(0.0f, 0.0f, 0.0f);
            float pdf = 0.0f;
            rgb f = material_sample_f(m, wo, rng_uniform2(&r), &wi, &pdf);
            grid_count(&g, pdf > 0.0f && isfinite(pdf) && !rgb_is_black(f) ? bsdf_cell(wi) : -1);
        }
    }
    trace_replaying = false;
    /* A stub answers with a placeholder: there is nothing to measure (its own mark says so). */
    bool micro = m->kind == MATERIAL_MICROFACET;
    if (ok && pl_todo_count() == stubs)
        grid_verdict(t, &g, micro ? "microfacet_sample_f" : "bsdf_sample_f", micro ? "microfacet_pdf" : "bsdf_pdf",
                     bsdf_rule(m), bsdf_words, NULL);
    grid_free(&g);
}

/* ---- the environment map -------------------------------------------------------------------- */

/* The cells are the map's texels split in ENV_SPLIT x ENV_SPLIT, row by row: a sampler that puts
 * every sample of a texel at one point of it (its corner) is told from one that spreads them. A
 * cell's mass is the pdf at its centre times its solid angle: exact, to rounding, for a density
 * that is constant over sin(theta) in a texel (task 8.3's), and for one constant per steradian. */
#define ENV_SPLIT 2

static void environment_integrate(const light *l, density_grid *g)
{
    const envmap *e = l->env;
    int w = ENV_SPLIT * e->width, h = ENV_SPLIT * e->height;
    double dphi = 2.0 * PL_PI / w;
    for (int y = 0; y < h; y++) {
        double t0 = y * PL_PI / h, t1 = (y + 1) * PL_PI / h, solid = dphi * (cos(t0) - cos(t1));
        for (int x = 0; x < w; x++) {
            vec3 dir = envmap_direction((float)(0.5 * (t0 + t1)), (float)((x + 0.5) * dphi));
            double pdf = light_environment_pdf(l, dir);
            g->mass[y * w + x] = pdf > 0.0 && isfinite(pdf) ? pdf * solid : 0.0;
            g->total += g->mass[y * w + x];
        }
    }
}

/* The cell a direction falls in, from its texel coordinates (envmap_texel_coords); -1 off the map. */
static int environment_cell(const envmap *e, vec3 d)
{
    vec2 c = envmap_texel_coords(e, d);
    int x = (int)floorf(ENV_SPLIT * c.x), y = (int)floorf(ENV_SPLIT * c.y);
    int w = ENV_SPLIT * e->width, h = ENV_SPLIT * e->height;
    return x >= 0 && x < w && y >= 0 && y < h ? y * w + x : -1;
}

static void texel_words(const void *user, int cell, char *out, size_t size)
{
    const envmap *e = user;
    int x = cell % (ENV_SPLIT * e->width), y = cell / (ENV_SPLIT * e->width);
    snprintf(out, size, "starting in texel (%d, %d) (its %s %s quarter)", x / ENV_SPLIT, y / ENV_SPLIT,
             y % ENV_SPLIT ? "lower" : "upper", x % ENV_SPLIT ? "right" : "left");
}

void density_check_environment(trace_log *t, const light *l)
{
    const envmap *e = l->env;
    t->density.environment = true;
    if (l->env_dist && !l->env_dist->valid) return;  /* the load warned: task 8.2's tables are not CDFs */
    density_grid g;
    int stubs = pl_todo_count();
    trace_replaying = true;
    bool ok = grid_alloc(&g, ENV_SPLIT * ENV_SPLIT * e->width * e->height);
    if (ok) {
        environment_integrate(l, &g);
        grid_bins(&g);
        for (int k = 0; k < DENSITY_SAMPLES; k++) {
            rng r = density_stream(t, 1, k);
            light_sample ls;
            memset(&ls, 0, sizeof ls);
            bool got = light_sample_environment(l, rng_uniform2(&r), &ls);
            grid_count(&g, got ? environment_cell(e, ls.wi) : -1);
        }
    }
    trace_replaying = false;
    if (ok && pl_todo_count() == stubs)
        grid_verdict(t, &g, l->env_dist ? "env_sample_importance" : "env_sample_uniform",
                     l->env_dist ? "env_pdf" : "the uniform density 1 / (4 pi)",
                     l->env_dist ? "part 8, tasks 8.3 and 8.4: env_pdf must be the density of env_sample_importance's "
                                   "directions, per unit solid angle"
                                 : "part 8, task 8.1: directions uniform over the sphere",
                     texel_words, e);
    grid_free(&g);
}

/* ---- the lens --------------------------------------------------------------------------------- */

/* The lens's disc in rings of equal area (r^2 / R^2 in steps of 1 / LENS_RINGS) and sectors of equal
 * angle in the camera's own X and Y: uniform points fall in each cell alike. */
#define LENS_RINGS 8
#define LENS_SECTORS 8

static void lens_words(const void *user, int cell, char *out, size_t size)
{
    (void)user;
    int ring = cell / LENS_SECTORS, sector = cell % LENS_SECTORS;
    snprintf(out, size, "in the ring from %.3g R to %.3g R, between %d and %d degrees", sqrt((double)ring / LENS_RINGS),
             sqrt((double)(ring + 1) / LENS_RINGS), 360 * sector / LENS_SECTORS, 360 * (sector + 1) / LENS_SECTORS);
}

/* The cell of lens point o, or -1 when it lies off the disc (or off its plane's rounding). */
static int lens_cell(const camera *c, vec3 o)
{
    vec3 right = vec3_normalize(mat4_dir(c->camera_to_world, vec3_make(1.0f, 0.0f, 0.0f)));
    vec3 up = vec3_normalize(mat4_dir(c->camera_to_world, vec3_make(0.0f, 1.0f, 0.0f)));
    vec3 offset = vec3_sub(o, c->position);
    double x = vec3_dot(offset, right) / c->lens_radius, y = vec3_dot(offset, up) / c->lens_radius;
    double r2 = x * x + y * y, phi = atan2(y, x);
    if (!(r2 <= 1.0 + 4e-4)) return -1;
    if (phi < 0.0) phi += 2.0 * PL_PI;
    int ring = (int)(r2 * LENS_RINGS), sector = (int)(phi / (2.0 * PL_PI) * LENS_SECTORS);
    ring = ring >= LENS_RINGS ? LENS_RINGS - 1 : ring;
    sector = sector >= LENS_SECTORS ? LENS_SECTORS - 1 : sector;
    return ring * LENS_SECTORS + sector;
}

void density_check_lens(trace_log *t, const camera *c, ray pinhole)
{
    t->density.lens = true;
    density_grid g;
    if (!grid_alloc(&g, LENS_RINGS * LENS_SECTORS)) {
        grid_free(&g);
        return;
    }
    for (int cell = 0; cell < g.cells; cell++) g.mass[cell] = 1.0 / g.cells;
    g.total = 1.0;
    grid_bins(&g);
    int stubs = pl_todo_count();
    trace_replaying = true;
    for (int k = 0; k < DENSITY_SAMPLES; k++) {
        rng r = density_stream(t, 2, k);
        ray lens = render_lens_ray(c, pinhole, rng_uniform2(&r));
        grid_count(&g, lens.max_t > lens.min_t ? lens_cell(c, lens.o) : -1);
    }
    trace_replaying = false;
    if (pl_todo_count() == stubs)
        grid_verdict(t, &g, "thin_lens_ray's lens points", "the uniform density over the lens",
                     "part 9, tasks 9.1 and 9.2: lens points uniform in area over the disc of radius -b, in the "
                     "camera's own X and Y", lens_words, NULL);
    grid_free(&g);
}
