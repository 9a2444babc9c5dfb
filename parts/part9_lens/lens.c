/* Part 9, tasks 9.1 and 9.2: the thin lens. */
#include "part9.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 9 | TASK 9.1 | lens_sample_disk =============================================
 * A point of the unit disc, uniform in area (handout/part9.md, section 9.1).
 * In:  u in [0,1)^2, uniform.
 * Out: a point p with |p| <= 1; over uniform u, every region of the disc is hit in proportion to
 *      its area.
 * Must: not r = u.x (that crowds the centre: a ring's area grows with its radius), and not a
 *       square: points outside the disc would be a lens larger than the camera's.
 * Test: make test-part9
 * ====================================================================================== */
vec2 lens_sample_disk(vec2 u)
{
    /* BEGIN SOLUTION */
    /* The fraction of the disc's area within radius r is r^2: r = sqrt(u.x) inverts it. */
    float r = sqrtf(u.x), phi = 2.0f * PL_PI * u.y;
    return vec2_make(r * cosf(phi), r * sinf(phi));
    /* END SOLUTION */
    /* STUB: return PL_TODO_VEC2("9.1", "lens_sample_disk"); */
}

/* === PART 9 | TASK 9.2 | thin_lens_ray ================================================
 * The ray of one sample through the thin lens (handout/part9.md, section 9.2).
 * In:  camera c (camera_to_world, position, lens_radius R > 0, focal_distance D);
 *      pinhole: the sample's ray from part 1 (origin c->position, unit direction);
 *      u in [0,1)^2 for the lens point.
 * Out: the ray from the lens point c->position + R (p.x X + p.y Y), p = lens_sample_disk(u) and X,
 *      Y the camera's local axes in world space, through the point where the pinhole ray meets
 *      the plane of focus (distance D in front of the camera along its view axis, local -Z);
 *      unit direction; min_t and max_t those of the pinhole ray.
 * Must: with R = 0 the ray is the pinhole ray; every lens ray of one film point meets the others
 *       on the plane of focus, which is therefore sharp.
 * Test: make test-part9
 * ====================================================================================== */
ray thin_lens_ray(const camera *c, ray pinhole, vec2 u)
{
    /* BEGIN SOLUTION */
    vec3 forward = mat4_dir(c->camera_to_world, vec3_make(0.0f, 0.0f, -1.0f));
    /* The pinhole ray reaches the plane of focus after D / cos(angle to the view axis). */
    vec3 focus = ray_at(&pinhole, c->focal_distance / vec3_dot(pinhole.d, forward));
    vec2 p = lens_sample_disk(u);
    vec3 on_lens = mat4_dir(c->camera_to_world, vec3_make(c->lens_radius * p.x, c->lens_radius * p.y, 0.0f));
    vec3 o = vec3_add(c->position, on_lens);
    return ray_make(o, vec3_normalize(vec3_sub(focus, o)), pinhole.min_t, pinhole.max_t);
    /* END SOLUTION */
    /* STUB: return PL_TODO_RAY("9.2", "thin_lens_ray"); */
}
