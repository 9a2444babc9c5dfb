/* 4x4 affine transforms: row-major, column vectors (p' = M p). Only the loader and the camera use
 * them, once per node or scene, so clarity wins over speed: no SIMD, no special cases. */
#include "mat4.h"
#include <math.h>

/* ---- building transforms ----------------------------------------------------------------------- */

mat4 mat4_identity(void)
{
    mat4 r = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return r;
}

/* (a b)[i][j] = sum_k a[i][k] b[k][j]: applying the product applies b first. */
mat4 mat4_mul(mat4 a, mat4 b)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0.0f;
            for (int k = 0; k < 4; k++) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

/* Translation and scale are both a basis and an origin: the unit axes moved to t, or the axes
 * stretched by s about the origin. */
mat4 mat4_translate(vec3 t)
{
    return mat4_from_basis(vec3_make(1, 0, 0), vec3_make(0, 1, 0), vec3_make(0, 0, 1), t);
}

mat4 mat4_scale(vec3 s)
{
    return mat4_from_basis(vec3_make(s.x, 0, 0), vec3_make(0, s.y, 0), vec3_make(0, 0, s.z), vec3_make(0, 0, 0));
}

/* Rodrigues' rotation formula as a matrix. */
mat4 mat4_rotate(vec3 axis, float degrees)
{
    vec3 a = vec3_normalize(axis);
    float rad = deg_to_rad(degrees);
    float c = cosf(rad), s = sinf(rad), k = 1.0f - c;
    mat4 r = mat4_identity();
    r.m[0][0] = a.x * a.x * k + c;
    r.m[0][1] = a.x * a.y * k - a.z * s;
    r.m[0][2] = a.x * a.z * k + a.y * s;
    r.m[1][0] = a.y * a.x * k + a.z * s;
    r.m[1][1] = a.y * a.y * k + c;
    r.m[1][2] = a.y * a.z * k - a.x * s;
    r.m[2][0] = a.z * a.x * k - a.y * s;
    r.m[2][1] = a.z * a.y * k + a.x * s;
    r.m[2][2] = a.z * a.z * k + c;
    return r;
}

/* A camera's pose: a right-handed frame whose -Z points from eye to target, with up as close to +Y
 * as that allows (up need not be perpendicular to the view direction). */
mat4 mat4_lookat(vec3 eye, vec3 target, vec3 up)
{
    vec3 back = vec3_normalize(vec3_sub(eye, target));  /* local +Z: the camera looks down -Z */
    vec3 right = vec3_normalize(vec3_cross(up, back));
    return mat4_from_basis(right, vec3_cross(back, right), back, eye);
}

/* The columns of a transform are the images of the axes and of the origin. */
mat4 mat4_from_basis(vec3 x, vec3 y, vec3 z, vec3 origin)
{
    mat4 r = mat4_identity();
    vec3 cols[4] = {x, y, z, origin};
    for (int j = 0; j < 4; j++) {
        r.m[0][j] = cols[j].x;
        r.m[1][j] = cols[j].y;
        r.m[2][j] = cols[j].z;
    }
    return r;
}

/* ---- inverting and applying ---------------------------------------------------------------------- */

mat4 mat4_transpose(mat4 a)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) r.m[i][j] = a.m[j][i];
    return r;
}

/* Gauss-Jordan elimination with partial pivoting, in double for stability. */
bool mat4_inverse(mat4 a, mat4 *out)
{
    /* The augmented matrix [a | I]: row operations that turn a into I turn I into a^-1. */
    double m[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            m[i][j] = a.m[i][j];
            m[i][j + 4] = (i == j) ? 1.0 : 0.0;
        }
    for (int col = 0; col < 4; col++) {
        /* The largest pivot left in this column keeps the division well conditioned; none at all
         * (to 1e-12) means a singular transform, e.g. a scale by 0 in a scene file. */
        int pivot = col;
        for (int i = col + 1; i < 4; i++)
            if (fabs(m[i][col]) > fabs(m[pivot][col])) pivot = i;
        if (fabs(m[pivot][col]) < 1e-12) return false;
        for (int j = 0; j < 8; j++) {
            double t = m[col][j];
            m[col][j] = m[pivot][j];
            m[pivot][j] = t;
        }
        /* Normalise the pivot row, then clear the column from every other row. */
        double inv = 1.0 / m[col][col];
        for (int j = 0; j < 8; j++) m[col][j] *= inv;
        for (int i = 0; i < 4; i++) {
            if (i == col) continue;
            double f = m[i][col];
            for (int j = 0; j < 8; j++) m[i][j] -= f * m[col][j];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) out->m[i][j] = (float)m[i][j + 4];
    return true;
}

/* A point moves with the translation column (w = 1); a direction does not (w = 0). */
vec3 mat4_point(mat4 a, vec3 p)
{
    return vec3_make(a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z + a.m[0][3],
                     a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z + a.m[1][3],
                     a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z + a.m[2][3]);
}

vec3 mat4_dir(mat4 a, vec3 v)
{
    return vec3_make(a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
                     a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
                     a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z);
}

/* Normals transform by the inverse transpose, so they stay perpendicular to surfaces under a
 * non-uniform scale; a singular transform (no inverse) falls back to the matrix itself. */
vec3 mat4_normal(mat4 a, vec3 n)
{
    mat4 inv;
    if (!mat4_inverse(a, &inv)) return vec3_normalize(mat4_dir(a, n));
    return vec3_normalize(mat4_dir(mat4_transpose(inv), n));
}
