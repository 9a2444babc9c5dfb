/* Procedural meshes (procmesh.h): a bumpy sphere of any size. */
#include "procmesh.h"
#include <math.h>

/* 4 rows^2 triangles make `triangles`: rows = sqrt(triangles / 4), at least 2 for a closed mesh. */
int procmesh_rows_for(long triangles)
{
    int rows = (int)lround(sqrt((double)triangles / 4.0));
    return rows > 1 ? rows : 2;
}

/* Grid vertex (i, j): i = 0 .. rows from the north pole, j = 0 .. 2 rows around (j = 2 rows is j = 0). */
static vec3 bumpy_vertex(int rows, int i, int j, vec3 center, float radius)
{
    /* The poles are single points, so the mesh closes exactly (no sliver of rounding at the seam). */
    if (i == 0) return vec3_add(center, vec3_make(0.0f, radius, 0.0f));
    if (i == rows) return vec3_add(center, vec3_make(0.0f, -radius, 0.0f));
    int cols = 2 * rows;
    double theta = M_PI * i / rows, phi = 2.0 * M_PI * (j % cols) / cols;
    double bump = 0.08 * sin(6.0 * theta) * cos(5.0 * phi) + 0.05 * sin(17.0 * theta + 1.0) * sin(13.0 * phi) +
                  0.02 * cos(41.0 * theta) * sin(37.0 * phi + 2.0);
    double r = radius * (1.0 + bump);
    return vec3_add(center, vec3_make((float)(r * sin(theta) * cos(phi)), (float)(r * cos(theta)),
                                      (float)(r * sin(theta) * sin(phi))));
}

pl_status procmesh_bumpy_sphere(scene *s, int rows, vec3 center, float radius, int mat)
{
    int cols = 2 * rows;
    for (int i = 0; i < rows; i++) {
        for (int j = 0; j < cols; j++) {
            vec3 a = bumpy_vertex(rows, i, j, center, radius), b = bumpy_vertex(rows, i + 1, j, center, radius);
            vec3 c = bumpy_vertex(rows, i + 1, j + 1, center, radius), d = bumpy_vertex(rows, i, j + 1, center, radius);
            /* Counter-clockwise seen from outside. */
            if (scene_add_triangle(s, triangle_make(a, c, b, mat)) < 0) return PL_ERR_NOMEM;
            if (scene_add_triangle(s, triangle_make(a, d, c, mat)) < 0) return PL_ERR_NOMEM;
        }
    }
    return PL_OK;
}
