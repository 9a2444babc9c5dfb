/* The scene: everything a render reads, in world space (Y up, metres), built by the COLLADA loader
 * (dae.h) or by code (tests). A scene owns all its arrays; scene_free releases them.
 *
 * Primitives are numbered 0 .. scene_prim_count() - 1: first the triangles, then the spheres.
 * The BVH and the linear scan both work on these indices.
 * Parts may not call: scene_free, scene_hit_finish, scene_add_material, scene_add_triangle,
 * scene_add_sphere, scene_add_light, material_make, triangle_make (the grader refuses them; the functions
 * marked PL_PART_API are theirs). */
#ifndef PL_SCENE_H
#define PL_SCENE_H

#include "part_api.h"

#include <stdbool.h>
#include <stdint.h>
#include "vec.h"
#include "mat4.h"
#include "aabb.h"
#include "ray.h"
#include "camera.h"

struct envmap;
struct env_distribution;

/* What the file asked for. Parts 1-5 shade every material as diffuse + emission; the others load
 * (with one warning) so course scenes that use them still render. */
typedef enum {
    MATERIAL_DIFFUSE = 0,
    MATERIAL_MIRROR,
    MATERIAL_GLASS,
    MATERIAL_REFRACTION,
    MATERIAL_MICROFACET
} material_kind;

typedef struct {
    material_kind kind;  /* what the file declared; shading treats all kinds as diffuse */
    rgb albedo;          /* diffuse reflectance in [0,1] per channel (grey 0.5 when unspecified);
                            for the other kinds, the colour their diffuse stand-in shades with */
    rgb Le;              /* emitted radiance (W / (sr m^2)); black for non-emitters */
    /* What the other kinds hold, read as CS184 reads its <mirror>, <glass>, <refraction> and
     * <microfacet> elements, for the parts that shade them: */
    rgb reflectance;     /* mirror, glass: tint of the reflected light (1 when unspecified) */
    rgb transmittance;   /* glass, refraction: tint of the transmitted light (1 when unspecified) */
    float ior;           /* glass, refraction: index of refraction inside, > 0 (1.5); outside is 1 */
    float alpha;         /* microfacet: the Beckmann distribution's roughness, > 0 (0.5) */
    rgb eta, k;          /* microfacet: the conductor's complex index of refraction eta + i k,
                            per channel (1.5 and 0 when unspecified) */
    char name[64];       /* the file's material id, for messages */
} material;

typedef struct {
    vec3 p0, p1, p2;  /* vertices, world space, counter-clockwise seen from the front */
    vec3 n0, n1, n2;  /* unit vertex normals, world space (the face normal when the file has none) */
    int material;     /* index into scene.materials */
} triangle;

typedef struct {
    vec3 center;   /* world space */
    float radius;  /* metres, > 0 */
    int material;  /* index into scene.materials */
} sphere;

typedef enum {
    LIGHT_POINT = 0,    /* isotropic point: radiance = intensity (W/sr) */
    LIGHT_DIRECTIONAL,  /* at infinity: radiance = irradiance on a surface facing it (W/m^2) */
    LIGHT_SPOT,         /* point with a cone: intensity on the axis, falloff outside */
    LIGHT_AREA,         /* CGL parallelogram, one-sided: radiance = emitted radiance */
    LIGHT_AMBIENT,      /* CS184: uniform radiance from the whole upper hemisphere (world +Y) */
    LIGHT_ENVIRONMENT   /* -e's map, at infinity in every direction: radiance per texel (envmap.h) */
} light_kind;

typedef struct light {
    light_kind kind;
    rgb radiance;          /* see light_kind for the unit of each kind */
    vec3 position;         /* point, spot: position; area: centre */
    vec3 direction;        /* directional: direction the light travels; spot: cone axis (unit);
                              area: the side it emits towards (unit normal) */
    vec3 edge_u, edge_v;   /* area: full edge vectors; corners are position +- edge_u/2 +- edge_v/2 */
    float area;            /* area: |edge_u x edge_v| in m^2 */
    float attenuation[3];  /* point, spot: constant, linear, quadratic (COLLADA); 1,0,0 = none */
    float falloff_deg;     /* spot: half-angle of the cone in degrees */
    float falloff_exp;     /* spot: exponent of the cos falloff inside the cone */
    float leave_base;      /* area: how far short of it a shadow ray ends, along direction:   */
    float leave_per_m;     /*   leave_base + leave_per_m * distance (light_make_area, spawn.h) */
    /* environment: the map, and part 8's tables for importance sampling it (NULL: the map is
     * sampled uniformly, --env-uniform); both the scene's */
    const struct envmap *env;
    const struct env_distribution *env_dist;
} light;

typedef struct scene {
    triangle *triangles; int num_triangles;
    sphere *spheres;     int num_spheres;
    material *materials; int num_materials;
    light *lights;       int num_lights;
    struct { int triangles, spheres, materials, lights; } capacity;  /* room allocated (scene_add_*) */
    camera camera;       /* the file's (camera.h), or a -c settings file's */
    bool has_camera;     /* false: camera_default_framing frames the bounds */
    bool course_profile; /* the file is in CS184's course profile (dae.h): by default its camera is
                            framed as CS184's application frames it (camera_uses_cs184_framing) */
    int visible_lights;  /* area lights the loader made visible geometry (visible_light.h): each
                            added an emitter material and two triangles after the file's own */
    char path[512];      /* the file it came from ("" for code-built scenes) */
    /* Where the render's (0, 0, 0) is in the file's coordinates. Every position above is stored
     * relative to it (dae.c takes the position of the file's camera, in double), so a scene far from
     * its file's origin renders with the precision of one at it: float has 1/16 m steps at 10^6 m.
     * Add it back to report a position in the file's coordinates (the trace does). */
    double origin[3];
    /* -e's environment map (envmap.h), owned; NULL for none. Rays that leave the scene see it, and
     * in a course with part 8 it is also a light (LIGHT_ENVIRONMENT) whose importance-sampling
     * tables env_dist holds (owned; NULL when the map is sampled uniformly). */
    struct envmap *env;
    struct env_distribution *env_dist;
} scene;

/* Releases the arrays and zeroes s. NULL-safe. */
void scene_free(scene *s);

static inline int scene_prim_count(const scene *s) { return s->num_triangles + s->num_spheres; }
PL_PART_API aabb scene_prim_bounds(const scene *s, int prim);
PL_PART_API vec3 scene_prim_centroid(const scene *s, int prim);
PL_PART_API aabb scene_bounds(const scene *s);

/* Intersects one primitive through part 1's triangle_intersect / sphere_intersect, setting
 * h->prim and h->material on a hit. Shrinks r->max_t on a hit, like them. Every call counts as one
 * primitive test on the calling thread: the framework's count (counters.h), which a traversal
 * cannot report for itself. Traversals test primitives only through this function. */
PL_PART_API bool scene_prim_intersect(const scene *s, int prim, ray *r, hit *h);

/* Fills the framework's part of a hit r made on h->prim: the point and its error bound (h->p,
 * h->p_err, h->ng: spawn.h), from part 1's t or barycentrics. accel_intersect calls it once for
 * the closest hit of every query (not for each candidate a traversal passes), so every hit a
 * part gets from render_intersect has them. frames: one tri_frame per triangle (accel_build
 * makes them), or NULL to compute the hit triangle's on the spot. */
struct tri_frame;
void scene_hit_finish(const scene *s, const struct tri_frame *frames, const ray *r, hit *h);

/* Appending, for loaders and tests. Each returns the new element's index, or -1 without memory. */
int scene_add_material(scene *s, material m);
int scene_add_triangle(scene *s, triangle t);
int scene_add_sphere(scene *s, sphere sp);
int scene_add_light(scene *s, light l);

/* A diffuse material with the given reflectance and emission (the other kinds' parameters at
 * their defaults). */
material material_make(rgb albedo, rgb Le);
/* A triangle with its face normal at all three vertices. */
triangle triangle_make(vec3 p0, vec3 p1, vec3 p2, int mat);

#endif
