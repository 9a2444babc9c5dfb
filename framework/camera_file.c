/* CS184 camera settings files: six lines of whitespace-separated numbers.
 *
 * The file is untrusted input like a scene: it is read whole through file_read_all (which refuses
 * FIFOs, devices and oversized files before reading), every number must be finite, and the values
 * must describe a camera that can render something. A camera that cannot (a zero rotation, znear past
 * zfar) would otherwise give an all-black image and exit 0, which hides the mistake. */
#include "camera_file.h"
#include "file.h"
#include "dae.h"  /* DAE_MAX_COORD: the scene's bound on coordinates, the camera's too */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A settings file is six short lines; 64 KB leaves room for comments-free padding and CRLF endings
 * while refusing anything that is clearly not a camera file. */
#define CAMERA_FILE_MAX_BYTES (64 * 1024)

/* CS184 writes the rotation with the stream's default 6 significant digits, so a saved rotation is
 * orthonormal only to about 1e-6. 1e-3 accepts every saved file and hand-edited values like 0.7071,
 * and still refuses a matrix that scales, shears or is all zero. */
#define ROTATION_TOLERANCE 1e-3

/* Reads exactly `count` finite numbers from the line starting at *cursor into out[], and moves
 * *cursor past that line. */
static pl_status read_line(const char **cursor, const char *path, int line, const char *what, int count,
                           float *out, pl_diag *d)
{
    const char *p = *cursor;
    if (*p == '\0')
        return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), found the end of the file", path, line, count, what);
    const char *eol = strchr(p, '\n');
    if (!eol) eol = p + strlen(p);
    for (int k = 0; k < count; k++) {
        /* strtof skips newlines too: stop it from taking a number from the next line. */
        while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r')) p++;
        char *end;
        errno = 0;
        out[k] = p < eol ? strtof(p, &end) : 0.0f;
        if (p == eol || end == p || end > eol || errno)
            return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), number %d is missing or not a number",
                           path, line, count, what, k + 1);
        if (!isfinite(out[k]))
            return pl_fail(d, PL_ERR_INVALID, "%s:%d: expected finite numbers (%s), got %g as number %d",
                           path, line, what, out[k], k + 1);
        p = end;
    }
    while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r')) p++;
    if (p != eol)
        return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected %d numbers (%s), found more: '%.20s'", path, line, count, what, p);
    *cursor = *eol ? eol + 1 : eol;
    return PL_OK;
}

/* After the sixth line only blank lines may follow: anything else is a file of another format or
 * a seventh line the reader would silently drop. `line` is the number of the line at p. */
static pl_status check_end(const char *p, const char *path, int line, pl_diag *d)
{
    for (; *p == ' ' || *p == '\t' || *p == '\r' || *p == '\n'; p++) line += *p == '\n';
    if (*p == '\0') return PL_OK;
    size_t n = strcspn(p, "\r\n");
    return pl_fail(d, PL_ERR_PARSE, "%s:%d: expected the end of the file after six lines, found '%.*s'", path, line,
                   (int)(n > 20 ? 20 : n), p);
}

/* Line 2: the position and target within the scene's bound (dae.h): a finite 1e38 would leave no
 * float precision for the rays and render black. */
static pl_status check_pose(const char *path, const float pose[6], pl_diag *d)
{
    for (int k = 0; k < 6; k++)
        if (!(fabsf(pose[k]) <= DAE_MAX_COORD))
            return pl_fail(d, PL_ERR_INVALID, "%s:2: expected coordinates within +-%g (position xyz, target xyz), got %g "
                           "as number %d", path, (double)DAE_MAX_COORD, pose[k], k + 1);
    return PL_OK;
}

/* Line 1: both fields of view in (0, 180) degrees, a positive aspect, 0 < znear < zfar. */
static pl_status check_lens(const char *path, const float lens[5], pl_diag *d)
{
    if (!(lens[0] > 0 && lens[0] < 180 && lens[1] > 0 && lens[1] < 180))
        return pl_fail(d, PL_ERR_INVALID, "%s:1: expected fields of view in (0, 180) degrees, got %g and %g", path, lens[0], lens[1]);
    if (!(lens[2] > 0))
        return pl_fail(d, PL_ERR_INVALID, "%s:1: expected a positive aspect ratio, got %g", path, lens[2]);
    if (!(lens[3] > 0 && lens[3] < lens[4]))
        return pl_fail(d, PL_ERR_INVALID, "%s:1: expected 0 < near < far, got near %g and far %g", path, lens[3], lens[4]);
    return PL_OK;
}

/* Line 4: a rotation has orthonormal rows (R R^T = I) and determinant +1 (not a mirror). */
static pl_status check_rotation(const char *path, const float r[9], pl_diag *d)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double dot = (double)r[3 * i] * r[3 * j] + (double)r[3 * i + 1] * r[3 * j + 1] + (double)r[3 * i + 2] * r[3 * j + 2];
            double want = i == j ? 1.0 : 0.0;
            if (fabs(dot - want) > ROTATION_TOLERANCE)
                return pl_fail(d, PL_ERR_INVALID,
                               "%s:4: expected a rotation (orthonormal rows, within %g), got rows %d and %d with dot product %g",
                               path, ROTATION_TOLERANCE, i + 1, j + 1, dot);
        }
    double det = (double)r[0] * ((double)r[4] * r[8] - (double)r[5] * r[7]) -
                 (double)r[1] * ((double)r[3] * r[8] - (double)r[5] * r[6]) +
                 (double)r[2] * ((double)r[3] * r[7] - (double)r[4] * r[6]);
    if (det < 0)
        return pl_fail(d, PL_ERR_INVALID, "%s:4: expected a rotation (determinant +1), got determinant %g (a mirror)", path, det);
    return PL_OK;
}

pl_status camera_file_load(const char *path, camera *out, pl_diag *d)
{
    char *text;
    size_t len;
    pl_status s = file_read_all(path, "camera settings", CAMERA_FILE_MAX_BYTES, &text, &len, d);
    if (s != PL_OK) return s;
    if (strlen(text) != len) {
        free(text);
        return pl_fail(d, PL_ERR_PARSE, "%s: expected a text file of numbers, found a NUL byte", path);
    }
    float lens[5], pose[6], orbit[5], rot[9], screen[3], focus[2];
    const char *cursor = text;
    s = read_line(&cursor, path, 1, "hfov vfov aspect near far", 5, lens, d);
    if (s == PL_OK) s = read_line(&cursor, path, 2, "position xyz, target xyz", 6, pose, d);
    if (s == PL_OK) s = read_line(&cursor, path, 3, "phi theta r min_r max_r", 5, orbit, d);
    if (s == PL_OK) s = read_line(&cursor, path, 4, "camera-to-world rotation, 9 entries", 9, rot, d);
    if (s == PL_OK) s = read_line(&cursor, path, 5, "screen_w screen_h screen_dist", 3, screen, d);
    if (s == PL_OK) s = read_line(&cursor, path, 6, "focal_distance lens_radius", 2, focus, d);
    if (s == PL_OK) s = check_end(cursor, path, 7, d);
    free(text);
    if (s == PL_OK) s = check_lens(path, lens, d);
    if (s == PL_OK) s = check_pose(path, pose, d);
    if (s == PL_OK) s = check_rotation(path, rot, d);
    if (s == PL_OK && !(focus[0] > 0 && focus[0] <= DAE_MAX_COORD))
        s = pl_fail(d, PL_ERR_INVALID, "%s:6: expected a focal distance in (0, %g], got %g", path, (double)DAE_MAX_COORD,
                    focus[0]);
    if (s == PL_OK && !(focus[1] >= 0))
        s = pl_fail(d, PL_ERR_INVALID, "%s:6: expected a lens radius >= 0, got %g", path, focus[1]);
    if (s != PL_OK) return s;

    *out = camera_from_cs184_settings(lens, pose, rot, focus);
    return PL_OK;
}
