/* CS184 camera settings files: six lines of whitespace-separated numbers. */
#include "camera_file.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Reads exactly `count` numbers from one line of f into out[]. */
static pl_status read_line(FILE *f, const char *path, int line, const char *what, int count, float *out, pl_diag *d)
{
    char buf[1024];
    if (!fgets(buf, sizeof buf, f))
        return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), found the end of the file", path, line, count, what);
    char *p = buf;
    for (int k = 0; k < count; k++) {
        char *end;
        errno = 0;
        out[k] = strtof(p, &end);
        if (end == p || errno)
            return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), number %d is missing or not a number",
                           path, line, count, what, k + 1);
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') p++;
    if (*p != '\0')
        return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), found more: '%.20s'", path, line, count, what, p);
    return PL_OK;
}

pl_status camera_file_load(const char *path, camera *out, pl_diag *d)
{
    FILE *f = fopen(path, "r");
    if (!f) return pl_fail(d, PL_ERR_IO, "%s: cannot open camera settings: %s", path, strerror(errno));
    float lens[5], pose[6], orbit[5], rot[9], screen[3], focus[2];
    pl_status s = read_line(f, path, 1, "hfov vfov aspect near far", 5, lens, d);
    if (s == PL_OK) s = read_line(f, path, 2, "position xyz, target xyz", 6, pose, d);
    if (s == PL_OK) s = read_line(f, path, 3, "phi theta r min_r max_r", 5, orbit, d);
    if (s == PL_OK) s = read_line(f, path, 4, "camera-to-world rotation, 9 entries", 9, rot, d);
    if (s == PL_OK) s = read_line(f, path, 5, "screen_w screen_h screen_dist", 3, screen, d);
    if (s == PL_OK) s = read_line(f, path, 6, "focal_distance lens_radius", 2, focus, d);
    fclose(f);
    if (s != PL_OK) return s;
    if (!(lens[0] > 0 && lens[0] < 180 && lens[1] > 0 && lens[1] < 180))
        return pl_fail(d, PL_ERR_INVALID, "%s:1: expected fields of view in (0, 180) degrees, got %g and %g", path, lens[0], lens[1]);

    camera c;
    memset(&c, 0, sizeof c);
    c.camera_to_world = mat4_identity();
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++) c.camera_to_world.m[row][col] = rot[3 * row + col];
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
    *out = c;
    return PL_OK;
}
