/* 4x4 affine transforms for scene loading (node transforms, camera pose).
 * Row-major storage m[row][col], acting on column vectors: p' = M p.
 * Parts may not call: none of these (every function here is marked PL_PART_API). */
#ifndef PL_MAT4_H
#define PL_MAT4_H

#include "part_api.h"

#include <stdbool.h>
#include "vec.h"

typedef struct { float m[4][4]; } mat4;

PL_PART_API mat4 mat4_identity(void);
PL_PART_API mat4 mat4_mul(mat4 a, mat4 b);                     /* a * b: apply b first, then a */
PL_PART_API mat4 mat4_translate(vec3 t);
PL_PART_API mat4 mat4_scale(vec3 s);
PL_PART_API mat4 mat4_rotate(vec3 axis, float degrees);        /* right-handed, about a unit-or-not axis */
PL_PART_API mat4 mat4_lookat(vec3 eye, vec3 target, vec3 up);  /* camera-to-world: looks down local -Z */
PL_PART_API mat4 mat4_from_basis(vec3 x, vec3 y, vec3 z, vec3 origin);  /* columns: local axes and origin */
PL_PART_API mat4 mat4_transpose(mat4 a);
PL_PART_API bool mat4_inverse(mat4 a, mat4 *out);              /* false when singular */
PL_PART_API vec3 mat4_point(mat4 a, vec3 p);                   /* w = 1 */
PL_PART_API vec3 mat4_dir(mat4 a, vec3 v);                     /* w = 0 */
PL_PART_API vec3 mat4_normal(mat4 a, vec3 n);                  /* inverse-transpose, normalised */

#endif
