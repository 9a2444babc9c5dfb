/* The camera: its type and every way the framework sets one up. This is the camera's one home: the
 * COLLADA loader, the -c settings file, the default framing and the render all build or adjust a
 * camera through these functions, so a rule (how one fov follows from the other, which lens a render
 * uses) is written once.
 *
 * How a render's camera comes about (camera_for_render): the scene's camera (from its file, or
 * replaced by a -c settings file), or the default framing when the scene has none; then either
 * CS184's orbit framing (camera_uses_cs184_framing: --camera cs184, or by default a file in the
 * course's profile) or the image's aspect ratio; then the -b / -d lens flags, only when they were
 * given.
 * Parts may not call: any function declared here but the static inline ones (the grader refuses them). */
#ifndef PL_CAMERA_H
#define PL_CAMERA_H

#include <stdbool.h>
#include "vec.h"
#include "mat4.h"
#include "aabb.h"
#include "options.h"
#include <stddef.h>

/* CS184's lens when nothing sets one: a pinhole (radius 0) focused at 4.7 m (its -d default). */
#define CAMERA_DEFAULT_LENS_RADIUS 0.0f
#define CAMERA_DEFAULT_FOCAL_DISTANCE 4.7f

/* A pinhole camera. It looks down its local -Z with local +Y up (COLLADA's convention). */
typedef struct camera {
    mat4 camera_to_world;  /* rigid transform: rotation + translation, no scale */
    vec3 position;         /* camera_to_world applied to the origin */
    float hfov, vfov;      /* full horizontal and vertical field of view, degrees */
    float znear, zfar;     /* camera rays span [znear, zfar] */
    float lens_radius;     /* thin lens, metres (not used by parts 1-5) */
    float focal_distance;  /* thin lens, metres (not used by parts 1-5) */
    bool fov_is_vertical;  /* which fov the file fixed: the other follows the image aspect */
    /* The side CS184's framing puts the eye on: the unit direction from the orbit's target to the
     * eye. For a COLLADA camera the course's c_dir = normalize(M (0, 0, -1, 1)), its node's matrix
     * (up axis included) applied to the POINT (0, 0, -1), translation and scale included, in the
     * file's coordinates (dae_light.c); zero when none was set (a -c file, the default framing, a
     * camera whose point is the origin): then the opposite of the view direction. */
    vec3 orbit_dir;
} camera;

/* The one fov-from-extent formula: the field of view (degrees) whose sensor half-width
 * tan(fov/2) is num / den times that of fov_deg. Both fovs of a camera are tied by it through the
 * aspect ratio, and CS184's framing crops or extends its 800x600 view with it. */
float camera_fov_scaled(float fov_deg, float num, float den);

/* The fov the camera did not fix (see fov_is_vertical) follows aspect = width / height. */
void camera_set_aspect(camera *c, float aspect);

/* A COLLADA <perspective> camera at its node's transform (scale is dropped: the pose is rigid).
 * xfov / yfov in degrees, 0 when the file gives none (at least one is given); when only one is
 * given, the other follows aspect_ratio. The lens is CS184's default. */
camera camera_from_collada(mat4 node_to_world, float xfov, float yfov, float aspect_ratio, float znear,
                           float zfar);

/* The camera of a CS184 settings file, from the numbers camera_file.h read and checked: line 1
 * (hfov vfov aspect near far), line 2 (position xyz, target xyz), line 4 (the camera-to-world
 * rotation, row by row) and line 6 (focal_distance lens_radius). Its vfov is fixed and hfov follows
 * the image, as in CS184's viewer. */
camera camera_from_cs184_settings(const float lens[5], const float pose[6], const float rotation[9],
                                  const float focus[2]);

/* For scenes without a camera: CS184's Cornell box lens, looking at the centre of the bounds from
 * +Z at 1.5 x their diagonal (a unit box around the origin when the bounds are empty). */
camera camera_default_framing(aabb bounds);

/* CS184's framing (--cs184-camera): keep only the side c->orbit_dir names (camera_orbit_dir), orbit
 * the bounds' centre at 1.5 x their diagonal from there, looking at it with world +Y up, with the fov
 * fixed for an 800x600 frame that a width x height image crops or extends (the pixel scale stays, as
 * in the original's -r). */
camera camera_cs184_framing(const camera *c, aabb bounds, int width, int height);
/* The unit direction from the orbit's target to the eye under CS184's framing: c->orbit_dir, or,
 * when that is zero, the opposite of c's view direction. */
vec3 camera_orbit_dir(const camera *c);

/* The -b / -d flags: each replaces the camera's value only when it was given on the command line,
 * so a -c settings file's lens survives when they are not. Inline: the command line's warnings
 * (cli.c, linked into the grader too) ask it which lens a render will have. */
static inline void camera_apply_lens_flags(camera *c, const options *o)
{
    if (o->lens_radius_given) c->lens_radius = o->lens_radius;
    if (o->focal_distance_given) c->focal_distance = o->focal_distance;
}

/* Whether a render of s under o frames it CS184's way: --camera cs184 says so, --camera literal
 * says not, and by default a file in the course's profile (scene.course_profile, dae.h) is, unless
 * a -c settings file gives the camera (CS184 takes that camera as it is too). */
struct scene;
bool camera_uses_cs184_framing(const struct scene *s, const options *o);
/* The status line naming the camera's framing and the option that gives the other, without a
 * newline, into buf: "camera: CS184's framing (...); --camera literal for the file's own". */
void camera_framing_line(const options *o, const struct scene *s, char *buf, size_t size);

/* The camera a render of s uses under options o (the order in the comment at the top). */
camera camera_for_render(const struct scene *s, const options *o);

#endif
