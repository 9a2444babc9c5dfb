/* COLLADA loader: materials. instance_material@target -> <material> -> <instance_effect> -> <effect>.
 * A CGL technique in the effect defines the BSDF; otherwise profile_COMMON's diffuse colour does.
 * Each <material> becomes one scene material, however many instances bind it. */
#include "dae_internal.h"
#include "material.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the default ----------------------------------------------------------------------------- */

/* Grey 0.5, made on first use and shared: geometry with no material still renders, and a scene
 * that binds everything has no unused material. */
pl_status dae_default_material(dae_ctx *c, int *out)
{
    if (c->default_material < 0) {
        material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
        snprintf(m.name, sizeof m.name, "%s", "(default grey)");
        c->default_material = scene_add_material(c->out, m);
        if (c->default_material < 0) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    }
    *out = c->default_material;
    return PL_OK;
}

/* ---- reading one effect ---------------------------------------------------------------------- */

/* The shading model element of profile_COMMON (phong, lambert, blinn or constant), or NULL. */
static const xmlNode *common_shader(const xmlNode *effect)
{
    const xmlNode *technique = dae_child(dae_child(effect, "profile_COMMON"), "technique");
    for (const xmlNode *s = dae_first(technique); s; s = dae_next(s))
        if (dae_is(s, "phong") || dae_is(s, "lambert") || dae_is(s, "blinn") || dae_is(s, "constant"))
            return s;
    return NULL;
}

/* A CGL technique anywhere an exporter puts one: under the effect, its profile or its technique. */
static const xmlNode *cgl_technique(const xmlNode *effect)
{
    const xmlNode *profile = dae_child(effect, "profile_COMMON");
    const xmlNode *t = dae_cgl_technique(effect);
    if (!t) t = dae_cgl_technique(profile);
    if (!t) t = dae_cgl_technique(dae_child(profile, "technique"));
    return t;
}

/* Fills albedo and Le from profile_COMMON; a texture keeps the grey default, with a warning. */
static pl_status read_common(dae_ctx *c, const xmlNode *effect, material *m)
{
    const xmlNode *shader = common_shader(effect);
    const xmlNode *diffuse = dae_child(shader, "diffuse");
    pl_status st = PL_OK;
    if (diffuse) {
        const xmlNode *color = dae_child(diffuse, "color");
        if (color) {
            st = dae_color(c, color, &m->albedo);
        } else if (dae_child(diffuse, "texture") || dae_child(diffuse, "param")) {
            dae_warn_once(c, diffuse, "texture",
                          "textures are not supported; the diffuse colour is grey 0.5 instead");
        }
    }
    if (!st && dae_child(dae_child(shader, "emission"), "color"))
        st = dae_child_color(c, shader, "emission", false, &m->Le);
    return st;
}

/* Reflectance at normal incidence of a conductor with index eta + i k, the colour a diffuse
 * stand-in for a microfacet metal should have. */
static float conductor_f0(float eta, float k)
{
    return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
}

/* A number child of a BSDF element that must be > 0 (an index of refraction, a roughness); def
 * when absent. */
static pl_status positive_child(dae_ctx *c, const xmlNode *bsdf, const char *name, float def, float *out)
{
    pl_status st = dae_child_float(c, bsdf, name, def, out);
    if (!st && !(*out > 0.0f))
        st = dae_error(c, dae_child(bsdf, name), PL_ERR_INVALID, "expected a number > 0, found %g", *out);
    return st;
}

/* A microfacet roughness: > 0 as every positive_child, and within the range where Beckmann's terms
 * stay finite in float. Below 1e-4 alpha^2 is already 1e-8 and D's peak 1/(pi alpha^2) about 3e7: the
 * surface is a mirror to float precision (use <mirror>); around 1e-23 alpha^2 underflows to 0 and D
 * becomes 0/0. Above 10 nearly every microfacet faces sideways and the metal renders black. CS184's
 * scenes use 0.005 to 0.5. */
static pl_status roughness_child(dae_ctx *c, const xmlNode *bsdf, float *out)
{
    pl_status st = positive_child(c, bsdf, "alpha", 0.5f, out);
    if (!st && !(*out >= 1e-4f && *out <= 10.0f))
        st = dae_error(c, dae_child(bsdf, "alpha"), PL_ERR_INVALID,
                       "expected a roughness from 1e-4 (a mirror to float precision) to 10, found %g", *out);
    return st;
}

/* The diffuse stand-in's colour: the element's `name` colour when the file gives one, else
 * profile_COMMON's (the last one given wins, as before the parameters were kept). */
static void stand_in(const xmlNode *bsdf, const char *name, rgb colour, material *m)
{
    if (dae_child(bsdf, name)) m->albedo = colour;
}

/* A valid material the course has no part to shade (material_kind_shaded): loaded as diffuse, and
 * said once per kind, never silently dropped. */
static void not_supported(dae_ctx *c, const xmlNode *bsdf, material_kind k, const char *kind)
{
    if (!material_kind_shaded(k))
        dae_warn_once(c, bsdf, kind, "%s materials are not supported yet, shaded as diffuse", kind);
}

/* Overrides m from the CGL technique's BSDF element (its first child). */
static pl_status read_cgl(dae_ctx *c, const xmlNode *technique, material *m)
{
    const xmlNode *bsdf = dae_first(technique);
    if (!bsdf) return dae_error(c, technique, PL_ERR_PARSE, "expected a BSDF element (emission, mirror, glass, ...)");
    pl_status st = PL_OK;
    if (dae_is(bsdf, "emission")) {
        /* CS184's emitter reflects nothing: all its light is its own */
        m->albedo = rgb_gray(0.0f);
        st = dae_child_color(c, bsdf, "radiance", true, &m->Le);
    } else if (dae_is(bsdf, "diffuse")) {
        st = dae_child_color(c, bsdf, "reflectance", false, &m->albedo);
    } else if (dae_is(bsdf, "mirror")) {
        m->kind = MATERIAL_MIRROR;
        st = dae_child_color(c, bsdf, "reflectance", false, &m->reflectance);
        stand_in(bsdf, "reflectance", m->reflectance, m);
        not_supported(c, bsdf, MATERIAL_MIRROR, "mirror");
    } else if (dae_is(bsdf, "glass")) {
        /* CS184 ignores <roughness>; it is read only so that a malformed value is an error. */
        m->kind = MATERIAL_GLASS;
        float roughness;
        st = dae_child_color(c, bsdf, "transmittance", false, &m->transmittance);
        if (!st) st = dae_child_color(c, bsdf, "reflectance", false, &m->reflectance);
        if (!st) st = positive_child(c, bsdf, "ior", 1.5f, &m->ior);
        if (!st) st = dae_child_float(c, bsdf, "roughness", 0.0f, &roughness);
        stand_in(bsdf, "transmittance", m->transmittance, m);
        stand_in(bsdf, "reflectance", m->reflectance, m);
        not_supported(c, bsdf, MATERIAL_GLASS, "glass");
    } else if (dae_is(bsdf, "refraction")) {
        m->kind = MATERIAL_REFRACTION;
        st = dae_child_color(c, bsdf, "transmittance", false, &m->transmittance);
        if (!st) st = positive_child(c, bsdf, "ior", 1.5f, &m->ior);
        stand_in(bsdf, "transmittance", m->transmittance, m);
        not_supported(c, bsdf, MATERIAL_REFRACTION, "refraction");
    } else if (dae_is(bsdf, "microfacet")) {
        /* The diffuse stand-in takes the metal's colour at normal incidence. */
        m->kind = MATERIAL_MICROFACET;
        st = roughness_child(c, bsdf, &m->alpha);
        if (!st) st = dae_child_color(c, bsdf, "eta", false, &m->eta);
        if (!st) st = dae_child_color(c, bsdf, "k", false, &m->k);
        m->albedo = rgb_make(conductor_f0(m->eta.r, m->k.r), conductor_f0(m->eta.g, m->k.g), conductor_f0(m->eta.b, m->k.b));
        not_supported(c, bsdf, MATERIAL_MICROFACET, "microfacet");
    } else {
        dae_warn_once(c, bsdf, dae_name(bsdf), "unknown CGL material <%s>; using profile_COMMON's colour",
                      dae_name(bsdf));
    }
    return st;
}

/* ---- materials and their bindings ------------------------------------------------------------- */

/* One <material> into one scene material: profile_COMMON first, then a CGL technique over it.
 * The index is kept in the entry, so a material bound again is not converted twice. */
static pl_status convert_material(dae_ctx *c, dae_entry *entry, int *out)
{
    const xmlNode *inst = dae_child(entry->node, "instance_effect");
    if (!inst) return dae_error(c, entry->node, PL_ERR_PARSE, "expected an <instance_effect>");
    dae_entry *effect;
    pl_status st = dae_resolve(c, inst, "url", "effect", &effect);
    material m = material_make(rgb_gray(0.5f), rgb_gray(0.0f));
    snprintf(m.name, sizeof m.name, "%s", entry->id);
    if (!st) st = read_common(c, effect->node, &m);
    const xmlNode *cgl = st ? NULL : cgl_technique(effect->node);
    if (cgl) st = read_cgl(c, cgl, &m);
    if (st) return st;
    entry->material = scene_add_material(c->out, m);
    if (entry->material < 0) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    *out = entry->material;
    return PL_OK;
}

pl_status dae_bind_materials(dae_ctx *c, const xmlNode *inst, dae_binding **out, int *count)
{
    *out = NULL;
    *count = 0;
    /* Count first, then fill: one allocation of exactly the bindings the instance declares. */
    const xmlNode *common = dae_child(dae_child(inst, "bind_material"), "technique_common");
    int n = 0;
    for (const xmlNode *im = dae_first(common); im; im = dae_next(im)) n += dae_is(im, "instance_material");
    if (n == 0) return PL_OK;
    dae_binding *b = calloc((size_t)n, sizeof *b);
    if (!b) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    int i = 0;
    pl_status st = PL_OK;
    for (const xmlNode *im = dae_first(common); im && !st; im = dae_next(im)) {
        if (!dae_is(im, "instance_material")) continue;
        b[i].symbol = dae_attr(im, "symbol");
        if (!b[i].symbol) { st = dae_error(c, im, PL_ERR_PARSE, "expected a symbol attribute"); break; }
        dae_entry *mat;
        st = dae_resolve(c, im, "target", "material", &mat);
        if (!st) {
            if (mat->material >= 0) b[i].material = mat->material;
            else st = convert_material(c, mat, &b[i].material);
        }
        i++;
    }
    if (st) { free(b); return st; }
    *out = b;
    *count = n;
    return PL_OK;
}

/* The material a primitive list's symbol names through its instance's bindings; an unbound one is
 * warned about and drawn in the default grey. */
pl_status dae_bound_material(dae_ctx *c, const xmlNode *at, const dae_binding *b, int count,
                             const char *symbol, int *out)
{
    /* No symbol: the instance's only (or first) binding is the evident intent. */
    if (!symbol && count > 0) { *out = b[0].material; return PL_OK; }
    for (int i = 0; symbol && i < count; i++)
        if (strcmp(b[i].symbol, symbol) == 0) { *out = b[i].material; return PL_OK; }
    if (symbol)
        dae_warn_once(c, at, "unbound material",
                      "material symbol '%.64s' is not bound by the <instance_geometry>; using grey 0.5", symbol);
    return dae_default_material(c, out);
}
