/* Procedural triangle meshes of any size, deterministic, for the BVH tests and `make bench`: scenes
 * built by code, in the framework so that the tests and the benchmark share them. Not part of any
 * assignment.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_PROCMESH_H
#define PL_PROCMESH_H

#include "scene.h"
#include "status.h"

/* Rows of latitude of the bumpy sphere with about `triangles` triangles (4 rows^2 of them). */
int procmesh_rows_for(long triangles);

/* Appends a bumpy sphere to s: a latitude-longitude grid of `rows` rows and 2 * rows columns
 * (4 rows^2 triangles, face normals, material mat), radius varying by about 15% with a sum of
 * sines so that neighbouring triangles face different ways. The mesh is watertight; the rows at
 * the poles hold 2 * rows zero-area triangles (a quad with two vertices at the pole), on purpose:
 * they are the degenerate case a BVH must survive. PL_ERR_NOMEM leaves s with part of the mesh. */
pl_status procmesh_bumpy_sphere(scene *s, int rows, vec3 center, float radius, int mat);

#endif
