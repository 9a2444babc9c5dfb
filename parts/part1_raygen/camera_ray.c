/* Part 1, task 1.1: camera rays. */
#include "part1.h"
#include "../../framework/todo.h"
#include <math.h>

/* === PART 1 | TASK 1.1 | camera_generate_ray =========================================
 * The ray from the camera through film point (x, y) (handout/part1.md, section 1.1).
 * In:  c (camera_to_world, position, hfov and vfov in degrees, znear, zfar);
 *      x, y in [0,1], (0,0) = bottom-left of the image, (0.5, 0.5) = its centre.
 * Out: a ray from c->position through the sensor point (tan(hfov/2) (2x-1), tan(vfov/2) (2y-1), -1)
 *      of camera space, turned into world space; unit direction; min_t = znear, max_t = zfar.
 * Must: the centre ray runs along the camera's -Z axis; the corners pass through the edges of the
 *       field of view.
 * Test: make test-part1
 * ====================================================================================== */
ray camera_generate_ray(const camera *c, float x, float y)
{
    /* BEGIN SOLUTION */
    vec3 sensor = vec3_make(tanf(deg_to_rad(0.5f * c->hfov)) * (2.0f * x - 1.0f),
                            tanf(deg_to_rad(0.5f * c->vfov)) * (2.0f * y - 1.0f), -1.0f);
    vec3 d = vec3_normalize(mat4_dir(c->camera_to_world, sensor));
    return ray_make(c->position, d, c->znear, c->zfar);
    /* END SOLUTION */
    /* STUB: return PL_TODO_RAY("1.1", "camera_generate_ray"); */
}
