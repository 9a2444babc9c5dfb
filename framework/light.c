/* Lights: sampling one incident direction at a shading point, with its solid-angle density.
 * Every kind returns radiance arriving at p (attenuation already applied), so the estimator in
 * part 3 is the same for all of them: L * f * cos / pdf. */
#include "light.h"
#include "frame.h"
#include "sampler.h"
#include "spawn.h"
#include "trace_hook.h"
#include "envmap.h"
#ifdef PL_HAS_PART8
#include "../parts/part8_envlight/part8.h"  /* call sites of the parts (framework/README.md) */
#endif
#include <math.h>
#include <stdlib.h>
#include <string.h>

bool light_is_delta(const light *l)
{
    return l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_DIRECTIONAL;
}

/* COLLADA attenuation: intensity / (constant + linear d + quadratic d^2). The inverse square law
 * is not in here: sample_point divides by d^2 for every point light. A denominator <= 0 (a file
 * with all zeros) means "no attenuation", as Blender's exporter intends. */
static float attenuation(const light *l, float dist)
{
    float den = l->attenuation[0] + l->attenuation[1] * dist + l->attenuation[2] * dist * dist;
    return den > 0.0f ? 1.0f / den : 1.0f;
}

/* A point source at q with intensity I (W/sr) gives irradiance I / d^2 on a surface facing it.
 * As a delta light it reports that as its "radiance" with pdf 1: the estimator's L cos / pdf is
 * then the irradiance, the integral over the delta direction. */
static bool sample_point(const light *l, vec3 p, light_sample *out)
{
    vec3 d = vec3_sub(l->position, p);
    float dist2 = vec3_dot(d, d);
    if (!(dist2 > 0.0f))
        return false;
    float dist = sqrtf(dist2);
    out->wi = vec3_scale(d, 1.0f / dist);
    out->dist = dist;
    out->point = l->position;
    out->pdf = 1.0f;
    out->is_delta = true;
    out->L = rgb_scale(l->radiance, attenuation(l, dist) / dist2);
    return true;
}

/* A spot light is a point light times a cone profile: full intensity on the axis, falling off as
 * cos^falloff_exp of the angle to the axis, and nothing beyond falloff_deg. */
static bool sample_spot(const light *l, vec3 p, light_sample *out)
{
    if (!sample_point(l, p, out))
        return false;
    float cos_axis = -vec3_dot(out->wi, vec3_normalize(l->direction));
    float cos_cone = cosf(deg_to_rad(l->falloff_deg));
    if (cos_axis <= cos_cone)
        return false;
    float profile = l->falloff_exp > 0.0f ? powf(cos_axis, l->falloff_exp) : 1.0f;
    out->L = rgb_scale(out->L, profile);
    return true;
}

static bool sample_directional(const light *l, light_sample *out)
{
    out->wi = vec3_neg(vec3_normalize(l->direction));
    out->dist = INFINITY;
    out->point = vec3_make(0.0f, 0.0f, 0.0f);  /* at infinity: unused */
    out->pdf = 1.0f;
    out->is_delta = true;
    out->L = l->radiance;
    return true;
}

/* A point uniform on the parallelogram has density 1 / area per unit area; per unit solid angle
 * seen from p that is dist^2 / (cos_light * area), cos_light taken against the UNIT direction.
 * (CS184 used an unnormalised vector here, which scales its light by the distance.) */
static bool sample_area(const light *l, vec3 p, vec2 u, light_sample *out)
{
    vec3 q = vec3_add(l->position, vec3_add(vec3_scale(l->edge_u, u.x - 0.5f),
                                            vec3_scale(l->edge_v, u.y - 0.5f)));
    vec3 d = vec3_sub(q, p);
    float dist2 = vec3_dot(d, d);
    if (!(dist2 > 0.0f) || !(l->area > 0.0f))
        return false;
    float dist = sqrtf(dist2);
    vec3 wi = vec3_scale(d, 1.0f / dist);
    float cos_light = -vec3_dot(wi, l->direction);
    if (cos_light <= 0.0f)  /* one-sided: p is behind the light, or in its plane */
        return false;
    float pdf = dist2 / (cos_light * l->area);
    if (!isfinite(pdf))
        return false;
    out->wi = wi;
    out->dist = dist;
    out->point = q;
    out->pdf = pdf;
    out->is_delta = false;
    out->L = l->radiance;
    return true;
}

/* CS184's ambient light: constant radiance from every direction of the upper hemisphere (world
 * +Y), sampled uniformly over that hemisphere. */
static bool sample_ambient(const light *l, vec2 u, light_sample *out)
{
    frame up = frame_from_normal(vec3_make(0.0f, 1.0f, 0.0f));
    vec3 w = sample_uniform_hemisphere(u);
    out->wi = frame_to_world(&up, w);
    out->dist = INFINITY;
    out->point = vec3_make(0.0f, 0.0f, 0.0f);  /* at infinity: unused */
    out->pdf = sample_uniform_hemisphere_pdf(w);
    out->is_delta = false;
    out->L = l->radiance;
    return out->pdf > 0.0f;
}

/* The environment map, through part 8: importance sampling by its tables (task 8.4), or uniform
 * sampling of the sphere (task 8.1) under --env-uniform. Tables that are not CDFs (a stubbed or
 * broken task 8.2) light the scene in the stubs' magenta from straight up, so the picture says so
 * rather than crashing a sampler that trusts them. Without part 8 the light does not exist. */
static bool sample_environment(const light *l, vec2 u, light_sample *out)
{
    out->dist = INFINITY;
    out->point = vec3_make(0.0f, 0.0f, 0.0f);  /* at infinity: unused */
    out->is_delta = false;
    out->pdf = 0.0f;
#ifdef PL_HAS_PART8
    if (!l->env_dist) out->L = env_sample_uniform(l->env, u, &out->wi, &out->pdf);
    else if (l->env_dist->valid) out->L = env_sample_importance(l->env, l->env_dist, u, &out->wi, &out->pdf);
    else out->wi = vec3_make(0.0f, 1.0f, 0.0f), out->pdf = 1.0f, out->L = rgb_magenta();
#else
    (void)l, (void)u;
    out->wi = vec3_make(0.0f, 1.0f, 0.0f), out->L = rgb_gray(0.0f);
#endif
    return out->pdf > 0.0f && isfinite(out->pdf);
}

static bool sample_light(const light *l, vec3 p, vec2 u, light_sample *out)
{
    switch (l->kind) {
    case LIGHT_POINT:       return sample_point(l, p, out);
    case LIGHT_SPOT:        return sample_spot(l, p, out);
    case LIGHT_DIRECTIONAL: return sample_directional(l, out);
    case LIGHT_AREA:        return sample_area(l, p, u, out);
    case LIGHT_AMBIENT:     return sample_ambient(l, u, out);
    case LIGHT_ENVIRONMENT: return sample_environment(l, u, out);
    }
    return false;
}

light light_make_area(vec3 position, vec3 edge_u, vec3 edge_v, vec3 direction, rgb radiance)
{
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_AREA;
    l.radiance = radiance;
    l.position = position;
    l.edge_u = edge_u;
    l.edge_v = edge_v;
    l.direction = direction;
    l.area = vec3_length(vec3_cross(edge_u, edge_v));
    l.attenuation[0] = 1.0f;
    spawn_light_leave(&l);
    return l;
}

vec3 light_area_corner(const light *l, int k)
{
    vec3 hu = vec3_scale(l->edge_u, 0.5f), hv = vec3_scale(l->edge_v, 0.5f);
    return vec3_add(l->position, vec3_add(k & 1 ? hu : vec3_neg(hu), k & 2 ? hv : vec3_neg(hv)));
}

float light_environment_pdf(const light *l, vec3 wi)
{
#ifdef PL_HAS_PART8
    if (l->kind != LIGHT_ENVIRONMENT || !l->env) return 0.0f;
    return l->env_dist ? env_pdf(l->env, l->env_dist, wi) : sample_uniform_sphere_pdf(wi);
#else
    (void)l, (void)wi;
    return 0.0f;
#endif
}

bool light_sample_environment(const light *l, vec2 u, light_sample *out)
{
    return l->kind == LIGHT_ENVIRONMENT && sample_environment(l, u, out);
}

/* A seam function (framework/seam.h): a trace of this thread sees every light sample. */
bool light_sample_L(const light *l, vec3 p, vec2 u, light_sample *out)
{
    bool ok = sample_light(l, p, u, out);
    if (pl_trace) trace_light(l, p, u, ok, out);
    return ok;
}

#ifdef PL_HAS_PART8
pl_status light_add_environment(scene *s, bool uniform, pl_diag *diag)
{
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_ENVIRONMENT;
    l.env = s->env;
    if (!uniform) {
        s->env_dist = calloc(1, sizeof *s->env_dist);
        if (!s->env_dist || env_distribution_alloc(s->env_dist, s->env->width, s->env->height) != PL_OK)
            return pl_fail(diag, PL_ERR_NOMEM, "-e %s: out of memory for the importance-sampling tables", s->env->path);
        env_build_distribution(s->env, s->env_dist);
        char why[160];
        if (!env_distribution_check(s->env_dist, why, sizeof why))
            pl_warn(diag, "task 8.2, env_build_distribution: %s; the environment lights in magenta until its tables "
                          "are CDFs", why);
        l.env_dist = s->env_dist;
    }
    return scene_add_light(s, l) >= 0 ? PL_OK : pl_fail(diag, PL_ERR_NOMEM, "out of memory for a light");
}
#endif
