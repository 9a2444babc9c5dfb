/* Test machinery: not part of any assignment. */
#include "tiny_scenes.h"
#include <stdlib.h>
#include <string.h>
#include "../../framework/cli.h"
#include "../../framework/light.h"

void tiny_world_begin(tiny_world *w)
{
    memset(w, 0, sizeof *w);
    w->o = options_default();
    w->o.threads = 1;
    w->o.quiet = true;
}

pl_status tiny_world_finish(tiny_world *w)
{
    pl_diag d = pl_diag_default();
    pl_status st = accel_build(&w->a, &w->s, false, 4, &d);
    if (st != PL_OK)
        return st;
    render_ctx_init(&w->ctx, &w->s, &w->a, &w->o);
    return PL_OK;
}

void tiny_world_refresh(tiny_world *w)
{
    render_ctx_init(&w->ctx, &w->s, &w->a, &w->o);
}

void tiny_world_free(tiny_world *w)
{
    accel_free(&w->a);
    scene_free(&w->s);
}

tiny_world *tiny_world_new(void)
{
    tiny_world *w = malloc(sizeof *w);
    if (w) tiny_world_begin(w);
    return w;
}

void tiny_world_destroy(tiny_world *w)
{
    if (!w) return;
    tiny_world_free(w);
    free(w);
}

int tiny_world_teardown(void **state)
{
    tiny_world_destroy(*state);
    *state = NULL;
    return 0;
}

bool tiny_add_quad(scene *s, vec3 c, vec3 ea, vec3 eb, vec3 facing, int mat)
{
    if (vec3_dot(vec3_cross(ea, eb), facing) < 0.0f) {
        vec3 t = ea;
        ea = eb;
        eb = t;
    }
    vec3 ha = vec3_scale(ea, 0.5f), hb = vec3_scale(eb, 0.5f);
    vec3 p00 = vec3_sub(vec3_sub(c, ha), hb), p10 = vec3_sub(vec3_add(c, ha), hb);
    vec3 p11 = vec3_add(vec3_add(c, ha), hb), p01 = vec3_add(vec3_sub(c, ha), hb);
    return scene_add_triangle(s, triangle_make(p00, p10, p11, mat)) >= 0 &&
           scene_add_triangle(s, triangle_make(p00, p11, p01, mat)) >= 0;
}

bool tiny_add_emitter(scene *s, vec3 c, vec3 ea, vec3 eb, vec3 facing, rgb Le)
{
    int mat = scene_add_material(s, material_make(rgb_gray(0.0f), Le));
    vec3 n = vec3_normalize(vec3_cross(ea, eb));
    light l = light_make_area(c, ea, eb, vec3_dot(n, facing) < 0.0f ? vec3_neg(n) : n, Le);
    return mat >= 0 && scene_add_light(s, l) >= 0 && tiny_add_quad(s, c, ea, eb, facing, mat);
}

bool tiny_scene_emitter_over_plane(scene *s, float rho, float Le, float half_x, float half_z, float height)
{
    memset(s, 0, sizeof *s);
    int floor_mat = scene_add_material(s, material_make(rgb_gray(rho), rgb_gray(0.0f)));
    vec3 up = vec3_make(0, 1, 0);
    return floor_mat >= 0 &&
           tiny_add_quad(s, vec3_make(0, 0, 0), vec3_make(40, 0, 0), vec3_make(0, 0, 40), up, floor_mat) &&
           tiny_add_emitter(s, vec3_make(0, height, 0), vec3_make(2 * half_x, 0, 0), vec3_make(0, 0, 2 * half_z),
                            vec3_neg(up), rgb_gray(Le));
}

double tiny_corner_form_factor(double x, double y, double h)
{
    double X = x / h, Y = y / h;
    double sx = sqrt(1.0 + X * X), sy = sqrt(1.0 + Y * Y);
    return (X / sx * atan(Y / sx) + Y / sy * atan(X / sy)) / (2.0 * 3.14159265358979323846);
}

/* A corner rectangle with signed sides: the sign says on which side of the point it lies, and the
 * rectangle over [x0, x1] x [z0, z1] is the signed sum of the four corner rectangles. */
static double signed_corner(double x, double z, double h)
{
    double f = tiny_corner_form_factor(fabs(x), fabs(z), h);
    return (x < 0) != (z < 0) ? -f : f;
}

double tiny_emitter_over_plane_direct(double rho, double Le, double half_x, double half_z, double height,
                                      double px, double pz)
{
    double x0 = -half_x - px, x1 = half_x - px, z0 = -half_z - pz, z1 = half_z - pz;
    double F = signed_corner(x1, z1, height) - signed_corner(x0, z1, height) -
               signed_corner(x1, z0, height) + signed_corner(x0, z0, height);
    return rho * Le * F;
}

bool tiny_scene_point_over_plane(scene *s, float rho, float I, float height, const float *att)
{
    memset(s, 0, sizeof *s);
    int floor_mat = scene_add_material(s, material_make(rgb_gray(rho), rgb_gray(0.0f)));
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    l.radiance = rgb_gray(I);
    l.position = vec3_make(0, height, 0);
    l.attenuation[0] = att ? att[0] : 1.0f;
    l.attenuation[1] = att ? att[1] : 0.0f;
    l.attenuation[2] = att ? att[2] : 0.0f;
    return floor_mat >= 0 && scene_add_light(s, l) >= 0 &&
           tiny_add_quad(s, vec3_make(0, 0, 0), vec3_make(40, 0, 0), vec3_make(0, 0, 40), vec3_make(0, 1, 0), floor_mat);
}

double tiny_point_over_plane_direct(double rho, double I, double height, const float *att, double px, double pz)
{
    double d2 = px * px + pz * pz + height * height, d = sqrt(d2);
    double den = att ? att[0] + att[1] * d + att[2] * d2 : 1.0;
    return rho / 3.14159265358979323846 * I / den * (height / d) / d2;
}

bool tiny_scene_furnace(scene *s, float rho, float Le)
{
    memset(s, 0, sizeof *s);
    int mat = scene_add_material(s, material_make(rgb_gray(rho), rgb_gray(Le)));
    if (mat < 0)
        return false;
    for (int axis = 0; axis < 3; axis++) {
        for (int side = -1; side <= 1; side += 2) {
            float c[3] = {0, 0, 0}, a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
            c[axis] = (float)side;
            a[(axis + 1) % 3] = 2.0f;
            b[(axis + 2) % 3] = 2.0f;
            vec3 centre = vec3_make(c[0], c[1], c[2]);
            vec3 ea = vec3_make(a[0], a[1], a[2]), eb = vec3_make(b[0], b[1], b[2]);
            vec3 inwards = vec3_neg(centre);
            light l = light_make_area(centre, ea, eb, inwards, rgb_gray(Le));
            if (scene_add_light(s, l) < 0 || !tiny_add_quad(s, centre, ea, eb, inwards, mat))
                return false;
        }
    }
    s->has_camera = true;
    s->camera.camera_to_world = mat4_identity();
    s->camera.position = vec3_make(0, 0, 0);
    s->camera.hfov = 90.0f;
    s->camera.vfov = 90.0f;
    s->camera.znear = 0.0f;
    s->camera.zfar = 1e30f;
    return true;
}

static void set_camera(scene *s, vec3 eye, vec3 target, float hfov)
{
    s->has_camera = true;
    s->camera.camera_to_world = mat4_lookat(eye, target, vec3_make(0, 1, 0));
    s->camera.position = eye;
    s->camera.hfov = hfov;
    s->camera.vfov = hfov;
    s->camera.fov_is_vertical = false;
    s->camera.znear = 0.0f;
    s->camera.zfar = 1e30f;
}

bool tiny_scene_cornell(scene *s)
{
    memset(s, 0, sizeof *s);
    int white = scene_add_material(s, material_make(rgb_make(0.73f, 0.73f, 0.73f), rgb_gray(0.0f)));
    int red = scene_add_material(s, material_make(rgb_make(0.63f, 0.065f, 0.05f), rgb_gray(0.0f)));
    int green = scene_add_material(s, material_make(rgb_make(0.14f, 0.45f, 0.091f), rgb_gray(0.0f)));
    int blue = scene_add_material(s, material_make(rgb_make(0.2f, 0.3f, 0.7f), rgb_gray(0.0f)));
    if (white < 0 || red < 0 || green < 0 || blue < 0)
        return false;
    vec3 X = vec3_make(2, 0, 0), Y = vec3_make(0, 2, 0), Z = vec3_make(0, 0, 2);
    bool ok = tiny_add_quad(s, vec3_make(0, 0, 0), X, Z, vec3_make(0, 1, 0), white) &&
              tiny_add_quad(s, vec3_make(0, 2, 0), X, Z, vec3_make(0, -1, 0), white) &&
              tiny_add_quad(s, vec3_make(0, 1, -1), X, Y, vec3_make(0, 0, 1), white) &&
              tiny_add_quad(s, vec3_make(-1, 1, 0), Y, Z, vec3_make(1, 0, 0), red) &&
              tiny_add_quad(s, vec3_make(1, 1, 0), Y, Z, vec3_make(-1, 0, 0), green) &&
              tiny_add_emitter(s, vec3_make(0, 1.98f, 0), vec3_make(1.0f, 0, 0), vec3_make(0, 0, 0.8f),
                               vec3_make(0, -1, 0), rgb_gray(5.0f));
    /* A box on the floor: four sides and a top, each facing out. */
    vec3 bc = vec3_make(-0.35f, 0.6f, -0.3f);
    vec3 bx = vec3_make(0.5f, 0, 0.15f), bz = vec3_make(-0.15f, 0, 0.5f), by = vec3_make(0, 1.2f, 0);
    vec3 nx = vec3_normalize(bx), nz = vec3_normalize(bz);
    ok = ok && tiny_add_quad(s, vec3_add(bc, vec3_scale(bx, 0.5f)), by, bz, nx, blue) &&
         tiny_add_quad(s, vec3_sub(bc, vec3_scale(bx, 0.5f)), by, bz, vec3_neg(nx), blue) &&
         tiny_add_quad(s, vec3_add(bc, vec3_scale(bz, 0.5f)), by, bx, nz, blue) &&
         tiny_add_quad(s, vec3_sub(bc, vec3_scale(bz, 0.5f)), by, bx, vec3_neg(nz), blue) &&
         tiny_add_quad(s, vec3_add(bc, vec3_make(0, 0.6f, 0)), bx, bz, vec3_make(0, 1, 0), blue);
    sphere sp = {vec3_make(0.45f, 0.35f, 0.25f), 0.35f, white};
    ok = ok && scene_add_sphere(s, sp) >= 0;
    set_camera(s, vec3_make(0, 1, 3.5f), vec3_make(0, 1, 0), 40.0f);
    return ok;
}

bool tiny_scene_stripes(scene *s)
{
    memset(s, 0, sizeof *s);
    int grey = scene_add_material(s, material_make(rgb_gray(0.0f), rgb_gray(1.0f)));
    int red = scene_add_material(s, material_make(rgb_gray(0.0f), rgb_make(1, 0, 0)));
    int green = scene_add_material(s, material_make(rgb_gray(0.0f), rgb_make(0, 1, 0)));
    if (grey < 0 || red < 0 || green < 0)
        return false;
    vec3 towards_camera = vec3_make(0, 0, 1), tall = vec3_make(0, 2, 0);
    /* Film x maps linearly onto the wall: x_world = 2 fx - 1; a pixel of a 32-wide image is 1/16. */
    bool ok = tiny_add_quad(s, vec3_make(-0.5f, 0, -1), vec3_make(1, 0, 0), tall, towards_camera, grey);
    const int stripes = 64;  /* over x in [0, 1]: four per pixel */
    for (int i = 0; ok && i < stripes; i++) {
        float w = 1.0f / stripes;
        ok = tiny_add_quad(s, vec3_make((i + 0.5f) * w, 0, -1), vec3_make(w, 0, 0), tall, towards_camera,
                           i % 2 == 0 ? red : green);
    }
    set_camera(s, vec3_make(0, 0, 0), vec3_make(0, 0, -1), 90.0f);
    return ok;
}

bool tiny_floor_hit(const render_ctx *ctx, float x, float z, ray *r, hit *h)
{
    *r = ray_make(vec3_make(x, 0.5f, z), vec3_make(0, -1, 0), 0.0f, INFINITY);
    return render_intersect(ctx, r, h);
}

void tiny_scene_translate(scene *s, vec3 t)
{
    for (int i = 0; i < s->num_triangles; i++) {
        triangle *tr = &s->triangles[i];
        tr->p0 = vec3_add(tr->p0, t), tr->p1 = vec3_add(tr->p1, t), tr->p2 = vec3_add(tr->p2, t);
    }
    for (int i = 0; i < s->num_spheres; i++) s->spheres[i].center = vec3_add(s->spheres[i].center, t);
    for (int i = 0; i < s->num_lights; i++) {
        light *l = &s->lights[i];
        /* An area light is made again: its offset terms depend on where it is (spawn.h). */
        if (l->kind == LIGHT_AREA)
            *l = light_make_area(vec3_add(l->position, t), l->edge_u, l->edge_v, l->direction, l->radiance);
        else
            l->position = vec3_add(l->position, t);
    }
}

void tiny_hit_push_behind(const ray *r, hit *h, float fraction)
{
    vec3 n = vec3_dot(h->ng, r->d) > 0.0f ? h->ng : vec3_neg(h->ng);  /* away from r's origin */
    vec3 abs_n = vec3_make(fabsf(n.x), fabsf(n.y), fabsf(n.z));
    h->p = vec3_add(h->p, vec3_scale(n, fraction * vec3_dot(abs_n, h->p_err)));
}
