/* The trace's modules and what they share (framework/trace.h says what the trace is).
 *
 *   trace.c           the driver: one pixel through render_pixel_traced, the summary, the result
 *   trace_events.c    the hooks trace_hook.h declares: each report of the seam becomes events and checks
 *   trace_print.c     the printer: one line of the tree as text, or one event of the JSON document
 *   trace_referee.c   the per-part rules: what a correct part returns from the numbers the hooks saw
 *   trace_density.c   the samplers' densities against their own samples, drawn at the vertex
 *
 * The referee and the density checks judge the parts by the parts' own functions, reached through
 * the framework (material.h, light.h, the seam), never by a copy of a part's formula: a copy would
 * be a second solution to keep equal to the first, and would mark an alternative a handout allows.
 * Test machinery: not part of any assignment.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_TRACE_INTERNAL_H
#define PL_TRACE_INTERNAL_H

#include <jansson.h>
#include <stdbool.h>
#include "trace.h"
#include "trace_hook.h"
#include "light.h"
#include "material.h"

#define MAX_NEST 16  /* part calls nested at once (a recursive part 4 nests one per bounce); deeper ones go unframed */

/* Set while the trace itself calls a part or seam function: its draws and light samples are no
 * part of the render's, and its hooks stay quiet. */
extern _Thread_local bool trace_replaying;

/* A part function the framework called and that has not returned yet. */
typedef struct {
    pl_seam_id fn;
    const render_ctx *ctx;  /* as passed (part 4 may pass its own copy of the context) */
    ray r;
    hit h;
    int todo_before;        /* pl_todo_count() at the call: a stub shows as a rise */
} trace_frame;

/* The replay of one at_least_one_bounce_radiance call: the path as f cos / pdf and the roulette
 * say it should go, compared with what the part returns. */
typedef struct {
    bool active;
    int bounce;             /* the vertex the path is at: 1 at h, one more for each bounce ray (a part
                               may skip a vertex's direct light, -o 0: the count is the rays') */
    rgb beta;               /* throughput of the vertex being lit */
    rgb expected;           /* the sum of what each bounce added */
    ray cur;                /* the ray that reached the vertex, and its hit */
    hit at;
    int draws;              /* random numbers drawn at this vertex since it was reached or its direct
                               light returned: the BSDF sample's two, then the roulette's */
    float value[4];         /* their values (the BSDF sample's replay reads the first two) */
    bool gambled;           /* roulette could have ended the path somewhere: the sum is not checked */
} trace_path;

/* The replay of one direct_importance or direct_hemisphere call: its samples' contributions. */
typedef struct {
    rgb visible;            /* sum of contributions the framework finds unoccluded */
    rgb hidden;             /* sum of those that hit something nearer than the light */
} trace_direct;

/* The density checks run so far (trace_density.c): a few per trace, so a trace's chance of a
 * false mark stays bounded whatever its length. */
typedef struct {
    int bsdf;               /* BSDF samplers checked */
    int bsdf_of[8];         /* ... of which at each of the first 8 materials (by index) */
    bool environment;       /* the environment map's sampler checked (once: it is the same everywhere) */
    bool lens;              /* the lens's points checked (once: the same for every pixel) */
} trace_density_done;

/* Everything one trace keeps: the request, the output (text, or the JSON document being built), the
 * stack of part calls under way, and the replays of the path and the direct light in progress. */
typedef struct trace_log {
    const render_ctx *ctx;
    trace_request req;
    FILE *out;
    bool recording;         /* the current sample is one to print */
    int sample;
    json_t *doc, *samples, *events, *checks;  /* JSON mode only */
    trace_frame stack[MAX_NEST];
    int depth;
    trace_path path;
    trace_direct direct;
    trace_density_done density;
    int marks;
    int stubs_marked;       /* pl_todo_count() when the last stub was marked */
    const char *camera_ray_by;  /* who made the sample's camera ray, for its mark: part 1, or part 9's lens */
} trace_log;

/* ---- the printer (trace_print.c) -------------------------------------------------------------- */

/* JSON values: a number (NaN and infinities as the strings "nan", "inf", "-inf"), a vector or a
 * colour as three numbers, a point in the file's coordinates (scene.h: the scene is centred). */
json_t *trace_jnum(double v);
json_t *trace_jvec(vec3 v);
json_t *trace_jrgb(rgb c);
json_t *trace_jpoint(const trace_log *t, vec3 v);

/* Prints one line at the current nesting; fields (owned, may be NULL) go into its JSON event. */
void trace_emit(trace_log *t, const char *kind, json_t *fields, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* An invariant broken or a replay that disagrees: one "!!" line saying what is wrong, counted. */
void trace_mark(trace_log *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Marks radiance that is NaN, infinite or negative, naming `what`. */
void trace_check_radiance(trace_log *t, const char *what, rgb c);
/* A ray's hit or miss, in words (primitive, material, distance, point, normal), with its marks. */
void trace_describe_hit(trace_log *t, const char *role, const ray *r, bool found, const hit *h);
/* The pixel's value as the image holds it, and the count of marks. */
void trace_summary(trace_log *t, const film_pixel *px);

/* Text forms: a vector or colour to five significant digits, a point in the file's coordinates. */
#define V3 "(%.5g, %.5g, %.5g)"
#define XYZ(v) (double)(v).x, (double)(v).y, (double)(v).z
#define RGB(c) (double)(c).r, (double)(c).g, (double)(c).b
#define FILE_AT(t, coord, axis) ((double)(coord) + (t)->ctx->scene->origin[axis])
#define PXYZ(v) FILE_AT(t, (v).x, 0), FILE_AT(t, (v).y, 1), FILE_AT(t, (v).z, 2)

/* ---- shared helpers (trace_print.c) ----------------------------------------------------------- */

/* The innermost part call under way, and whether it is fn. */
trace_frame *trace_top(trace_log *t);
bool trace_in(trace_log *t, pl_seam_id fn);
/* Within float rounding of each other (sums in another order differ in the last bits). */
bool trace_rgb_close(rgb a, rgb b);
/* The material a hit names, or NULL when it names none of the scene's. */
const material *trace_material_at(const trace_log *t, const hit *h);
/* Whether m shades as part 3's diffuse BSDF (diffuse, or a kind the course has no part for). */
bool trace_shades_diffuse(const material *m);

/* ---- the referee (trace_referee.c): what a correct part returns, from what the hooks saw ------ */

/* Task 3.5: a light sample's contribution by the framework's own visibility test, added to the
 * running sum; returns it, its cosine, whether it is visible, and a diffuse f above 1/pi (else black). */
rgb referee_light_sample(trace_log *t, const light *l, const light_sample *ls, float *cosine, bool *visible, rgb *bright);
/* Task 3.1: marks a diffuse f above 1/pi (bright; black: nothing to mark). */
void referee_diffuse_bound(trace_log *t, rgb bright);
/* Tasks 3.4 and 3.5: what the part returned against the sum of its samples. */
void referee_direct(trace_log *t, pl_seam_id fn, rgb L);
/* Task 3.4: what one hemisphere ray that hit something adds (Le f cos / pdf / N). */
void referee_hemisphere_hit(trace_log *t, const ray *r, const hit *h);
/* Task 4.1: what one bounce adds to the path's sum, after its direct light returned L. */
void referee_bounce_added(trace_log *t, rgb L);
/* Tasks 4.1, 4.2 (and 6, 7 through material.h): a bounce ray left the vertex. */
void referee_bounce_ray(trace_log *t, const ray *r);
/* Task 4.1: the path ended with the part's answer L. */
void referee_path_end(trace_log *t, rgb L);
/* Task 5.1: CS184's stopping rule beside the part's verdict. */
void referee_converged(trace_log *t, int n, double s1, double s2, float tol, bool verdict);
/* Task 9.2: the lens ray beside the facts that make it one. */
void referee_lens_ray(trace_log *t, const camera *c, ray pinhole, vec2 u, ray r);
/* Part 8: an environment sample's radiance and pdf against the map and the part's env_pdf. */
void referee_environment(trace_log *t, const light *l, const light_sample *ls);

/* ---- the densities (trace_density.c): samplers against their own samples ---------------------- */

/* The BSDF sampler of material m at direction wo (local): its pdf against its samples, drawn here. */
void density_check_bsdf(trace_log *t, const material *m, vec3 wo);
/* The environment light's sampler: its pdf (env_pdf, or uniform) against its samples. */
void density_check_environment(trace_log *t, const light *l);
/* The lens: thin_lens_ray's starting points against the uniform disc of radius -b. */
void density_check_lens(trace_log *t, const camera *c, ray pinhole);

#endif
