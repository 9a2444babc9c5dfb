/* The scene container: growable arrays and primitive numbering. */
#include "scene.h"
#include "buf.h"
#include "check.h"
#include "counters.h"
#include "envmap.h"
#include "material.h"
#include "spawn.h"
#include "../parts/part1_raygen/part1.h"  /* call sites of the parts (framework/README.md) */
#include <stdlib.h>
#include <string.h>

/* ---- owning the arrays ------------------------------------------------------------------------ */

/* NULL-safe, and the scene is left empty (every count 0), so a second free or a later use of the
 * counts is harmless. */
void scene_free(scene *s)
{
    if (!s) return;
    void *owned[] = {s->triangles, s->spheres, s->materials, s->lights};
    for (size_t i = 0; i < sizeof owned / sizeof owned[0]; i++) free(owned[i]);
    envmap_free(s->env);
    free(s->env);
    env_distribution_free(s->env_dist);
    free(s->env_dist);
    memset(s, 0, sizeof *s);
}

/* Each array grows by the framework's one growable-array helper (buf.h). */
int scene_add_material(scene *s, material m)
{
    return buf_append(&s->materials, &s->num_materials, &s->capacity.materials, sizeof m, &m);
}
int scene_add_triangle(scene *s, triangle t)
{
    return buf_append(&s->triangles, &s->num_triangles, &s->capacity.triangles, sizeof t, &t);
}
int scene_add_sphere(scene *s, sphere sp)
{
    return buf_append(&s->spheres, &s->num_spheres, &s->capacity.spheres, sizeof sp, &sp);
}
int scene_add_light(scene *s, light l)
{
    return buf_append(&s->lights, &s->num_lights, &s->capacity.lights, sizeof l, &l);
}

/* ---- building the parts of a scene by code (the loader and the tests) ------------------------- */

/* A diffuse material of albedo (reflectance) and Le (emitted radiance); every other field zero. */
material material_make(rgb albedo, rgb Le)
{
    material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_DIFFUSE;
    m.albedo = albedo;
    m.Le = Le;
    /* The other kinds' parameters at CS184's defaults, so every material holds valid ones. */
    m.reflectance = m.transmittance = rgb_gray(1.0f);
    m.ior = 1.5f;
    m.alpha = 0.5f;
    m.eta = rgb_gray(1.5f);
    m.k = rgb_gray(0.0f);
    return m;
}

/* A flat triangle: its face normal, by the right-hand rule on p0 p1 p2, at all three corners
 * (meshes with their own normals fill n0..n2 themselves). */
triangle triangle_make(vec3 p0, vec3 p1, vec3 p2, int mat)
{
    vec3 n = vec3_normalize(vec3_cross(vec3_sub(p1, p0), vec3_sub(p2, p0)));
    triangle t = {p0, p1, p2, n, n, n, mat};
    return t;
}

/* ---- primitives by number: triangles first, then spheres ---------------------------------------- */

/* One numbering for both kinds, so a BVH stores plain ints and part 2 never asks which kind. */
aabb scene_prim_bounds(const scene *s, int prim)
{
    if (prim < s->num_triangles) {
        const triangle *t = &s->triangles[prim];
        return aabb_extend(aabb_extend(aabb_extend(aabb_empty(), t->p0), t->p1), t->p2);
    }
    const sphere *sp = &s->spheres[prim - s->num_triangles];
    vec3 r = vec3_make(sp->radius, sp->radius, sp->radius);
    aabb b = {vec3_sub(sp->center, r), vec3_add(sp->center, r)};
    return b;
}

vec3 scene_prim_centroid(const scene *s, int prim) { return aabb_centroid(scene_prim_bounds(s, prim)); }

aabb scene_bounds(const scene *s)
{
    aabb b = aabb_empty();
    for (int i = 0; i < scene_prim_count(s); i++) b = aabb_union(b, scene_prim_bounds(s, i));
    return b;
}

bool scene_prim_intersect(const scene *s, int prim, ray *r, hit *h)
{
    PL_CHECK(prim >= 0 && prim < scene_prim_count(s));
    /* Counted here, whatever the caller: part 2's work per ray is the framework's figure. */
    counters_add_prim(prim);
    bool found;
    int mat;
    if (prim < s->num_triangles) {
        found = triangle_intersect(&s->triangles[prim], r, h);
        mat = s->triangles[prim].material;
    } else {
        const sphere *sp = &s->spheres[prim - s->num_triangles];
        found = sphere_intersect(sp, r, h);
        mat = sp->material;
    }
    /* Part 1's intersection functions fill the hit's geometry; which primitive and material it was
     * is the framework's to record. */
    if (found) {
        h->prim = prim;
        h->material = mat;
    }
    return found;
}

void scene_hit_finish(const scene *s, const tri_frame *frames, const ray *r, hit *h)
{
    /* The point and its error bound from part 1's t or barycentrics, so that rays leave every
     * surface the same way whatever part 1 computed (spawn.h). */
    if (h->prim < s->num_triangles) {
        const triangle *t = &s->triangles[h->prim];
        tri_frame own;
        if (!frames) own = tri_frame_make(t);
        hit_refine_triangle(t, frames ? &frames[h->prim] : &own, h);
    } else {
        hit_refine_sphere(&s->spheres[h->prim - s->num_triangles], r, h);
    }
    /* Glass keeps its outward normal in the shading frame, so its BSDF can tell in from out. */
    h->transmits = material_has_inside(&s->materials[h->material]);
}
