/* The camera's one home: building it (COLLADA, CS184 settings file, default framing) and adjusting
 * it for a render (aspect ratio, CS184's framing, lens flags). */
#include "camera.h"
#include "scene.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- the field of view ----------------------------------------------------------------------- */

float camera_fov_scaled(float fov_deg, float num, float den)
{
    /* The sensor sits at distance 1, so its half-width is tan(fov/2): scale that, not the angle. */
    return rad_to_deg(2.0f * atanf(tanf(deg_to_rad(fov_deg) * 0.5f) * num / den));
}

void camera_set_aspect(camera *c, float aspect)
{
    if (c->fov_is_vertical)
        c->hfov = camera_fov_scaled(c->vfov, aspect, 1.0f);
    else
        c->vfov = camera_fov_scaled(c->hfov, 1.0f, aspect);
}

/* A camera with no pose yet: every field zero, CS184's lens. */
static camera camera_blank(void)
{
    camera c;
    memset(&c, 0, sizeof c);
    c.lens_radius = CAMERA_DEFAULT_LENS_RADIUS;
    c.focal_distance = CAMERA_DEFAULT_FOCAL_DISTANCE;
    return c;
}

/* ---- building a camera ----------------------------------------------------------------------- */

/* The pose without the node's scale: camera_to_world is rigid by contract. */
static mat4 rigid(mat4 m)
{
    vec3 z = vec3_normalize(mat4_dir(m, vec3_make(0, 0, 1)));
    vec3 y = mat4_dir(m, vec3_make(0, 1, 0));
    vec3 x = vec3_normalize(vec3_cross(y, z));
    y = vec3_cross(z, x);
    return mat4_from_basis(x, y, z, mat4_point(m, vec3_make(0, 0, 0)));
}

camera camera_from_collada(mat4 node_to_world, float xfov, float yfov, float aspect_ratio, float znear,
                           float zfar)
{
    camera c = camera_blank();
    c.hfov = xfov;
    c.vfov = yfov;
    c.znear = znear;
    c.zfar = zfar;
    /* One fov given: the other follows the file's aspect ratio now, and the image's aspect may
     * change it later. Both given: the file fixed both, and the horizontal one wins later. */
    c.fov_is_vertical = xfov == 0;
    if (xfov == 0 || yfov == 0) camera_set_aspect(&c, aspect_ratio);
    c.camera_to_world = rigid(node_to_world);
    c.position = mat4_point(node_to_world, vec3_make(0, 0, 0));
    return c;
}

camera camera_from_cs184_settings(const float lens[5], const float pose[6], const float rotation[9],
                                  const float focus[2])
{
    camera c = camera_blank();
    c.camera_to_world = mat4_identity();
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++) c.camera_to_world.m[row][col] = rotation[3 * row + col];
    c.camera_to_world.m[0][3] = pose[0];
    c.camera_to_world.m[1][3] = pose[1];
    c.camera_to_world.m[2][3] = pose[2];
    c.position = vec3_make(pose[0], pose[1], pose[2]);
    c.hfov = lens[0];
    c.vfov = lens[1];
    c.fov_is_vertical = true;  /* CS184 keeps vfov and derives hfov from the window's aspect */
    c.znear = lens[3];
    c.zfar = lens[4];
    c.focal_distance = focus[0];
    c.lens_radius = focus[1];
    return c;
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

camera camera_default_framing(aabb bounds)
{
    camera base = camera_blank();
    base.hfov = 49.13434f;  /* CS184's Cornell box lens */
    base.vfov = 37.8f;
    base.znear = 1e-4f;
    base.zfar = 1e30f;
    if (aabb_is_empty(bounds)) {
        bounds.min = vec3_make(-1, -1, -1);
        bounds.max = vec3_make(1, 1, 1);
    }
    vec3 centre = aabb_centroid(bounds);
    float diag = vec3_length(aabb_extent(bounds));
    return camera_looking(&base, vec3_add(centre, vec3_make(0, 0, 1.5f * diag)), centre);
}

/* ---- adjusting it for a render --------------------------------------------------------------- */

camera camera_cs184_framing(const camera *c, aabb bounds, int width, int height)
{
    /* The original fixes the lens for its 800x600 window first. */
    camera lens = *c;
    camera_set_aspect(&lens, 800.0f / 600.0f);
    /* It keeps only a direction (c_dir, camera.h's orbit_dir) and orbits the centre of the bounds
     * at 1.5 x their diagonal, the eye on that side of it (CS184's Camera::place: target + r c_dir). */
    vec3 side = camera_orbit_dir(c);
    vec3 centre = aabb_centroid(bounds);
    float dist = 1.5f * vec3_length(aabb_extent(bounds));
    camera out = camera_looking(&lens, vec3_add(centre, vec3_scale(side, dist)), centre);
    out.znear = fminf(c->znear, dist * 1e-3f);
    out.zfar = fmaxf(c->zfar, dist * 10.0f);
    /* -r W H keeps the pixel scale: other sizes crop or extend the 800x600 view. */
    out.hfov = camera_fov_scaled(out.hfov, (float)width, 800.0f);
    out.vfov = camera_fov_scaled(out.vfov, (float)height, 600.0f);
    return out;
}

vec3 camera_orbit_dir(const camera *c)
{
    if (vec3_length(c->orbit_dir) > 0.0f) return vec3_normalize(c->orbit_dir);
    /* No course direction (a -c file, the default framing): behind the camera, so the orbit looks
     * the way the camera looks. */
    return vec3_normalize(mat4_dir(c->camera_to_world, vec3_make(0, 0, 1)));
}

bool camera_uses_cs184_framing(const scene *s, const options *o)
{
    if (o->framing != FRAMING_AUTO) return o->framing == FRAMING_CS184;
    /* The course's files put their cameras where only CS184's framing makes sense (the Cornell
     * boxes' at floor height); pathlab's own scenes, and a -c file's camera, mean theirs. */
    return s->course_profile && !o->camera_file;
}

void camera_framing_line(const options *o, const scene *s, char *buf, size_t size)
{
    bool cs184 = camera_uses_cs184_framing(s, o);
    const char *why = o->framing != FRAMING_AUTO ? "as asked"
                      : cs184                    ? "the file is in the course's profile"
                      : o->camera_file           ? "the -c file's camera"
                                                 : "the file is not in the course's profile";
    if (cs184)
        snprintf(buf, size, "camera: CS184's framing, an orbit on the scene's bounds from the side M (0,0,-1,1) of the file's camera "
                            "(%s); --camera literal for the file's own camera", why);
    else
        snprintf(buf, size, "camera: %s, as written (%s); --camera cs184 for CS184's framing",
                 s->has_camera ? "the file's camera" : "no camera in the file, the default view", why);
}

camera camera_for_render(const scene *s, const options *o)
{
    camera c = s->has_camera ? s->camera : camera_default_framing(scene_bounds(s));
    if (camera_uses_cs184_framing(s, o))
        c = camera_cs184_framing(&c, scene_bounds(s), o->width, o->height);
    else
        camera_set_aspect(&c, (float)o->width / (float)o->height);
    camera_apply_lens_flags(&c, o);
    return c;
}
