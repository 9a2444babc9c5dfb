/* COLLADA loader: lights and the camera, placed by their node's transform. A CGL technique in a
 * <light> wins over technique_common, as in CS184. */
#include "dae_internal.h"
#include "light.h"
#include "buf.h"
#include "check.h"
#include "visible_light.h"

#include <math.h>
#include <string.h>


/* ---- lights ------------------------------------------------------------------------------ */

/* The node's local -Z in world space: where directional and spot lights point, unit length. */
static vec3 local_minus_z(mat4 m) { return vec3_normalize(mat4_dir(m, vec3_make(0, 0, -1))); }

/* One light from its type element, placed by the node's transform m. Every kind starts at the
 * node's origin with no attenuation (constant 1); each branch reads what its kind has. */
static pl_status read_light(dae_ctx *c, const xmlNode *shape, mat4 m, light *l)
{
    memset(l, 0, sizeof *l);
    l->attenuation[0] = 1.0f;
    l->position = mat4_point(m, vec3_make(0, 0, 0));
    pl_status st = dae_child_color(c, shape, "color", true, &l->radiance);
    if (st) return st;
    if (dae_is(shape, "point") || dae_is(shape, "spot")) {
        l->kind = dae_is(shape, "point") ? LIGHT_POINT : LIGHT_SPOT;
        st = dae_child_float(c, shape, "constant_attenuation", 1.0f, &l->attenuation[0]);
        if (!st) st = dae_child_float(c, shape, "linear_attenuation", 0.0f, &l->attenuation[1]);
        if (!st) st = dae_child_float(c, shape, "quadratic_attenuation", 0.0f, &l->attenuation[2]);
        if (!st && l->kind == LIGHT_SPOT) {
            float full_angle;
            l->direction = local_minus_z(m);
            /* COLLADA's falloff_angle is the cone's full opening (default 180: a hemisphere). */
            st = dae_child_float(c, shape, "falloff_angle", 180.0f, &full_angle);
            if (!st) st = dae_child_float(c, shape, "falloff_exponent", 0.0f, &l->falloff_exp);
            if (!st && !(full_angle > 0 && full_angle <= 360))
                st = dae_error(c, shape, PL_ERR_INVALID, "expected falloff_angle in (0, 360] degrees, found %g",
                               full_angle);
            l->falloff_deg = 0.5f * full_angle;
        }
    } else if (dae_is(shape, "directional")) {
        l->kind = LIGHT_DIRECTIONAL;
        l->direction = local_minus_z(m);
    } else if (dae_is(shape, "ambient")) {
        /* Light from the whole upper hemisphere (world +Y, light.c); the sampler ignores direction. */
        l->kind = LIGHT_AMBIENT;
        l->direction = vec3_make(0, 1, 0);
    } else {  /* area: the node's unit square [-1/2, 1/2]^2 at z = 0, emitting towards its -Z */
        *l = light_make_area(l->position, mat4_dir(m, vec3_make(1, 0, 0)), mat4_dir(m, vec3_make(0, 1, 0)),
                             mat4_normal(m, vec3_make(0, 0, -1)), l->radiance);
        if (!(l->area > 0))
            st = dae_error(c, shape, PL_ERR_INVALID, "the node's transform gives the area light no area");
    }
    return st;
}

/* An <instance_light>: the CGL technique when there is one (CS184's area lights live there), else
 * technique_common; an unknown light type is warned about and skipped, never guessed. */
pl_status dae_instance_light(dae_ctx *c, const xmlNode *inst, mat4 to_world)
{
    dae_entry *entry;
    pl_status st = dae_resolve(c, inst, "url", "light", &entry);
    if (st) return st;
    const xmlNode *technique = dae_cgl_technique(entry->node);
    if (!technique) technique = dae_child(entry->node, "technique_common");
    if (!technique) return dae_error(c, entry->node, PL_ERR_PARSE, "expected a <technique_common> or a CGL technique");
    const xmlNode *shape = dae_first(technique);
    if (!shape) return dae_error(c, technique, PL_ERR_PARSE, "expected a light type (point, spot, directional, ambient, area)");
    if (!dae_is(shape, "point") && !dae_is(shape, "spot") && !dae_is(shape, "directional") &&
        !dae_is(shape, "ambient") && !dae_is(shape, "area")) {
        dae_warn_once(c, shape, dae_name(shape), "<%s> lights are not supported; skipped", dae_name(shape));
        return PL_OK;
    }
    light l;
    if ((st = read_light(c, shape, to_world, &l))) return st;
    if (scene_add_light(c->out, l) < 0 ||
        buf_append(&c->light_nodes, &c->num_light_nodes, &c->light_nodes_cap, sizeof inst, &inst) < 0)
        return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return PL_OK;
}

/* ---- area lights made visible ------------------------------------------------------------ */

/* How many (area light, emissive triangle) pairs coverage would compare. */
static long coverage_pairs(const scene *s)
{
    long lights = 0, emissive = 0;
    for (int k = 0; k < s->num_lights; k++) lights += s->lights[k].kind == LIGHT_AREA;
    for (int i = 0; i < s->num_triangles; i++) emissive += !rgb_is_black(s->materials[s->triangles[i].material].Le);
    return lights * emissive;
}

/* Light k's two triangles, within the caps: the primitive limit and the coordinates' range. */
static pl_status make_visible(dae_ctx *c, int k, const xmlNode *at)
{
    pl_status st = dae_check_room(c, at, 2);
    for (int corner = 0; corner < 4 && !st; corner++)
        st = dae_check_coord(c, at, "a corner of the area light made visible", light_area_corner(&c->out->lights[k], corner));
    if (!st && visible_light_add(c->out, k) < 0) st = pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return st;
}

pl_status dae_make_lights_visible(dae_ctx *c)
{
    scene *s = c->out;
    PL_CHECK(c->num_light_nodes == s->num_lights);
    int file_triangles = s->num_triangles, num_lights = s->num_lights;
    long pairs = coverage_pairs(s);
    for (int k = 0; k < num_lights; k++) {
        const light *l = &s->lights[k];
        if (l->kind != LIGHT_AREA || rgb_is_black(l->radiance)) continue;  /* nothing to see */
        const xmlNode *at = c->light_nodes[k];
        if (pairs > VISIBLE_LIGHT_MAX_PAIRS) {
            dae_warn_once(c, at, "visible lights", "%ld pairs of area lights and emissive triangles, more than the "
                          "%ld the loader compares to find the lights no emissive mesh covers: every area light "
                          "stays a pure light source, which rays do not see", pairs, (long)VISIBLE_LIGHT_MAX_PAIRS);
            return PL_OK;
        }
        double covered = visible_light_coverage(s, l, file_triangles);
        if (covered >= VISIBLE_LIGHT_COVERED) continue;  /* the file's own emitter shows it */
        if (covered > VISIBLE_LIGHT_PARTLY)
            dae_warn_once(c, at, "partly covered light", "emissive triangles cover %.0f%% of this area light: it is "
                          "made visible whole, as CS184's second-assignment framework makes every area light, and "
                          "where the file's mesh lies two emitters coincide", 100.0 * covered);
        pl_status st = make_visible(c, k, at);
        if (st) return st;
    }
    return PL_OK;
}

/* ---- camera ------------------------------------------------------------------------------ */

/* A field of view a pinhole camera can have: strictly between 0 and 180 degrees. */
static pl_status check_fov(dae_ctx *c, const xmlNode *perspective, const char *name, float fov)
{
    if (fov > 0 && fov < 180) return PL_OK;
    return dae_error(c, perspective, PL_ERR_INVALID, "expected %s in (0, 180) degrees, found %g", name, fov);
}

bool dae_camera_wins(const dae_ctx *c, bool seen_one) { return !seen_one || c->out->course_profile; }

/* CS184's framing direction of a camera at x (camera.h's orbit_dir): c_dir = normalize(M (0,0,-1,1)),
 * the node's matrix (up axis included) applied to the point (0, 0, -1), computed in double in the
 * file's coordinates, as Application::load does. Zero, with a warning, where that point is the
 * origin: the course's direction is undefined there (CS184 normalises a zero vector); the warning
 * only for a course file, the one framed this way by default. */
static vec3 cs184_orbit_dir(dae_ctx *c, const xmlNode *inst, const dae_xform *x)
{
    double p[3], len2 = 0;
    for (int i = 0; i < 3; i++) {
        p[i] = x->t[i] - (double)x->linear.m[i][2];  /* t + L (0, 0, -1) */
        len2 += p[i] * p[i];
    }
    if (!(len2 > 0)) {
        if (c->out->course_profile)  /* only a course file is framed this way by default */
            dae_warn_once(c, inst, "orbit at origin", "the camera's point M (0, 0, -1) is the origin, where CS184's "
                          "framing direction is undefined; its framing orbits opposite the camera's view instead");
        return vec3_make(0, 0, 0);
    }
    double len = sqrt(len2);
    return vec3_make((float)(p[0] / len), (float)(p[1] / len), (float)(p[2] / len));
}

pl_status dae_instance_camera(dae_ctx *c, const xmlNode *inst, mat4 to_world, const dae_xform *x)
{
    dae_entry *entry;
    pl_status st = dae_resolve(c, inst, "url", "camera", &entry);
    if (st) return st;
    /* One camera is kept (dae_camera_wins): a course file's last, as CS184's application keeps it,
     * any other file's first; the others are warned about. */
    if (c->has_camera) {
        bool last = dae_camera_wins(c, true);
        dae_warn_once(c, inst, "second camera", "the scene has more than one camera; using the %s",
                      last ? "last, as CS184 does with a file in the course's profile" : "first");
        if (!last) return PL_OK;
    }
    const xmlNode *common = dae_child(dae_child(entry->node, "optics"), "technique_common");
    const xmlNode *perspective = dae_child(common, "perspective");
    if (!perspective) {
        if (dae_child(common, "orthographic")) {
            dae_warn_once(c, inst, "orthographic", "orthographic cameras are not supported; using a default camera");
            return PL_OK;
        }
        return dae_error(c, entry->node, PL_ERR_PARSE, "expected <optics><technique_common><perspective>");
    }
    bool has_x = dae_child(perspective, "xfov") != NULL, has_y = dae_child(perspective, "yfov") != NULL;
    if (!has_x && !has_y) return dae_error(c, perspective, PL_ERR_PARSE, "expected an <xfov> or a <yfov>");
    /* Read and check the numbers here, where errors can name the element; camera.c builds it. */
    float xfov, yfov, aspect, znear, zfar;
    st = dae_child_float(c, perspective, "xfov", 0.0f, &xfov);  /* 0: not given */
    if (!st) st = dae_child_float(c, perspective, "yfov", 0.0f, &yfov);
    if (!st) st = dae_child_float(c, perspective, "aspect_ratio", 4.0f / 3.0f, &aspect);  /* CS184's 800x600 */
    if (!st) st = dae_child_float(c, perspective, "znear", 0.01f, &znear);
    if (!st) st = dae_child_float(c, perspective, "zfar", 1e30f, &zfar);
    if (!st && has_x) st = check_fov(c, perspective, "xfov", xfov);
    if (!st && has_y) st = check_fov(c, perspective, "yfov", yfov);
    if (!st && !(aspect > 0)) st = dae_error(c, perspective, PL_ERR_INVALID, "expected aspect_ratio > 0, found %g", aspect);
    if (!st && !(znear >= 0 && zfar > znear))
        st = dae_error(c, perspective, PL_ERR_INVALID, "expected 0 <= znear < zfar, found %g and %g", znear, zfar);
    if (st) return st;
    c->out->camera = camera_from_collada(to_world, xfov, yfov, aspect, znear, zfar);
    c->out->camera.orbit_dir = cs184_orbit_dir(c, inst, x);
    c->has_camera = true;
    return PL_OK;
}
