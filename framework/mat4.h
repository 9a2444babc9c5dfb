/* 4x4 affine transforms for scene loading (node transforms, camera pose).
 * Row-major storage m[row][col], acting on column vectors: p' = M p. */
#ifndef PL_MAT4_H
#define PL_MAT4_H

#include <stdbool.h>
#include "vec.h"

typedef struct { float m[4][4]; } mat4;

mat4 mat4_identity(void);
mat4 mat4_mul(mat4 a, mat4 b);                     /* a * b: apply b first, then a */
mat4 mat4_translate(vec3 t);
mat4 mat4_scale(vec3 s);
mat4 mat4_rotate(vec3 axis, float degrees);        /* right-handed, about a unit-or-not axis */
mat4 mat4_lookat(vec3 eye, vec3 target, vec3 up);  /* camera-to-world: looks down local -Z */
mat4 mat4_from_basis(vec3 x, vec3 y, vec3 z, vec3 origin);  /* columns: local axes and origin */
mat4 mat4_transpose(mat4 a);
bool mat4_inverse(mat4 a, mat4 *out);              /* false when singular */
vec3 mat4_point(mat4 a, vec3 p);                   /* w = 1 */
vec3 mat4_dir(mat4 a, vec3 v);                     /* w = 0 */
vec3 mat4_normal(mat4 a, vec3 n);                  /* inverse-transpose, normalised */

#endif
