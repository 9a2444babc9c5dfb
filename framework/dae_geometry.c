/* COLLADA loader: geometry. Meshes (every <triangles>, <polylist> and <polygons> list, polygons
 * fan-triangulated, the file's normals when present) and CS184's CGL spheres. */
#include "dae_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A view of a <source>'s float array: element i is data[i * stride .. i * stride + 2]. */
typedef struct {
    const float *data;
    int count;   /* elements */
    int stride;  /* floats per element, >= 3 */
    const xmlNode *source;
} accessor;

/* One primitive list's inputs: where each per-corner index sits in <p>. */
typedef struct {
    accessor positions, normals;
    int position_offset, normal_offset;  /* normal_offset -1: no normals */
    bool normals_from_vertices;          /* NORMAL given in <vertices>: indexed like positions */
    int stride;                          /* indices per corner: max offset + 1 */
    vec3 *world_p, *world_n;             /* every position and normal in world space, transformed once
                                            per list (not once per corner); a NaN x marks a normal to skip */
} inputs;

/* The instance being converted: its transforms and material bindings. */
typedef struct {
    mat4 to_world;
    mat4 normal_to_world;  /* inverse transpose of to_world */
    bool mirrored;         /* det < 0: swap winding so the front stays the front */
    const dae_binding *bindings;
    int num_bindings;
    const xmlNode *elem;   /* the <instance_geometry>, named in errors about what it produced */
} instance;

/* ---- sources ----------------------------------------------------------------------------- */

/* The numbers of a <float_array>, read once per source and kept in its index entry (a source
 * shared by several lists is parsed once); exactly `count` of them, or a located error. */
static pl_status read_float_array(dae_ctx *c, dae_entry *entry, const xmlNode *array)
{
    int declared;
    pl_status st = dae_attr_int(c, array, "count", true, 0, 0, &declared);
    if (!st) st = dae_float_list(c, array, declared, &entry->floats, &entry->num_floats);
    if (!st && entry->num_floats > declared)
        st = dae_error(c, array, PL_ERR_PARSE, "expected %d numbers (count), found more", declared);
    else if (!st && entry->num_floats != declared)
        st = dae_error(c, array, PL_ERR_PARSE, "expected %d numbers (count), found %d", declared,
                       entry->num_floats);
    if (st) {
        free(entry->floats);
        entry->floats = NULL;
        entry->num_floats = 0;
    }
    return st;
}

/* Reads the <source> named by attribute attr of at as 3-vectors (positions or normals). */
static pl_status read_source(dae_ctx *c, const xmlNode *at, const char *attr, const char *semantic,
                             accessor *out)
{
    dae_entry *entry;
    pl_status st = dae_resolve(c, at, attr, "source", &entry);
    if (st) return st;
    const xmlNode *source = entry->node;
    const xmlNode *array = dae_child(source, "float_array");
    if (!array) return dae_error(c, source, PL_ERR_PARSE, "expected a <float_array> for %s", semantic);
    if (!entry->floats && (st = read_float_array(c, entry, array))) return st;

    const xmlNode *acc = dae_child(dae_child(source, "technique_common"), "accessor");
    if (!acc) return dae_error(c, source, PL_ERR_PARSE, "expected <technique_common><accessor>");
    int count, stride, offset;
    if ((st = dae_attr_int(c, acc, "count", true, 0, 0, &count))) return st;
    if ((st = dae_attr_int(c, acc, "stride", false, 1, 1, &stride))) return st;
    if ((st = dae_attr_int(c, acc, "offset", false, 0, 0, &offset))) return st;
    if (stride < 3)
        return dae_error(c, acc, PL_ERR_PARSE, "expected stride >= 3 for %s (x y z), found %d", semantic, stride);
    /* In 64 bits: a hostile count times stride must not wrap. */
    long long needed = count > 0 ? (long long)offset + (long long)(count - 1) * stride + 3 : 0;
    if (needed > entry->num_floats)
        return dae_error(c, acc, PL_ERR_PARSE, "count %d x stride %d needs %lld numbers, the <float_array> has %d",
                         count, stride, needed, entry->num_floats);
    out->data = entry->floats ? entry->floats + offset : NULL;
    out->count = count;
    out->stride = stride;
    out->source = source;
    return PL_OK;
}

/* Element i of a source: its first three floats (extra components, e.g. a w, are ignored). */
static vec3 element(const accessor *a, int i)
{
    const float *p = a->data + (size_t)i * (size_t)a->stride;
    return vec3_make(p[0], p[1], p[2]);
}

/* ---- inputs ------------------------------------------------------------------------------ */

/* A VERTEX input points at <vertices>, which names the POSITION source (and may add NORMAL, then
 * indexed with the positions). */
static pl_status read_vertices(dae_ctx *c, const xmlNode *input, inputs *in)
{
    dae_entry *vertices;
    pl_status st = dae_resolve(c, input, "source", "vertices", &vertices);
    bool have_position = false;
    for (const xmlNode *v = dae_first(vertices ? vertices->node : NULL); v && !st; v = dae_next(v)) {
        const char *semantic = dae_attr(v, "semantic");
        if (!dae_is(v, "input") || !semantic) continue;
        if (strcmp(semantic, "POSITION") == 0) {
            st = read_source(c, v, "source", "POSITION", &in->positions);
            have_position = true;
        } else if (strcmp(semantic, "NORMAL") == 0) {
            st = read_source(c, v, "source", "NORMAL", &in->normals);
            in->normals_from_vertices = true;
        }
    }
    if (!st && !have_position)
        st = dae_error(c, vertices->node, PL_ERR_PARSE, "expected an <input semantic=\"POSITION\">");
    return st;
}

/* A primitive list's <input>s: which offset in each corner's run of indices is the vertex and
 * which the normal; other semantics (TEXCOORD, COLOR) only widen the run. */
static pl_status read_inputs(dae_ctx *c, const xmlNode *prim, inputs *in)
{
    memset(in, 0, sizeof *in);
    in->position_offset = -1;
    in->normal_offset = -1;
    int max_offset = 0;
    pl_status st = PL_OK;
    for (const xmlNode *i = dae_first(prim); i && !st; i = dae_next(i)) {
        if (!dae_is(i, "input")) continue;
        const char *semantic = dae_attr(i, "semantic");
        int offset;
        if (!semantic) return dae_error(c, i, PL_ERR_PARSE, "expected a semantic attribute");
        if ((st = dae_attr_int(c, i, "offset", true, 0, 0, &offset))) return st;
        if (offset > 1000) return dae_error(c, i, PL_ERR_PARSE, "expected an offset below 1000, found %d", offset);
        if (offset > max_offset) max_offset = offset;
        if (strcmp(semantic, "VERTEX") == 0 && in->position_offset < 0) {
            in->position_offset = offset;
            st = read_vertices(c, i, in);
        } else if (strcmp(semantic, "NORMAL") == 0 && in->normal_offset < 0) {
            in->normal_offset = offset;
            st = read_source(c, i, "source", "NORMAL", &in->normals);
        }
    }
    if (!st && in->position_offset < 0)
        st = dae_error(c, prim, PL_ERR_PARSE, "expected an <input semantic=\"VERTEX\">");
    if (in->normal_offset < 0 && in->normals_from_vertices) in->normal_offset = in->position_offset;
    in->stride = max_offset + 1;
    return st;
}

/* ---- polygons ---------------------------------------------------------------------------- */

/* One corner, transformed to world space; has_normal false when the file gives none. */
typedef struct { vec3 p, n; bool has_normal; } corner;

/* Every index is checked against its source before use: a hostile file gets an error, not a read
 * past the array. */
static pl_status read_corner(dae_ctx *c, const xmlNode *p, const inputs *in, const int *idx, corner *out)
{
    int v = idx[in->position_offset];
    if (v >= in->positions.count)
        return dae_error(c, p, PL_ERR_PARSE, "VERTEX index %d is out of range (the positions have %d entr%s)",
                         v, in->positions.count, in->positions.count == 1 ? "y" : "ies");
    out->p = in->world_p[v];
    out->has_normal = false;
    if (in->normal_offset >= 0) {
        int n = idx[in->normal_offset];
        if (n >= in->normals.count)
            return dae_error(c, p, PL_ERR_PARSE, "NORMAL index %d is out of range (the normals have %d entr%s)",
                             n, in->normals.count, in->normals.count == 1 ? "y" : "ies");
        out->n = in->world_n[n];
        out->has_normal = !isnan(out->n.x);
    }
    return PL_OK;
}

/* Transforms the list's positions and normals to world space once: a vertex is shared by about six
 * triangles, so this is a sixth of the work of transforming every corner. Every position is
 * checked against the coordinate bound here. */
static pl_status transform_inputs(dae_ctx *c, inputs *in, const instance *inst)
{
    in->world_p = malloc(((size_t)in->positions.count + 1) * sizeof *in->world_p);
    in->world_n = malloc(((size_t)in->normals.count + 1) * sizeof *in->world_n);
    if (!in->world_p || !in->world_n) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    for (int i = 0; i < in->positions.count; i++) {
        in->world_p[i] = mat4_point(inst->to_world, element(&in->positions, i));
        pl_status st = dae_check_coord(c, inst->elem, "a vertex", in->world_p[i]);
        if (st) return st;
    }
    for (int i = 0; i < in->normals.count; i++) {
        vec3 n = vec3_normalize(mat4_dir(inst->normal_to_world, element(&in->normals, i)));
        /* A zero or broken normal is skipped: the triangle's face normal stands in for it. */
        in->world_n[i] = vec3_is_finite(n) && vec3_length(n) > 0.5f ? n : vec3_make(NAN, 0, 0);
    }
    return PL_OK;
}

/* One triangle into the scene; the file's normals replace the face normal at the corners that
 * have one. */
static pl_status add_triangle(dae_ctx *c, const instance *inst, corner a, corner b, corner d, int mat)
{
    if (inst->mirrored) { corner t = b; b = d; d = t; }
    triangle t = triangle_make(a.p, b.p, d.p, mat);
    if (a.has_normal) t.n0 = a.n;
    if (b.has_normal) t.n1 = b.n;
    if (d.has_normal) t.n2 = d.n;
    if (scene_add_triangle(c->out, t) < 0) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return PL_OK;
}

/* Fan-triangulates one polygon of n corners whose indices start at idx. */
static pl_status add_polygon(dae_ctx *c, const xmlNode *p, const inputs *in, const instance *inst,
                             const int *idx, int n, int mat)
{
    corner first, prev, cur;
    pl_status st = read_corner(c, p, in, idx, &first);
    if (!st) st = read_corner(c, p, in, idx + in->stride, &prev);
    for (int k = 2; k < n && !st; k++) {
        st = read_corner(c, p, in, idx + (size_t)k * (size_t)in->stride, &cur);
        if (!st) st = add_triangle(c, inst, first, prev, cur, mat);
        prev = cur;
    }
    return st;
}

/* <triangles> and <polylist>: one <p> for the whole list; vcount (polylist) or 3 corners each. */
static pl_status read_list(dae_ctx *c, const xmlNode *prim, const inputs *in, const instance *inst,
                           int count, int mat)
{
    const xmlNode *p = dae_child(prim, "p");
    int *vcount = NULL, *idx = NULL, num_vcount = count, num_idx = 0;
    pl_status st = PL_OK;
    bool polylist = dae_is(prim, "polylist");
    /* A polylist's vcount: one corner count per polygon, each at least 3, exactly `count` of them. */
    if (polylist) {
        const xmlNode *vc = dae_child(prim, "vcount");
        if (!vc && count > 0) return dae_error(c, prim, PL_ERR_PARSE, "expected a <vcount> (count is %d)", count);
        if (vc) st = dae_int_list(c, vc, count, &vcount, &num_vcount);
        if (!st && num_vcount > count)
            st = dae_error(c, prim, PL_ERR_PARSE, "vcount has more entries than count says (%d)", count);
        else if (!st && num_vcount != count)
            st = dae_error(c, prim, PL_ERR_PARSE, "vcount has %d entr%s, count says %d", num_vcount,
                           num_vcount == 1 ? "y" : "ies", count);
        for (int i = 0; i < num_vcount && !st; i++)
            if (vcount[i] < 3)
                st = dae_error(c, vc, PL_ERR_PARSE, "polygon %d has %d vertices: expected at least 3", i, vcount[i]);
    }
    /* The corners fix how many indices <p> must hold, and the triangles the scene must have room for. */
    long long corners = 0;
    for (int i = 0; i < count && !st; i++) corners += polylist ? vcount[i] : 3;
    if (!st) st = dae_check_room(c, inst->elem, (long)(corners - 2LL * count));  /* n - 2 triangles per polygon */
    if (!st && corners > 0 && !p) st = dae_error(c, prim, PL_ERR_PARSE, "expected a <p> with the indices");
    long long want = corners * in->stride;
    if (!st && p) st = dae_int_list(c, p, want < INT_MAX ? (int)want : INT_MAX, &idx, &num_idx);
    if (!st && num_idx > want)
        st = dae_error(c, p, PL_ERR_PARSE, "expected %lld indices (%lld corners x %d inputs), found more", want,
                       corners, in->stride);
    else if (!st && num_idx != want)
        st = dae_error(c, p ? p : prim, PL_ERR_PARSE, "expected %lld indices (%lld corners x %d inputs), found %d",
                       want, corners, in->stride, num_idx);
    /* Then the polygons, each a run of n corners in <p>. */
    size_t at = 0;
    for (int i = 0; i < count && !st; i++) {
        int n = polylist ? vcount[i] : 3;
        st = add_polygon(c, p, in, inst, idx + at, n, mat);
        at += (size_t)n * (size_t)in->stride;
    }
    free(vcount);
    free(idx);
    return st;
}

/* <polygons>: one <p> per polygon; a <ph> (polygon with holes) keeps its outline, with a warning. */
static pl_status read_polygons(dae_ctx *c, const xmlNode *prim, const inputs *in, const instance *inst,
                               int count, int mat)
{
    int found = 0;
    pl_status st = PL_OK;
    for (const xmlNode *e = dae_first(prim); e && !st; e = dae_next(e)) {
        const xmlNode *p = e;
        if (dae_is(e, "ph")) {
            dae_warn_once(c, e, "ph", "holes in <polygons> (<ph>) are not supported; the outline is filled");
            p = dae_child(e, "p");
            if (!p) { st = dae_error(c, e, PL_ERR_PARSE, "expected a <p> outline"); break; }
        } else if (!dae_is(e, "p")) {
            continue;
        }
        int *idx, n;
        if ((st = dae_int_list(c, p, -1, &idx, &n))) break;
        if (n % in->stride != 0 || n / in->stride < 3)
            st = dae_error(c, p, PL_ERR_PARSE, "expected at least 3 corners of %d indices each, found %d indices",
                           in->stride, n);
        if (!st) st = dae_check_room(c, inst->elem, n / in->stride - 2);
        if (!st) st = add_polygon(c, p, in, inst, idx, n / in->stride, mat);
        free(idx);
        found++;
    }
    if (!st && found != count)
        st = dae_error(c, prim, PL_ERR_PARSE, "count says %d polygons, found %d <p>", count, found);
    return st;
}

/* One <triangles>, <polylist> or <polygons>: its inputs, its material, its world-space vertices,
 * then its polygons. */
static pl_status read_primitive(dae_ctx *c, const xmlNode *prim, const instance *inst)
{
    int count, mat;
    inputs in = {0};  /* freed below on every path, even before read_inputs fills it */
    pl_status st = dae_attr_int(c, prim, "count", true, 0, 0, &count);
    if (!st) st = read_inputs(c, prim, &in);
    if (!st) st = dae_bound_material(c, prim, inst->bindings, inst->num_bindings, dae_attr(prim, "material"), &mat);
    if (!st) st = transform_inputs(c, &in, inst);
    if (!st)
        st = dae_is(prim, "polygons") ? read_polygons(c, prim, &in, inst, count, mat)
                                      : read_list(c, prim, &in, inst, count, mat);
    free(in.world_p);
    free(in.world_n);
    return st;
}

/* Every surface list of a mesh; lines and strips draw nothing a path tracer can hit, so they are
 * warned about and skipped. */
static pl_status read_mesh(dae_ctx *c, const xmlNode *mesh, const instance *inst)
{
    pl_status st = PL_OK;
    for (const xmlNode *e = dae_first(mesh); e && !st; e = dae_next(e)) {
        if (dae_is(e, "triangles") || dae_is(e, "polylist") || dae_is(e, "polygons"))
            st = read_primitive(c, e, inst);
        else if (dae_is(e, "lines") || dae_is(e, "linestrips") || dae_is(e, "trifans") || dae_is(e, "tristrips"))
            dae_warn_once(c, e, dae_name(e), "<%s> primitives are not supported; skipped", dae_name(e));
    }
    return st;
}

/* ---- spheres ----------------------------------------------------------------------------- */

static pl_status read_sphere(dae_ctx *c, const xmlNode *shape, const instance *inst)
{
    float radius;
    const xmlNode *r = dae_child(shape, "radius");
    if (!r) return dae_error(c, shape, PL_ERR_PARSE, "expected a <radius>");
    pl_status st = dae_floats(c, r, &radius, 1, 0, NULL);
    if (st) return st;
    if (!(radius > 0)) return dae_error(c, r, PL_ERR_INVALID, "expected a radius > 0, found %g", radius);
    /* Uniform scale assumed (as CS184): the mean axis length stands for it. */
    mat4 m = inst->to_world;
    float sx = vec3_length(mat4_dir(m, vec3_make(1, 0, 0)));
    float sy = vec3_length(mat4_dir(m, vec3_make(0, 1, 0)));
    float sz = vec3_length(mat4_dir(m, vec3_make(0, 0, 1)));
    float scale = (sx + sy + sz) / 3.0f;
    if (fabsf(sx - sy) > 1e-3f * scale || fabsf(sy - sz) > 1e-3f * scale)
        dae_warn_once(c, shape, "non-uniform sphere", "a sphere under a non-uniform scale stays round (mean scale)");
    sphere sp;
    sp.center = mat4_point(m, vec3_make(0, 0, 0));
    sp.radius = radius * scale;
    if (!(sp.radius > 0) || !(sp.radius <= DAE_MAX_COORD))
        return dae_error(c, inst->elem, PL_ERR_INVALID,
                         "the node's transform scales the sphere to radius %g: expected (0, %g]", sp.radius, DAE_MAX_COORD);
    st = dae_check_coord(c, inst->elem, "the sphere's centre", sp.center);
    if (!st) st = dae_check_room(c, inst->elem, 1);
    if (st) return st;
    st = dae_bound_material(c, shape, inst->bindings, inst->num_bindings, NULL, &sp.material);
    if (!st && scene_add_sphere(c->out, sp) < 0) st = pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return st;
}

/* ---- instances --------------------------------------------------------------------------- */

/* The determinant of the linear part: negative when the transform mirrors (a scale by -1). */
static float det3(mat4 a)
{
    float (*m)[4] = a.m;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

pl_status dae_instance_geometry(dae_ctx *c, const xmlNode *inst_elem, mat4 to_world)
{
    dae_entry *geometry;
    pl_status st = dae_resolve(c, inst_elem, "url", "geometry", &geometry);
    if (st) return st;
    instance inst;
    inst.to_world = to_world;
    mat4 inv;
    /* A singular transform flattens the mesh; its normals then follow the matrix itself. */
    inst.normal_to_world = mat4_inverse(to_world, &inv) ? mat4_transpose(inv) : to_world;
    inst.mirrored = det3(to_world) < 0;
    inst.elem = inst_elem;
    dae_binding *bindings;
    if ((st = dae_bind_materials(c, inst_elem, &bindings, &inst.num_bindings))) return st;
    inst.bindings = bindings;

    const xmlNode *cgl = dae_cgl_technique(geometry->node);
    const xmlNode *shape = dae_child(cgl, "sphere");
    const xmlNode *mesh = dae_child(geometry->node, "mesh");
    if (shape) st = read_sphere(c, shape, &inst);
    else if (mesh) st = read_mesh(c, mesh, &inst);
    else
        dae_warn_once(c, geometry->node, "geometry kind",
                      "only <mesh> and CGL sphere geometry are supported; '%.64s' skipped", geometry->id);
    free(bindings);
    return st;
}
