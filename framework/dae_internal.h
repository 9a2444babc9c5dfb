/* Shared by the COLLADA loader's modules (dae*.c) and nothing else: the parse context, the id
 * index, located errors and warnings, and number lists read from element text.
 *
 *   dae.c           entry points, document checks, up axis, the node tree and its transforms
 *   dae_xml.c       element helpers, the id index, numbers, errors and once-per-kind warnings
 *   dae_geometry.c  meshes (<triangles>, <polylist>, <polygons>) and CGL spheres
 *   dae_material.c  material binding and the effect -> material translation
 *   dae_light.c     lights (and the area lights made visible geometry) and the camera
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_DAE_INTERNAL_H
#define PL_DAE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <libxml/tree.h>
#include "dae.h"
#include "scene.h"
#include "status.h"

/* One element with an id. Ids are unique per element name (a <node> and a <camera> may share one,
 * as some exporters write). The slots cache what was derived from the element, so each element is
 * converted once however often it is referenced. */
typedef struct {
    const char *id;    /* points into the document */
    xmlNode *node;     /* NULL: empty slot */
    int material;      /* <material>: its index in scene.materials, -1 until converted */
    float *floats;     /* <source>: its parsed <float_array>, NULL until read */
    int num_floats;
} dae_entry;

typedef struct {
    dae_entry *slots;  /* open addressing, capacity a power of two, at most half full */
    size_t capacity;
} dae_index;

#define DAE_MAX_WARN_KINDS 64

/* A node's transform to the world: its linear part in float (rotations and scales need no more) and
 * its translation in double, so that a scene 10^6 m from the file's origin keeps its millimetres
 * until the scene's origin (scene.origin) is taken off (dae.c). */
typedef struct {
    mat4 linear;           /* the translation column is zero */
    double t[3];
} dae_xform;

typedef struct {
    const char *name;      /* the file name used in messages */
    pl_diag *diag;         /* never NULL inside the loader */
    xmlDoc *doc;
    dae_index index;
    scene *out;
    mat4 up;               /* file axes -> pathlab's Y-up world, applied before every node */
    bool finding_origin;   /* the first pass: only the first camera's position is wanted (dae.c) */
    bool origin_found;
    int default_material;  /* grey 0.5, created on first use; -1 before */
    bool has_camera;
    long node_visits;      /* bounds the work <instance_node> chains can cause */
    dae_limits limits;     /* primitives and instances the scene may ask for */
    const xmlNode **light_nodes;  /* the <instance_light> of each scene light, for located messages */
    int num_light_nodes, light_nodes_cap;
    const char *warned[DAE_MAX_WARN_KINDS];  /* kinds already warned about (string literals or names in doc) */
    int num_warned;
} dae_ctx;

/* ---- elements ---------------------------------------------------------------------------- */
bool dae_is(const xmlNode *n, const char *name);
const char *dae_name(const xmlNode *n);
xmlNode *dae_first(const xmlNode *parent);          /* first element child, or NULL */
xmlNode *dae_next(const xmlNode *n);                /* next element sibling, or NULL */
xmlNode *dae_child(const xmlNode *parent, const char *name);
/* An attribute's value without copying (it lives as long as the document), or NULL. */
const char *dae_attr(const xmlNode *n, const char *name);
long dae_line(const xmlNode *n);
/* The <technique profile="CGL"> of an <extra> child of parent, or NULL. */
xmlNode *dae_cgl_technique(const xmlNode *parent);

/* ---- messages ---------------------------------------------------------------------------- */
/* "name:line: <element>: <message>" in the diag; returns status. */
pl_status dae_error(dae_ctx *c, const xmlNode *at, pl_status status, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Warns "name:line: <element>: <message>" unless a warning of this kind was already given. */
void dae_warn_once(dae_ctx *c, const xmlNode *at, const char *kind, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* ---- ids --------------------------------------------------------------------------------- */
pl_status dae_index_build(dae_ctx *c);
void dae_index_free(dae_index *ix);
dae_entry *dae_index_find(const dae_index *ix, const char *id, const char *element);
/* Follows the reference in attribute attr of at ("#id") to an element named element. */
pl_status dae_resolve(dae_ctx *c, const xmlNode *at, const char *attr, const char *element,
                      dae_entry **out);

/* ---- numbers ----------------------------------------------------------------------------- */
/* Reads exactly want numbers (or, when want_alt > 0, want_alt of them) from n's text, and never
 * more than one past the larger: "found more" then. found gets how many were read (may be NULL). */
pl_status dae_floats(dae_ctx *c, const xmlNode *n, float *out, int want, int want_alt, int *found);
/* Exactly `want` numbers in double (node transforms: a translation of 10^6 m keeps its millimetres). */
pl_status dae_doubles(dae_ctx *c, const xmlNode *n, double *out, int want);
/* Reads the numbers of n's text into a new array (caller frees, also when *count is 0). Reading
 * stops one number past max (the count the file declares; < 0: none): *count is then max + 1. */
pl_status dae_float_list(dae_ctx *c, const xmlNode *n, int max, float **out, int *count);
/* The same for non-negative integers (<p>, <vcount>). */
pl_status dae_int_list(dae_ctx *c, const xmlNode *n, int max, int **out, int *count);
/* One float from the text of parent's child `name`; def when the child is absent. */
pl_status dae_child_float(dae_ctx *c, const xmlNode *parent, const char *name, float def, float *out);
/* An integer attribute >= min; def when absent (required: absence is an error). */
pl_status dae_attr_int(dae_ctx *c, const xmlNode *n, const char *name, bool required, int def,
                       int min, int *out);
/* A colour: 3 or 4 non-negative numbers (alpha ignored). */
pl_status dae_color(dae_ctx *c, const xmlNode *n, rgb *out);
/* The colour in parent's child `name`: its text, or its <color> child. */
pl_status dae_child_color(dae_ctx *c, const xmlNode *parent, const char *name, bool required, rgb *out);

/* A point or length after its node transforms: finite and within +-DAE_MAX_COORD, else a located
 * error at `at` (the <instance_geometry> whose transform produced it) naming what. */
pl_status dae_check_coord(dae_ctx *c, const xmlNode *at, const char *what, vec3 p);
/* Room for `more` primitives within the limit, else a located error at `at`. */
pl_status dae_check_room(dae_ctx *c, const xmlNode *at, long more);

/* ---- converters, one per module ---------------------------------------------------------- */
pl_status dae_instance_geometry(dae_ctx *c, const xmlNode *inst, mat4 to_world);
pl_status dae_instance_light(dae_ctx *c, const xmlNode *inst, mat4 to_world);
/* After the whole document: every area light no emissive mesh covers becomes visible geometry
 * (visible_light.h), in the order of the lights, with located messages. */
pl_status dae_make_lights_visible(dae_ctx *c);
/* The camera also takes its node's transform in the file's coordinates (x, before the scene's
 * origin is taken off), where CS184's framing direction is defined (camera.h's orbit_dir). */
pl_status dae_instance_camera(dae_ctx *c, const xmlNode *inst, mat4 to_world, const dae_xform *x);
/* Which camera a file's render uses: the last one for a file in the course's profile (CS184's
 * Application::load sets its camera at every camera node), the first for any other. True when the
 * camera about to be read replaces the one read before (or is the first). */
bool dae_camera_wins(const dae_ctx *c, bool seen_one);

/* Material bindings of one <instance_geometry>: symbol -> scene material index. */
typedef struct { const char *symbol; int material; } dae_binding;
pl_status dae_bind_materials(dae_ctx *c, const xmlNode *inst, dae_binding **out, int *count);
/* The material a primitive list with this symbol (NULL: none given) uses. */
pl_status dae_bound_material(dae_ctx *c, const xmlNode *at, const dae_binding *b, int count,
                             const char *symbol, int *out);
pl_status dae_default_material(dae_ctx *c, int *out);

#endif
