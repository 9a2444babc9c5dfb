/* Area lights as visible geometry (visible_light.h): whether an emissive mesh covers a light, and
 * the two triangles that show it where none does. */
#include "visible_light.h"
#include "light.h"
#include <float.h>
#include <math.h>
#include <stdio.h>

/* ---- the light's plane, in double --------------------------------------------------------------
 * Coverage is a question about a file's numbers (is this quad where that light is?), asked once per
 * load: double keeps its answer free of float's rounding wherever the scene sits. */

typedef struct {
    double c[3];       /* the light's centre */
    double n[3];       /* its unit normal */
    double du[3], dv[3];  /* the dual basis: (p - c).du and (p - c).dv are p's coordinates along
                             edge_u and edge_v, the light spanning [-1/2, 1/2] in both */
    double tol;        /* how far from the plane a corner may lie and still be in it (m) */
    aabb box;          /* the light's corners, grown by tol: a cheap test before the exact one */
} light_plane;

static void dvec_of(vec3 v, double out[3]) { out[0] = v.x, out[1] = v.y, out[2] = v.z; }
static double ddot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void dcross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* False for a light with no area or no normal (the loader refuses those before this is asked). */
static bool plane_make(const light *l, light_plane *p)
{
    double u[3], v[3], vxn[3], nxu[3];
    dvec_of(l->position, p->c);
    dvec_of(l->edge_u, u);
    dvec_of(l->edge_v, v);
    dvec_of(l->direction, p->n);
    double len = sqrt(ddot(p->n, p->n));
    if (!(len > 0)) return false;
    for (int i = 0; i < 3; i++) p->n[i] /= len;
    /* du is orthogonal to v and n with u.du = 1; dv likewise: they undo a skewed parallelogram too. */
    dcross(v, p->n, vxn);
    dcross(p->n, u, nxu);
    double su = ddot(u, vxn), sv = ddot(v, nxu);
    if (!(fabs(su) > 0 && fabs(sv) > 0)) return false;
    for (int i = 0; i < 3; i++) p->du[i] = vxn[i] / su, p->dv[i] = nxu[i] / sv;
    /* A thousandth of the light's size (Blender writes a quad and a light of one matrix to 1e-7),
     * plus float's steps where the scene sits, so a box far from the origin is judged alike. */
    float far = fmaxf(fmaxf(fabsf(l->position.x), fabsf(l->position.y)), fabsf(l->position.z));
    p->tol = 1e-3 * 0.5 * (sqrt(ddot(u, u)) + sqrt(ddot(v, v))) + 64.0 * FLT_EPSILON * far;
    vec3 grow = vec3_make(1, 1, 1);
    p->box = aabb_empty();
    for (int k = 0; k < 4; k++) p->box = aabb_extend(p->box, light_area_corner(l, k));
    p->box.min = vec3_sub(p->box.min, vec3_scale(grow, (float)p->tol));
    p->box.max = vec3_add(p->box.max, vec3_scale(grow, (float)p->tol));
    return true;
}

/* ---- clipping a triangle to the light ---------------------------------------------------------- */

/* The part of polygon in (n corners, in the light's coordinates) where sign * coordinate `axis` <=
 * 1/2, into out (room for n + 1); returns its corner count (Sutherland and Hodgman's step). */
static int clip_half(double in[][2], int n, int axis, double sign, double out[][2])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *p = in[i], *q = in[(i + 1) % n];
        double dp = sign * p[axis] - 0.5, dq = sign * q[axis] - 0.5;
        if (dp <= 0) out[m][0] = p[0], out[m][1] = p[1], m++;
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {  /* the edge crosses the line: keep the crossing */
            double t = dp / (dp - dq);
            out[m][0] = p[0] + t * (q[0] - p[0]), out[m][1] = p[1] + t * (q[1] - p[1]), m++;
        }
    }
    return m;
}

/* The area of triangle tri (light coordinates) inside the light's square [-1/2, 1/2]^2, whose area
 * is 1: the share of the light the triangle covers. Four clips add a corner each at most: 7. */
static double clipped_share(double tri[3][2])
{
    double a[8][2], b[8][2];
    int n = clip_half(tri, 3, 0, 1.0, a);
    n = clip_half(a, n, 0, -1.0, b);
    n = clip_half(b, n, 1, 1.0, a);
    n = clip_half(a, n, 1, -1.0, b);
    double twice = 0;  /* the shoelace formula */
    for (int i = 0; i < n; i++) twice += b[i][0] * b[(i + 1) % n][1] - b[(i + 1) % n][0] * b[i][1];
    return 0.5 * fabs(twice);
}

/* The share of the light triangle t covers: 0 unless every corner is in the light's plane. */
static double triangle_share(const light_plane *p, const triangle *t)
{
    vec3 corners[3] = {t->p0, t->p1, t->p2};
    double tri[3][2];
    for (int k = 0; k < 3; k++) {
        double d[3];
        dvec_of(corners[k], d);
        for (int i = 0; i < 3; i++) d[i] -= p->c[i];
        if (fabs(ddot(d, p->n)) > p->tol) return 0;
        tri[k][0] = ddot(d, p->du), tri[k][1] = ddot(d, p->dv);
    }
    return clipped_share(tri);
}

static bool boxes_overlap(aabb a, aabb b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

double visible_light_coverage(const scene *s, const light *l, int num_triangles)
{
    light_plane p;
    if (l->kind != LIGHT_AREA || !plane_make(l, &p)) return 0;
    double share = 0;
    for (int i = 0; i < num_triangles && i < s->num_triangles; i++) {
        const triangle *t = &s->triangles[i];
        if (rgb_is_black(s->materials[t->material].Le) || !boxes_overlap(p.box, scene_prim_bounds(s, i))) continue;
        share += triangle_share(&p, t);
    }
    return share;
}

/* ---- the light's own triangles ----------------------------------------------------------------- */

int visible_light_add(scene *s, int index)
{
    const light l = s->lights[index];  /* a copy: adding to the scene may move its arrays */
    material m = material_make(rgb_gray(0.0f), l.radiance);  /* an emitter reflects nothing */
    snprintf(m.name, sizeof m.name, "area light %d, made visible", index);
    int mat = scene_add_material(s, m);
    if (mat < 0) return -1;
    /* The corners; the triangles wound so that their face normal is the light's direction, and
     * that direction at every corner, so that hits agree on the side that glows. */
    vec3 c00 = light_area_corner(&l, 0), c10 = light_area_corner(&l, 1);
    vec3 c01 = light_area_corner(&l, 2), c11 = light_area_corner(&l, 3);
    bool front = vec3_dot(vec3_cross(vec3_sub(c10, c00), vec3_sub(c11, c00)), l.direction) >= 0.0f;
    triangle a = front ? triangle_make(c00, c10, c11, mat) : triangle_make(c00, c11, c10, mat);
    triangle b = front ? triangle_make(c00, c11, c01, mat) : triangle_make(c00, c01, c11, mat);
    a.n0 = a.n1 = a.n2 = b.n0 = b.n1 = b.n2 = l.direction;
    int first = scene_add_triangle(s, a);
    if (first < 0 || scene_add_triangle(s, b) < 0) return -1;
    s->visible_lights++;
    return first;
}

void visible_light_status_line(const scene *s, char *buf, size_t size)
{
    if (s->visible_lights <= 0) {
        if (size) buf[0] = '\0';
        return;
    }
    snprintf(buf, size, "lights: %d area light%s made visible (no emissive mesh over %s in the file): "
             "two emitting triangles each, as CS184's second-assignment framework shows them",
             s->visible_lights, s->visible_lights == 1 ? "" : "s", s->visible_lights == 1 ? "it" : "them");
}
