/* COLLADA loader, entry points: the document, its up axis, and the node tree with its transforms.
 * Elements are converted as the visual scene instances them; see dae_internal.h for the modules. */
#include "dae.h"
#include "dae_internal.h"
#include "file.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <stdint.h>
#include <libxml/parser.h>
#include <libxml/SAX2.h>
#include <libxml/xmlerror.h>

/* Deeper than any exporter writes, shallow enough for the C stack. */
#define MAX_NODE_DEPTH 128

/* ---- XML errors -------------------------------------------------------------------------- */

typedef struct {
    dae_ctx *ctx;
    xmlParserCtxtPtr parser;
    bool failed;
} xml_errors;

/* Keeps the first error (the one worth showing) and never prints. */
static void record_xml_error(xml_errors *errs, const xmlError *e)
{
    if (errs->failed || !e || e->level < XML_ERR_ERROR) return;
    errs->failed = true;
    char msg[512];
    snprintf(msg, sizeof msg, "%s", e->message ? e->message : "malformed XML");
    size_t len = strlen(msg);
    while (len > 0 && (msg[len - 1] == '\n' || msg[len - 1] == ' ')) msg[--len] = '\0';
    for (char *ch = msg; *ch; ch++)
        if (*ch == '\n') *ch = ' ';  /* one line per message */
    /* Errors raised outside the parser (encoding conversion) carry no line: use the parser's. */
    long line = e->line > 0 ? e->line : (errs->parser && errs->parser->input ? errs->parser->input->line : 1);
    pl_fail(errs->ctx->diag, PL_ERR_PARSE, "%s:%ld: XML: %s", errs->ctx->name, line, msg);
}

/* The parser's own errors arrive here, with the parser as user data. */
static void on_parser_error(void *user, xmlErrorPtr e)
{
    xmlParserCtxtPtr parser = user;
    record_xml_error(parser->_private, e);
}

/* libxml2 reports a few errors (character encoding) through its per-thread handler instead. */
static void on_library_error(void *user, xmlErrorPtr e) { record_xml_error(user, e); }

/* Records each element's line in its _private field (free for applications): libxml2's own
 * node->line saturates at 65535, and a mesh file easily runs past that. */
static void on_start_element(void *user, const xmlChar *localname, const xmlChar *prefix, const xmlChar *uri,
                             int num_namespaces, const xmlChar **namespaces, int num_attributes,
                             int num_defaulted, const xmlChar **attributes)
{
    xmlParserCtxtPtr parser = user;
    xmlSAX2StartElementNs(user, localname, prefix, uri, num_namespaces, namespaces, num_attributes, num_defaulted,
                          attributes);
    if (parser->node && parser->input) parser->node->_private = (void *)(intptr_t)parser->input->line;
}

/* COLLADA never needs entities, and expanding them is how a 100 KB file asks for gigabytes
 * ("billion laughs"): a document that declares any is refused at the declaration, before a byte
 * is expanded. References to undeclared entities are already well-formedness errors. */
static void on_entity_decl(void *user, const xmlChar *name, int type, const xmlChar *public_id,
                           const xmlChar *system_id, xmlChar *content)
{
    (void)type, (void)public_id, (void)system_id, (void)content;
    xmlParserCtxtPtr parser = user;
    xml_errors *errs = parser->_private;
    if (!errs->failed) {
        errs->failed = true;
        pl_fail(errs->ctx->diag, PL_ERR_PARSE,
                "%s:%d: <!ENTITY %.64s>: expected no entity declarations (COLLADA needs none, and their "
                "expansion can cost gigabytes)", errs->ctx->name, parser->input ? parser->input->line : 1,
                name ? (const char *)name : "?");
    }
    xmlStopParser(parser);
}

/* The document tree from memory, with the handlers above installed: errors recorded with their
 * line, entities refused, the network never touched. */
static pl_status parse_xml(dae_ctx *c, const char *xml, size_t len)
{
    if (len > INT_MAX) return pl_fail(c->diag, PL_ERR_PARSE, "%s:1: XML: file too large", c->name);
    xmlParserCtxtPtr parser = xmlNewParserCtxt();
    if (!parser) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    xml_errors errs = {c, parser, false};
    parser->_private = &errs;
    parser->sax->serror = on_parser_error;
    /* The per-thread handler is swapped only for this parse, so nothing else sees the change. */
    xmlStructuredErrorFunc saved_handler = xmlStructuredError;
    void *saved_context = xmlStructuredErrorContext;
    xmlSetStructuredErrorFunc(&errs, on_library_error);
    parser->sax->startElementNs = on_start_element;
    parser->sax->entityDecl = on_entity_decl;
    /* NONET: never fetch; no NOENT/DTDLOAD: external entities stay unloaded; BIG_LINES: exact lines
     * past 65535 in libxml2's own messages. */
    int opts = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_BIG_LINES;
    c->doc = xmlCtxtReadMemory(parser, xml, (int)len, c->name, NULL, opts);
    xmlSetStructuredErrorFunc(saved_context, saved_handler);
    bool ok = c->doc && !errs.failed && parser->wellFormed;
    xmlFreeParserCtxt(parser);
    if (ok) return PL_OK;
    if (!errs.failed) pl_fail(c->diag, PL_ERR_PARSE, "%s:1: XML: not a well-formed document", c->name);
    return PL_ERR_PARSE;
}

/* ---- transforms -------------------------------------------------------------------------- */

/* The rotation from the file's up axis to pathlab's Y up, applied above every node's transform. */
static pl_status read_up_axis(dae_ctx *c, const xmlNode *root)
{
    c->up = mat4_identity();
    const xmlNode *n = dae_child(dae_child(root, "asset"), "up_axis");
    if (!n) return PL_OK;  /* COLLADA's default is Y_UP */
    xmlChar *text = xmlNodeGetContent(n);
    const char *s = text ? (const char *)text : "";
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') s++;
    size_t len = strcspn(s, " \t\r\n");
    pl_status st = PL_OK;
    mat4 m = mat4_identity();
    if (len == 4 && strncmp(s, "Y_UP", 4) == 0) {
        /* already pathlab's convention */
    } else if (len == 4 && strncmp(s, "Z_UP", 4) == 0) {
        /* CS184's mapping (x, y, z) -> (-x, z, y), a proper rotation, so course scenes frame alike */
        m.m[0][0] = -1; m.m[1][1] = 0; m.m[1][2] = 1; m.m[2][1] = 1; m.m[2][2] = 0;
    } else if (len == 4 && strncmp(s, "X_UP", 4) == 0) {
        /* COLLADA's X_UP has right = -Y, up = +X: (x, y, z) -> (-y, x, z) */
        m.m[0][0] = 0; m.m[0][1] = -1; m.m[1][0] = 1; m.m[1][1] = 0;
    } else {
        st = dae_error(c, n, PL_ERR_PARSE, "expected X_UP, Y_UP or Z_UP, found '%.*s'", (int)(len > 32 ? 32 : len), s);
    }
    xmlFree(text);
    c->up = m;
    return st;
}

/* ---- transforms in double --------------------------------------------------------------------
 * A node's world transform is a float linear part and a double translation (dae_xform). Elements
 * are read in double, composed in double, and the scene's origin is taken off before anything is
 * stored in float: a Cornell box 10^6 m from its file's origin loads as the same box at 0. */

/* Camera units: a camera nearer the file's origin keeps it (visit_child). Within 1 km, float's steps
 * are at most 6e-5 m, which renders a metre-sized scene unbiased (a Cornell box moved by 10^3 m is,
 * measured: issue 32), and the file's own numbers are kept: cornell_grazing.dae sits 100 m out on
 * purpose, where a shadow ray from the raw hit point darkens the image enough to grade. */
#define DAE_ORIGIN_NEAR 1024.0

static dae_xform xform_identity(void)
{
    dae_xform x = {mat4_identity(), {0, 0, 0}};
    return x;
}

static dae_xform xform_linear(mat4 m)
{
    dae_xform x = {m, {0, 0, 0}};
    for (int i = 0; i < 3; i++) x.linear.m[i][3] = 0.0f;
    return x;
}

/* a then b (b applied first): the linear parts multiply, a's linear part moves b's translation. */
static dae_xform xform_mul(const dae_xform *a, const dae_xform *b)
{
    dae_xform r = {mat4_mul(a->linear, b->linear), {0, 0, 0}};
    for (int i = 0; i < 3; i++)
        r.t[i] = a->t[i] + (double)a->linear.m[i][0] * b->t[0] + (double)a->linear.m[i][1] * b->t[1] +
                 (double)a->linear.m[i][2] * b->t[2];
    return r;
}

/* The float transform the instances use: x with the scene's origin taken off its translation. */
static mat4 xform_to_render(const dae_ctx *c, const dae_xform *x)
{
    mat4 m = x->linear;
    for (int i = 0; i < 3; i++) m.m[i][3] = (float)(x->t[i] - c->out->origin[i]);
    return m;
}

/* The product of a node's transform elements in document order (COLLADA post-multiplies). */
static pl_status node_transform(dae_ctx *c, const xmlNode *node, dae_xform *out)
{
    dae_xform m = xform_identity();
    for (const xmlNode *t = dae_first(node); t; t = dae_next(t)) {
        double v[16];
        pl_status st = PL_OK;
        dae_xform step = xform_identity();
        if (dae_is(t, "matrix")) {
            st = dae_doubles(c, t, v, 16);
            for (int i = 0; i < 3; i++) {  /* row-major, as written; the last row is (0 0 0 1) */
                for (int j = 0; j < 3; j++) step.linear.m[i][j] = (float)v[4 * i + j];
                step.t[i] = v[4 * i + 3];
            }
        } else if (dae_is(t, "translate")) {
            st = dae_doubles(c, t, v, 3);
            for (int i = 0; i < 3; i++) step.t[i] = v[i];
        } else if (dae_is(t, "scale")) {
            st = dae_doubles(c, t, v, 3);
            step = xform_linear(mat4_scale(vec3_make((float)v[0], (float)v[1], (float)v[2])));
        } else if (dae_is(t, "rotate")) {
            st = dae_doubles(c, t, v, 4);
            if (!st && v[0] == 0 && v[1] == 0 && v[2] == 0)
                st = dae_error(c, t, PL_ERR_INVALID, "expected a non-zero rotation axis (x y z degrees)");
            step = xform_linear(mat4_rotate(vec3_make((float)v[0], (float)v[1], (float)v[2]), (float)v[3]));
        } else if (dae_is(t, "lookat")) {
            /* The eye in double; the view's direction from target - eye, taken in double too. */
            st = dae_doubles(c, t, v, 9);
            vec3 ahead = vec3_make((float)(v[3] - v[0]), (float)(v[4] - v[1]), (float)(v[5] - v[2]));
            vec3 up = vec3_make((float)v[6], (float)v[7], (float)v[8]);
            if (!st && vec3_length(vec3_cross(ahead, up)) == 0.0f)
                st = dae_error(c, t, PL_ERR_INVALID,
                               "expected eye != target and an up vector not along the view direction");
            step = xform_linear(mat4_lookat(vec3_make(0, 0, 0), ahead, up));
            for (int i = 0; i < 3; i++) step.t[i] = v[i];
        } else if (dae_is(t, "skew")) {
            /* Valid COLLADA that pathlab cannot apply: warned about once, never silently dropped. */
            dae_warn_once(c, t, "skew", "<skew> transforms are not supported; ignored");
            continue;
        } else {
            continue;
        }
        if (st) return st;
        m = xform_mul(&m, &step);
    }
    *out = m;
    return PL_OK;
}

/* ---- the node tree ----------------------------------------------------------------------- */

static pl_status visit_node(dae_ctx *c, const xmlNode *node, const dae_xform *parent, int depth);

/* Transform elements are read by node_transform, so visit_child passes over them quietly. */
static bool is_transform(const xmlNode *n)
{
    return dae_is(n, "matrix") || dae_is(n, "translate") || dae_is(n, "rotate") || dae_is(n, "scale") ||
           dae_is(n, "lookat") || dae_is(n, "skew");
}

/* One child of a node, under the node's world transform x: a nested node, an instance of geometry,
 * a light, a camera or another node; anything else is warned about once. On the first pass
 * (c->finding_origin) only the nodes are followed, to the cameras: the position of the one the
 * render uses (dae_camera_wins) becomes the scene's origin. */
static pl_status visit_child(dae_ctx *c, const xmlNode *e, const dae_xform *x, int depth)
{
    if (dae_is(e, "node")) return visit_node(c, e, x, depth + 1);
    if (dae_is(e, "instance_node")) {
        dae_entry *target;
        pl_status st = dae_resolve(c, e, "url", "node", &target);
        return st ? st : visit_node(c, target->node, x, depth + 1);
    }
    if (c->finding_origin) {
        /* The position of the camera the render uses (dae_camera_wins), so that what it sees is
         * stored with float's finest steps; but a camera within DAE_ORIGIN_NEAR of the file's origin leaves it at 0, so that a
         * scene near its origin loads with exactly the file's numbers. Near in the camera's own
         * units: a scene scaled by 10^-3 (its camera too) 10 m away is 10^4 of its sizes away. */
        if (dae_is(e, "instance_camera") && dae_camera_wins(c, c->origin_found)) {
            double units = vec3_length(mat4_dir(x->linear, vec3_make(1, 0, 0))), reach = DAE_ORIGIN_NEAR * units;
            bool near = fabs(x->t[0]) < reach && fabs(x->t[1]) < reach && fabs(x->t[2]) < reach;
            for (int i = 0; i < 3; i++) c->out->origin[i] = near ? 0.0 : x->t[i];
            c->origin_found = true;
        }
        return PL_OK;
    }
    mat4 m = xform_to_render(c, x);
    if (dae_is(e, "instance_geometry")) return dae_instance_geometry(c, e, m);
    if (dae_is(e, "instance_light")) return dae_instance_light(c, e, m);
    if (dae_is(e, "instance_camera")) return dae_instance_camera(c, e, m, x);
    if (dae_is(e, "instance_controller")) {
        dae_warn_once(c, e, "instance_controller",
                      "skinned or morphed meshes (<instance_controller>) are not supported; skipped");
        return PL_OK;
    }
    if (!is_transform(e) && !dae_is(e, "extra") && !dae_is(e, "asset"))
        dae_warn_once(c, e, dae_name(e), "<%s> is not supported here; ignored", dae_name(e));
    return PL_OK;
}

static pl_status visit_node(dae_ctx *c, const xmlNode *node, const dae_xform *parent, int depth)
{
    if (depth > MAX_NODE_DEPTH)
        return dae_error(c, node, PL_ERR_PARSE, "nodes nested deeper than %d levels (an <instance_node> cycle?)",
                         MAX_NODE_DEPTH);
    /* <instance_node> can multiply work exponentially (a node instancing another twice, 40 times). */
    if (++c->node_visits > c->limits.max_instances)
        return dae_error(c, node, PL_ERR_INVALID, "more than %ld node instances (<instance_node> fan-out?): the "
                         "limit guards time and memory; --max-instances N raises it", c->limits.max_instances);
    dae_xform local = xform_identity();
    pl_status st = node_transform(c, node, &local);
    dae_xform x = xform_mul(parent, &local);
    for (const xmlNode *e = dae_first(node); e && !st; e = dae_next(e)) st = visit_child(c, e, &x, depth);
    return st;
}

/* ---- the course's profile ------------------------------------------------------------------ */

/* Any <technique profile="CGL"> in the document: CS184's extensions. Walked without recursion (a
 * hostile file may nest deeply), following parent links back up. */
static bool uses_cgl(const xmlNode *root)
{
    const xmlNode *n = root;
    while (n) {
        if (n->type == XML_ELEMENT_NODE && dae_is(n, "technique")) {
            const char *profile = dae_attr(n, "profile");
            if (profile && strcmp(profile, "CGL") == 0) return true;
        }
        if (n->children) { n = n->children; continue; }
        while (n && n != root && !n->next) n = n->parent;
        if (!n || n == root) break;
        n = n->next;
    }
    return false;
}

/* Whether <asset><contributor> names pathlab (as author or authoring tool): pathlab's own scenes
 * are written in CS184's dialect, CGL and all, but their cameras are placed to be taken literally,
 * and they say whose they are there. */
static bool names_pathlab(const xmlNode *root)
{
    for (const xmlNode *who = dae_first(dae_child(root, "asset")); who; who = dae_next(who)) {
        if (!dae_is(who, "contributor")) continue;
        for (const xmlNode *e = dae_first(who); e; e = dae_next(e)) {
            if (!dae_is(e, "author") && !dae_is(e, "authoring_tool")) continue;
            xmlChar *text = xmlNodeGetContent(e);
            bool ours = text && strstr((const char *)text, "pathlab");
            xmlFree(text);
            if (ours) return true;
        }
    }
    return false;
}

/* The whole document: its root, its up axis and id index, then the visual scene's node tree. */
static pl_status load_document(dae_ctx *c)
{
    xmlNode *root = xmlDocGetRootElement(c->doc);
    if (!dae_is(root, "COLLADA"))
        return dae_error(c, root, PL_ERR_PARSE, "expected the root element <COLLADA>");
    pl_status st = read_up_axis(c, root);
    if (!st) st = dae_index_build(c);
    if (st) return st;
    /* A course file (CS184's extensions, not one of pathlab's own) is framed as the course frames it. */
    c->out->course_profile = uses_cgl(root) && !names_pathlab(root);

    /* What loads but is not honoured is said once, so a scene never differs silently. */
    const xmlNode *animations = dae_child(root, "library_animations");
    if (animations && dae_first(animations))
        dae_warn_once(c, animations, "animation", "animations are not supported; the scene loads at rest");
    const xmlNode *units = dae_child(dae_child(root, "asset"), "unit");
    const char *meter = dae_attr(units, "meter");
    if (meter && strtod(meter, NULL) != 1.0)
        dae_warn_once(c, units, "unit", "unit meter=\"%.32s\" is ignored: lengths are read as metres", meter);

    const xmlNode *sc = dae_child(root, "scene");
    if (!sc) return dae_error(c, root, PL_ERR_PARSE, "expected a <scene> element");
    const xmlNode *inst = dae_child(sc, "instance_visual_scene");
    if (!inst) return dae_error(c, sc, PL_ERR_PARSE, "expected an <instance_visual_scene>");
    dae_entry *vs;
    st = dae_resolve(c, inst, "url", "visual_scene", &vs);
    /* Two walks of the node tree: the first finds the render's camera's position, the scene's
     * origin (no camera: the file's own), the second loads everything relative to it. */
    dae_xform up = xform_linear(c->up);
    for (int pass = 0; pass < 2 && !st; pass++) {
        c->finding_origin = pass == 0;
        c->node_visits = 0;
        for (const xmlNode *n = vs ? dae_first(vs->node) : NULL; n && !st; n = dae_next(n))
            st = visit_child(c, n, &up, 0);
    }
    /* Last: whether a light's quad covers it is known only once every mesh is read. */
    return st ? st : dae_make_lights_visible(c);
}

/* ---- entry points ------------------------------------------------------------------------ */

/* The caps README.md states: 2,000,000 primitives, 1,000,000 node instances. */
dae_limits dae_limits_default(void)
{
    dae_limits l = {DAE_DEFAULT_MAX_PRIMITIVES, DAE_DEFAULT_MAX_INSTANCES};
    return l;
}

pl_status dae_load_memory_limited(const char *xml, size_t len, const char *name, const dae_limits *limits,
                                  scene *out, pl_diag *diag)
{
    pl_diag fallback = pl_diag_default();  /* a NULL diag still gets errors recorded and warnings printed */
    memset(out, 0, sizeof *out);
    dae_ctx c;
    memset(&c, 0, sizeof c);
    c.name = name ? name : "<memory>";
    c.diag = diag ? diag : &fallback;
    c.out = out;
    c.default_material = -1;
    c.limits = limits ? *limits : dae_limits_default();
    c.diag->error[0] = '\0';

    /* Parse, convert, and free the document whatever happened: a failed load leaves no scene. */
    pl_status st = parse_xml(&c, xml ? xml : "", xml ? len : 0);
    if (!st) st = load_document(&c);
    dae_index_free(&c.index);
    free(c.light_nodes);
    xmlFreeDoc(c.doc);
    if (st) {
        scene_free(out);
        return st;
    }
    out->has_camera = c.has_camera;
    snprintf(out->path, sizeof out->path, "%s", c.name);
    return PL_OK;
}

pl_status dae_load_limited(const char *path, const dae_limits *limits, scene *out, pl_diag *diag)
{
    memset(out, 0, sizeof *out);
    char *buf;
    size_t len;
    pl_status st = file_read_all(path, "scene", DAE_MAX_FILE_BYTES, &buf, &len, diag);
    if (st) return st;
    st = dae_load_memory_limited(buf, len, path, limits, out, diag);
    free(buf);
    return st;
}

pl_status dae_load_memory(const char *xml, size_t len, const char *name, scene *out, pl_diag *diag)
{
    return dae_load_memory_limited(xml, len, name, NULL, out, diag);
}

pl_status dae_load(const char *path, scene *out, pl_diag *diag)
{
    return dae_load_limited(path, NULL, out, diag);
}
