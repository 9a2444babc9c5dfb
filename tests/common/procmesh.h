/* Test machinery and benchmark: not part of any assignment.
 * Procedural triangle meshes of any size, deterministic, for the BVH tests and `make bench`. */
#ifndef PL_PROCMESH_H
#define PL_PROCMESH_H

#include "../../framework/scene.h"
#include "../../framework/status.h"

/* Rows of latitude of the bumpy sphere with about `triangles` triangles (4 rows^2 of them). */
int procmesh_rows_for(long triangles);

/* Appends a bumpy sphere to s: a latitude-longitude grid of `rows` rows and 2 * rows columns
 * (4 rows^2 triangles, face normals, material mat), radius varying by about 15% with a sum of
 * sines so that neighbouring triangles face different ways. The mesh is watertight; the rows at
 * the poles hold 2 * rows zero-area triangles (a quad with two vertices at the pole), on purpose:
 * they are the degenerate case a BVH must survive. PL_ERR_NOMEM leaves s with part of the mesh. */
pl_status procmesh_bumpy_sphere(scene *s, int rows, vec3 center, float radius, int mat);

#endif
