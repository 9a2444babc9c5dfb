/* The scene container: growable arrays, primitive numbering, and camera framing. */
#include "scene.h"
#include "counters.h"
#include "../parts/part1_raygen/part1.h"  /* call sites: framework/parts.h */
#include <stdlib.h>
#include <string.h>
#include <math.h>

void scene_free(scene *s)
{
    if (!s) return;
    free(s->triangles);
    free(s->spheres);
    free(s->materials);
    free(s->lights);
    memset(s, 0, sizeof *s);
}

/* Appends one element of size `size` to *array (count *n), doubling capacity at powers of two. */
static int append(void **array, int *n, size_t size, const void *elem)
{
    int count = *n;
    if (count == 0 || (count & (count - 1)) == 0) {  /* count is 0 or a power of two: grow */
        size_t cap = count == 0 ? 4 : (size_t)count * 2;
        void *grown = realloc(*array, cap * size);
        if (!grown) return -1;
        *array = grown;
    }
    memcpy((char *)*array + (size_t)count * size, elem, size);
    *n = count + 1;
    return count;
}

int scene_add_material(scene *s, material m) { return append((void **)&s->materials, &s->num_materials, sizeof m, &m); }
int scene_add_triangle(scene *s, triangle t) { return append((void **)&s->triangles, &s->num_triangles, sizeof t, &t); }
int scene_add_sphere(scene *s, sphere sp) { return append((void **)&s->spheres, &s->num_spheres, sizeof sp, &sp); }
int scene_add_light(scene *s, light l) { return append((void **)&s->lights, &s->num_lights, sizeof l, &l); }

material material_make(rgb albedo, rgb Le)
{
    material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_DIFFUSE;
    m.albedo = albedo;
    m.Le = Le;
    return m;
}

triangle triangle_make(vec3 p0, vec3 p1, vec3 p2, int mat)
{
    vec3 n = vec3_normalize(vec3_cross(vec3_sub(p1, p0), vec3_sub(p2, p0)));
    triangle t = {p0, p1, p2, n, n, n, mat};
    return t;
}

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
    if (found) {
        h->prim = prim;
        h->material = mat;
    }
    return found;
}


void camera_set_aspect(camera *c, float aspect)
{
    if (c->fov_is_vertical)
        c->hfov = rad_to_deg(2.0f * atanf(tanf(deg_to_rad(c->vfov) * 0.5f) * aspect));
    else
        c->vfov = rad_to_deg(2.0f * atanf(tanf(deg_to_rad(c->hfov) * 0.5f) / aspect));
}

/* Places a camera at eye looking at target with world +Y up, keeping the lens settings of base. */
static camera camera_looking(const camera *base, vec3 eye, vec3 target)
{
    camera c = *base;
    vec3 up = vec3_make(0, 1, 0);
    vec3 dir = vec3_normalize(vec3_sub(target, eye));
    if (fabsf(vec3_dot(dir, up)) > 0.999f) up = vec3_make(0, 0, 1);  /* looking straight up or down */
    c.camera_to_world = mat4_lookat(eye, target, up);
    c.position = eye;
    return c;
}

camera scene_default_camera(const scene *s)
{
    camera base;
    memset(&base, 0, sizeof base);
    base.hfov = 49.13434f;  /* CS184's Cornell box lens */
    base.vfov = 37.8f;
    base.znear = 1e-4f;
    base.zfar = 1e30f;
    base.focal_distance = 4.7f;
    aabb b = scene_bounds(s);
    if (aabb_is_empty(b)) {
        b.min = vec3_make(-1, -1, -1);
        b.max = vec3_make(1, 1, 1);
    }
    vec3 centre = aabb_centroid(b);
    float diag = vec3_length(aabb_extent(b));
    return camera_looking(&base, vec3_add(centre, vec3_make(0, 0, 1.5f * diag)), centre);
}

camera camera_cs184_framing(const camera *c, aabb bounds)
{
    /* CS184 keeps only the view direction (the camera applied to (0,0,-1)) and orbits the centre
     * of the bounds at 1.5 x their diagonal. */
    vec3 view = vec3_normalize(mat4_dir(c->camera_to_world, vec3_make(0, 0, -1)));
    vec3 centre = aabb_centroid(bounds);
    float dist = 1.5f * vec3_length(aabb_extent(bounds));
    camera out = camera_looking(c, vec3_sub(centre, vec3_scale(view, dist)), centre);
    out.znear = fminf(c->znear, dist * 1e-3f);
    out.zfar = fmaxf(c->zfar, dist * 10.0f);
    return out;
}
