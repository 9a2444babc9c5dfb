/* --trace-pixel's referee: from the numbers the hooks saw, what a correct part returns, part by
 * part, and a "!!" mark where the part's answer or a value it made breaks a rule. It judges by the
 * parts' own functions reached through the framework (material_f, material_pdf, material_sample_f,
 * russian_roulette on fresh generators, zero_bounce_radiance, light_environment_pdf), never by a
 * copy of a part's formula (trace_internal.h says why). A new part adds its rule here, in a
 * paragraph of its own. Test machinery: not part of any assignment. */
#include "trace_internal.h"
#include "accel.h"
#include "envmap.h"
#include "frame.h"
#include "sampler.h"
#include "spawn.h"
#include "todo.h"
#include "../parts/part3_direct/part3.h"  /* replayed part functions (framework/README.md) */
#include "../parts/part4_global/part4.h"
#include <math.h>

/* ---- part 3: direct light (tasks 3.1, 3.4, 3.5) ------------------------------------------------ */

void referee_diffuse_bound(trace_log *t, rgb bright)
{
    if (!rgb_is_black(bright))
        trace_mark(t, "bsdf_f is " V3 " here: a diffuse f is at most 1/pi = 0.3183, or the surface reflects more light "
                   "than it receives", RGB(bright));
}

/* One light sample of direct_importance, by the framework's own visibility test: the shadow ray the
 * framework would spawn (spawn_ray_to_light), so the trace and a correct part agree on every sample. */
rgb referee_light_sample(trace_log *t, const light *l, const light_sample *ls, float *cosine, bool *visible, rgb *bright)
{
    const scene *s = t->ctx->scene;
    trace_frame *f = trace_top(t);
    rgb c = rgb_gray(0.0f);
    if (!f || f->fn != PL_SEAM_direct_importance) return c;
    frame sf = shading_frame(&f->r, &f->h);
    vec3 wo = frame_to_local(&sf, vec3_neg(f->r.d)), wi = frame_to_local(&sf, ls->wi);
    *cosine = wi.z;
    /* The samples this vertex takes per light: -l at the first vertex, one deeper (render.h). */
    int n = light_is_delta(l) ? 1 : render_light_samples(f->ctx, &f->r);
    ray probe = spawn_ray_to_light(&f->r, &f->h, l, ls);
    *visible = !accel_occluded(t->ctx->accel, &probe);
    if (ls->pdf > 0.0f && wi.z > 0.0f && f->h.material >= 0 && f->h.material < s->num_materials) {
        const material *m = &s->materials[f->h.material];
        rgb fr = material_f(m, wo, wi);
        c = rgb_scale(rgb_mul(ls->L, fr), wi.z / ls->pdf / (float)n);
        if (trace_shades_diffuse(m) && rgb_max(fr) > 1.0001f * PL_INV_PI) *bright = fr;
    }
    if (*visible) t->direct.visible = rgb_add(t->direct.visible, c);
    else t->direct.hidden = rgb_add(t->direct.hidden, c);
    return c;
}

/* What direct_importance returned against the sum of its light samples the trace saw: a shadowed
 * sample still counted is named as such, any other difference as the two sums; likewise for
 * direct_hemisphere's rays. */
void referee_direct(trace_log *t, pl_seam_id fn, rgb L)
{
    trace_direct *d = &t->direct;
    if (trace_rgb_close(L, d->visible)) return;
    if (fn == PL_SEAM_direct_hemisphere)
        trace_mark(t, "the hemisphere samples add up to " V3 " (each Le f cos / pdf / N, the uniform pdf 1/(2 pi), N = "
                   "num_lights x the light samples) but direct_hemisphere returned " V3 ": a direction from another "
                   "sampler must be divided by that sampler's pdf, and the sum by N", RGB(d->visible), RGB(L));
    else if (!rgb_is_black(d->hidden) && trace_rgb_close(L, rgb_add(d->visible, d->hidden)))
        trace_mark(t, "a light sample hits something nearer than the light and is still counted");
    else
        trace_mark(t, "the light samples add up to " V3 " but direct_importance returned " V3, RGB(d->visible), RGB(L));
}

/* What one hemisphere ray that hit something must add: Le f cos / pdf / N with task 3.4's uniform
 * pdf 1/(2 pi) and N = num_lights x the light samples at this vertex (render_light_samples). */
void referee_hemisphere_hit(trace_log *t, const ray *r, const hit *h)
{
    int before = pl_todo_count();
    trace_frame *f = trace_top(t);
    rgb Le = zero_bounce_radiance(f->ctx, r, h);
    if (pl_todo_count() != before) return;
    const scene *s = f->ctx->scene;
    frame sf = shading_frame(&f->r, &f->h);
    vec3 wo = frame_to_local(&sf, vec3_neg(f->r.d)), wi = frame_to_local(&sf, vec3_normalize(r->d));
    int n = s->num_lights * render_light_samples(f->ctx, &f->r);
    rgb adds = rgb_gray(0.0f);
    if (wi.z > 0.0f && f->h.material >= 0 && f->h.material < s->num_materials && n > 0)
        adds = rgb_scale(rgb_mul(Le, material_f(&s->materials[f->h.material], wo, wi)), wi.z * 2.0f * (float)PL_PI / (float)n);
    t->direct.visible = rgb_add(t->direct.visible, adds);
    trace_emit(t, "emission", json_pack("{s:o, s:o}", "emission", trace_jrgb(Le), "contribution", trace_jrgb(adds)),
               "  emission towards the surface " V3 ", adds " V3 " (Le f cos / (1 / (2 pi)) / N, N = %d)", RGB(Le),
               RGB(adds), n);
}

/* ---- part 4: paths (tasks 4.1 and 4.2), with parts 6 and 7's samplers through material.h ------ */

/* One bounce's direct light returned L: the throughput times L, kept unless -o 0 drops it. */
void referee_bounce_added(trace_log *t, rgb L)
{
    trace_path *p = &t->path;
    rgb added = rgb_mul(p->beta, L);
    const render_settings *s = &t->stack[t->depth - 1].ctx->settings;
    bool kept = s->accumulate || p->bounce == s->max_depth;
    if (kept) p->expected = rgb_add(p->expected, added);
    trace_emit(t, "added", json_pack("{s:i, s:o, s:b}", "bounce", p->bounce, "added", trace_jrgb(added), "kept", kept),
               "bounce %d adds throughput x direct = " V3 "%s", p->bounce, RGB(added), kept ? "" : " (not kept: -o 0)");
    p->draws = 0;
}

/* What a mirror's or glass's sample must weigh, f |cos| / pdf (part 6's handout): its reflectance
 * when it reflects (wi on wo's side), its transmittance times a radiance scale when it refracts
 * (eta^2, CS184's 1 / eta^2 or none: part 6's handout accepts each). Never R or 1 - R times that: the
 * branch's probability must cancel. */
static void check_delta_weight(trace_log *t, const material *m, vec3 wo, vec3 wi, rgb weight)
{
    if (rgb_is_black(weight)) return;  /* no direction: the path ends, nothing to weigh */
    if (wi.z * wo.z > 0.0f) {
        if (!trace_rgb_close(weight, m->reflectance))
            trace_mark(t, "this reflection weighs f |cos| / pdf = " V3 ", not the reflectance " V3 " (part 6, tasks 6.2 "
                       "and 6.5)", RGB(weight), RGB(m->reflectance));
        return;
    }
    float eta = wo.z > 0.0f ? 1.0f / m->ior : m->ior;
    const float scales[] = {eta * eta, 1.0f / (eta * eta), 1.0f};
    for (int i = 0; i < 3; i++)
        if (trace_rgb_close(weight, rgb_scale(m->transmittance, scales[i]))) return;
    trace_mark(t, "this refraction weighs f |cos| / pdf = " V3 ", not the transmittance " V3 " times eta^2 = %.4g (or "
               "1 / eta^2, or 1) (part 6, tasks 6.4 and 6.5)", RGB(weight), RGB(m->transmittance), (double)(eta * eta));
}

/* A mirror's or glass's f and pdf are no functions of wi (material.h): the sample that sent the
 * bounce ray wi is replayed on the numbers the vertex drew, checked against wi and weighed. Its two
 * numbers are the vertex's first two draws, or the second and third where roulette drew first (both
 * orders are the part's to choose). Returns f and sets *pdf. */
static rgb delta_replay(trace_log *t, const material *m, vec3 wo, vec3 wi, float *pdf)
{
    trace_path *p = &t->path;
    rgb fr = rgb_gray(0.0f), first_fr = fr;
    vec3 said = wi, first = wi;
    float first_pdf = 0.0f;
    bool matched = false;
    for (int k = 0; k + 1 < p->draws && k < 2 && !matched; k++) {
        trace_replaying = true;
        fr = material_sample_f(m, wo, vec2_make(p->value[k], p->value[k + 1]), &said, pdf);
        trace_replaying = false;
        if (k == 0) {
            first = said;
            first_fr = fr;
            first_pdf = *pdf;
        }
        matched = vec3_dot(said, wi) >= 0.9999f * vec3_length(wi);
    }
    if (!matched) {
        /* Neither order sent wi: say so, and weigh the sample of the first two draws. */
        trace_mark(t, "the bounce ray leaves along " V3 " (local) but material_sample_f sent " V3, XYZ(wi), XYZ(first));
        said = first;
        fr = first_fr;
        *pdf = first_pdf;
    }
    if (*pdf > 0.0f) check_delta_weight(t, m, wo, said, rgb_scale(fr, fabsf(said.z) / *pdf));
    return fr;
}

/* The BSDF sample that sent wi (local) from the current vertex; returns the new throughput. A
 * rough BSDF's sampler is measured against its pdf here too, a few times a trace (trace_density.c). */
static rgb bsdf_step(trace_log *t, vec3 wo, vec3 wi, const char *how)
{
    trace_path *p = &t->path;
    const material *m = trace_material_at(t, &p->at);
    rgb fr = rgb_gray(0.0f);
    float pdf = 0.0f;
    bool delta = m && material_is_delta(m);
    if (delta && p->draws >= 2)
        fr = delta_replay(t, m, wo, wi, &pdf);
    else if (m && !delta) {
        fr = material_f(m, wo, wi);
        pdf = material_pdf(m, wo, wi);
    }
    rgb factor = pdf > 0.0f ? rgb_scale(fr, fabsf(wi.z) / pdf) : rgb_gray(0.0f);
    rgb beta = rgb_mul(p->beta, factor);
    trace_emit(t, "bsdf_sample",
               json_pack("{s:o, s:o, s:o, s:o, s:o}", "direction", trace_jvec(wi), "f", trace_jrgb(fr), "pdf",
                         trace_jnum(pdf), "cosine", trace_jnum(wi.z), "throughput", trace_jrgb(beta)),
               "BSDF sample%s: direction " V3 " (local, +z the normal), f " V3 ", pdf %.6g, cos %.5g -> throughput " V3,
               how, XYZ(wi), RGB(fr), (double)pdf, (double)wi.z, RGB(beta));
    /* Light passes below a surface that transmits (glass); every other surface reflects. A diffuse
     * sampler never leaves below it; part 7's metal may draw a direction below, which it must
     * then return black, with pdf 0: the path ends there. */
    if (wi.z <= 0.0f && !p->at.transmits && m && (trace_shades_diffuse(m) || !rgb_is_black(factor)))
        trace_mark(t, "the bounce direction is below the surface it leaves (cos theta = %.5g)", (double)wi.z);
    if (!(pdf > 0.0f) && !rgb_is_black(fr)) trace_mark(t, "pdf is 0 but f is " V3 " (not black)", RGB(fr));
    bool cosine_pdf = fabsf(pdf - wi.z * PL_INV_PI) <= 1e-3f * pdf;
    if (m && trace_shades_diffuse(m) && ((cosine_pdf && rgb_max(factor) > 1.0001f) || rgb_max(fr) > 1.0001f * PL_INV_PI))
        trace_mark(t, "throughput above 1 after a diffuse bounce: f cos / pdf = " V3 ", f = " V3 " (a diffuse f is at "
                   "most 1/pi)", RGB(factor), RGB(fr));
    if (m && !delta && t->recording) density_check_bsdf(t, m, wo);
    return beta;
}

/* Measures russian_roulette's rule at this vertex, whatever its convention (go on when the draw is
 * below q, or stop when it is below 1 - q: both are correct) and whenever it draws (before or after
 * the BSDF sample): replayed ROULETTE_DRAWS times with fresh generators, the probability of going on,
 * against the factor the throughput of a path that goes on is divided by. The mean stays the same
 * only when the two agree. Returns the throughput of a path that goes on. */
#define ROULETTE_DRAWS 4096

static rgb roulette(trace_log *t, rgb beta, bool went_on)
{
    trace_path *p = &t->path;
    if (p->draws < 3) return beta;  /* two draws for the direction: no roulette at this vertex */
    rgb after = beta;
    int goes = 0;
    trace_replaying = true;
    for (int k = 0; k < ROULETTE_DRAWS; k++) {
        rgb b = beta;
        /* Independent draws (rng.h): the streams of one rng_seeded seed form a lattice, which moved
         * the sixth draw's measured probability by up to twice this check's slack. */
        rng g = rng_for_sample(0x7261636500000000ull, (uint64_t)p->bounce, (uint64_t)k);
        if (russian_roulette(&b, p->bounce + 1, &g)) goes++, after = b;
    }
    trace_replaying = false;
    double q = (double)goes / ROULETTE_DRAWS;
    /* What the throughput of a path that goes on is divided by: before over after. */
    double divided = goes > 0 && rgb_max(after) > 0.0f ? (double)rgb_max(beta) / rgb_max(after) : NAN;
    trace_emit(t, "roulette",
               json_pack("{s:o, s:o, s:b, s:o}", "probability", trace_jnum((float)q), "divided_by",
                         trace_jnum((float)divided), "continue", went_on, "throughput",
                         trace_jrgb(went_on ? after : rgb_gray(0))),
               "Russian roulette before bounce %d -> %s; the rule goes on with probability %.3g (measured over %d draws) "
               "and divides by %.3g", p->bounce + 1, went_on ? "continue" : "stop", q, ROULETTE_DRAWS,
               goes > 0 ? divided : 1.0);
    if (went_on && goes == 0)
        trace_mark(t, "the path went on, but russian_roulette replayed with this throughput and depth ends every path");
    /* Five standard errors of the measured probability, and the draws' own step. */
    double slack = 5.0 * sqrt(q * (1.0 - q) / ROULETTE_DRAWS) + 2.0 / ROULETTE_DRAWS;
    p->gambled = p->gambled || goes < ROULETTE_DRAWS;
    if (goes > 0 && isfinite(divided) && fabs(q - divided) > slack) {
        if (divided > 0.9999 && q < 1.0 - slack)
            trace_mark(t, "russian_roulette ends paths but does not divide the throughput of those that go on by its "
                       "probability");
        else
            trace_mark(t, "russian_roulette goes on with probability %.3g but divides the throughput by %.3g: the mean "
                       "changes unless the two are equal (handout/part4.md, 4.2)", q, divided);
    }
    if (went_on)
        trace_emit(t, "throughput", json_pack("{s:o}", "throughput", trace_jrgb(after)), "throughput / probability = " V3,
                   RGB(after));
    return after;
}

/* A bounce ray left the vertex: the BSDF step that chose it and the roulette that let it go on. */
void referee_bounce_ray(trace_log *t, const ray *r)
{
    trace_path *p = &t->path;
    frame sf = shading_frame(&p->cur, &p->at);
    vec3 wo = frame_to_local(&sf, vec3_neg(p->cur.d)), wi = frame_to_local(&sf, r->d);
    p->beta = roulette(t, bsdf_step(t, wo, wi, ""), true);
    p->bounce++;  /* the ray reaches the next vertex: nothing drawn there yet */
    p->draws = 0;
}

/* The path ended: its last, unused direction replayed, then its sum against what the part returned. */
void referee_path_end(trace_log *t, rgb L)
{
    trace_path *p = &t->path;
    const material *m = trace_material_at(t, &p->at);
    if (p->draws >= 2 && m) {
        /* The path ended after drawing its next direction: replay material_sample_f with those numbers. */
        frame sf = shading_frame(&p->cur, &p->at);
        vec3 wo = frame_to_local(&sf, vec3_neg(p->cur.d)), wi;
        float pdf;
        trace_replaying = true;
        (void)material_sample_f(m, wo, vec2_make(p->value[0], p->value[1]), &wi, &pdf);
        trace_replaying = false;
        rgb beta = bsdf_step(t, wo, wi, " (replayed; the path ends after it)");
        roulette(t, beta, false);
    }
    p->active = false;
    /* The throughput a part hands russian_roulette is its own choice (the path's, or this bounce's
     * alone: CS184's recursion), and so is what it divides by: once roulette played, the trace's sum
     * is one correct answer of several. Its rule was checked at each vertex above. */
    if (p->gambled) {
        trace_emit(t, "unchecked", json_pack("{s:o}", "expected", trace_jrgb(p->expected)),
                   "the bounces add up to " V3 " by the path's throughput; not checked, roulette played on this path",
                   RGB(p->expected));
        return;
    }
    if (pl_todo_count() == t->stack[t->depth - 1].todo_before && !trace_rgb_close(L, p->expected))
        trace_mark(t, "the bounces add up to " V3 " but at_least_one_bounce_radiance returned " V3
                   ": the throughput is not the product of f cos / pdf over the roulette's probabilities",
                   RGB(p->expected), RGB(L));
}

/* ---- part 5: the stopping rule (task 5.1) ------------------------------------------------------ */

/* CS184's stopping rule, recomputed so the check shows its numbers beside the part's verdict. */
void referee_converged(trace_log *t, int n, double s1, double s2, float tol, bool verdict)
{
    double mean = s1 / n, var = n > 1 ? fmax(0.0, (s2 - s1 * s1 / n) / (n - 1)) : 0.0;
    double half = 1.96 * sqrt(var / n), bound = tol * mean;
    bool was = t->recording;
    json_t *saved = t->events;
    t->recording = true;
    t->events = NULL;
    t->depth = -1;
    trace_emit(t, "batch_check", json_pack("{s:i, s:f, s:f, s:f, s:b}", "samples", n, "mean", mean, "half_width", half,
                                           "tolerance", bound, "stop", verdict),
               "batch check after %d samples: mean luminance %.6g, half-width %.6g, tolerance %.6g -> %s", n, mean, half,
               bound, verdict ? "stop" : "go on");
    if (verdict != (half <= bound) && n > 1)
        trace_mark(t, "adaptive_converged says %s, but I = %.6g %s T * mean = %.6g", verdict ? "stop" : "go on", half,
                   half <= bound ? "<=" : ">", bound);
    t->depth = 0;
    t->recording = was;
    t->events = saved;
}

/* ---- part 8: the environment light (tasks 8.1, 8.3, 8.4) --------------------------------------- */

/* The density part 8 gives a direction inside texel (x, y) of the map at (fx, fy) within it (0 to
 * 1 across it, kept 2e-4 from its edges): a direction at most 2e-4 of a texel from the sample's,
 * which changes sin(theta), and so the density, by at most 2e-4 of itself away from a pole. */
static double texel_pdf(const light *l, int x, int y, double fx, double fy)
{
    const envmap *e = l->env;
    fx = fmin(fmax(fx, 2e-4), 1.0 - 2e-4), fy = fmin(fmax(fy, 2e-4), 1.0 - 2e-4);
    vec3 w = envmap_direction((float)((y + fy) * PL_PI / e->height), (float)((x + fx) * 2.0 * PL_PI / e->width));
    return light_environment_pdf(l, w);
}

/* Where a sample at texel coordinate c (texel k = floor(c)) lies within candidate texel k2: at c
 * itself in its own texel, at the shared edge in a neighbour. */
static double within(double c, int k, int k2, int after)
{
    return k2 == k ? c - k : k2 == after ? 0.0 : 1.0;
}

/* An environment sample against the two facts that make it one (part 8): its radiance is the map's
 * in its direction, and its pdf is the density part 8 gives that direction (env_pdf over the
 * tables, task 8.3; 1 / (4 pi) for uniform sampling, task 8.1). A direction within 1e-4 of a
 * texel's edge may belong to either texel (its angles were rounded to floats): either one's
 * radiance and density are right there. Whether the pdf is the density the sampler draws with is
 * the density check's to say (trace_density.c). */
void referee_environment(trace_log *t, const light *l, const light_sample *ls)
{
    const envmap *e = l->env;
    if (l->env_dist && !l->env_dist->valid) return;  /* the load warned: task 8.2's tables are not CDFs */
    vec2 c = envmap_texel_coords(e, ls->wi);
    double u = c.x, v = c.y;
    int x = (int)fmin(fmax(floor(u), 0.0), e->width - 1), y = (int)fmin(fmax(floor(v), 0.0), e->height - 1);
    /* The texel, and the one across each edge the direction is within 1e-4 of (phi wraps around). */
    int xs[2] = {x, x}, ys[2] = {y, y};
    if (u - floor(u) < 1e-4) xs[1] = (x + e->width - 1) % e->width;
    else if (ceil(u) - u < 1e-4) xs[1] = (x + 1) % e->width;
    if (v - floor(v) < 1e-4 && y > 0) ys[1] = y - 1;
    else if (ceil(v) - v < 1e-4 && y < e->height - 1) ys[1] = y + 1;
    /* 1e-3 of the density, and near a pole what sinf(acosf(y)) in float may cost a correct part. */
    double sin_theta = hypot(ls->wi.x, ls->wi.z) / vec3_length(ls->wi);
    double slack = 1e-3 + 1e-6 / (sin_theta * sin_theta);
    bool radiance_ok = false, pdf_ok = false;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            rgb T = envmap_texel(e, xs[i], ys[j]);
            radiance_ok |= ls->L.r == T.r && ls->L.g == T.g && ls->L.b == T.b;
            double pdf = texel_pdf(l, xs[i], ys[j], within(u, x, xs[i], (x + 1) % e->width), within(v, y, ys[j], y + 1));
            pdf_ok |= fabs(ls->pdf - pdf) <= slack * pdf;
        }
    rgb want = envmap_texel(e, x, y);
    if (!radiance_ok)
        trace_mark(t, "the environment sample's radiance " V3 " is not the map's in its direction, texel (%d, %d): " V3
                   " (return the radiance of the direction you chose)", RGB(ls->L), x, y, RGB(want));
    if (!pdf_ok)
        trace_mark(t, "the environment sample's pdf %.6g is not the density of its direction, %.6g (%s)", (double)ls->pdf,
                   light_environment_pdf(l, ls->wi),
                   l->env_dist ? "env_pdf's there, task 8.3: a sample's pdf is the density of the direction it returns, "
                                 "task 8.4"
                               : "uniform over the sphere: 1 / (4 pi), task 8.1");
}

/* ---- part 9: the thin lens (task 9.2) --------------------------------------------------------- */

/* Part 9's lens ray beside the facts that make it right, each recomputed here: it starts on the
 * lens (the disc of radius R around the camera's position, in the camera's own X and Y), its
 * direction is a unit vector, and it passes through the pinhole ray's point on the plane of focus
 * (D ahead along the view axis), measured along its direction made unit (a direction of another
 * length is its own mark, not a miss). The tolerances are float rounding's, scaled to the camera's
 * distance from the scene's origin. */
void referee_lens_ray(trace_log *t, const camera *c, ray pinhole, vec2 u, ray r)
{
    vec3 forward = mat4_dir(c->camera_to_world, vec3_make(0.0f, 0.0f, -1.0f));
    vec3 focus = ray_at(&pinhole, c->focal_distance / vec3_dot(pinhole.d, forward));
    vec3 offset = vec3_sub(r.o, c->position), to_focus = vec3_sub(focus, r.o);
    float off_plane = vec3_dot(offset, forward);
    float from_centre = vec3_length(vec3_sub(offset, vec3_scale(forward, off_plane)));
    float length = vec3_length(r.d);
    vec3 d = length > 0.0f ? vec3_scale(r.d, 1.0f / length) : r.d;
    float miss = vec3_length(vec3_sub(to_focus, vec3_scale(d, vec3_dot(to_focus, d))));
    float scale = 1.0f + vec3_length(c->position);
    bool through = miss <= 1e-4f * (vec3_length(to_focus) + scale);  /* within rounding: the text says so */
    char passes[64] = "passes through that point";
    if (!through) snprintf(passes, sizeof passes, "passes %.3g from that point", (double)miss);
    trace_emit(t, "lens_ray",
               json_pack("{s:o, s:o, s:o, s:o, s:o}", "focus", trace_jpoint(t, focus), "lens_radius",
                         trace_jnum(c->lens_radius), "from_lens_centre", trace_jnum(from_centre), "off_lens_plane",
                         trace_jnum(off_plane), "focus_miss", trace_jnum(miss)),
               "thin lens (task 9.2), u = (%.5g, %.5g): the pinhole ray meets the plane of focus (%.5g ahead) at " V3
               "; the lens ray starts %.5g from the lens's centre (radius %.5g) and %s",
               (double)u.x, (double)u.y, (double)c->focal_distance, PXYZ(focus), (double)from_centre,
               (double)c->lens_radius, passes);
    if (!(fabsf(off_plane) <= 1e-5f * scale) || !(from_centre <= c->lens_radius * (1.0f + 1e-4f) + 1e-6f * scale))
        trace_mark(t, "the lens ray starts off the lens: %.5g along the view axis and %.5g from the lens's centre "
                   "(radius %.5g); the lens is the disc of radius -b in the camera's own X and Y", (double)off_plane,
                   (double)from_centre, (double)c->lens_radius);
    if (!(fabsf(length - 1.0f) <= 1e-4f))
        trace_mark(t, "the lens ray's direction has length %.6g, not 1: a camera ray's direction is a unit vector "
                   "(ray.h, part9.h), and every distance and cosine along it assumes so", (double)length);
    if (!through)
        trace_mark(t, "the lens ray misses the pinhole ray's point on the plane of focus by %.3g: that point would not "
                   "be sharp", (double)miss);
}
