/* CS184 camera settings files (-c): the camera a course saved from the original viewer. This file
 * reads and checks the numbers; camera.c turns them into a camera.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_CAMERA_FILE_H
#define PL_CAMERA_FILE_H

#include "camera.h"
#include "status.h"

/* Reads the six lines (hfov vfov aspect near far / pos.xyz target.xyz / phi theta r min_r max_r /
 * the 9 entries of the camera-to-world rotation, row by row / screen_w screen_h screen_dist /
 * focal_distance lens_radius) into *out. The file must be a regular file of at most 64 KB; every
 * number must be finite; fovs in (0, 180), 0 < near < far, position and target within +-DAE_MAX_COORD
 * (1e18, as scene coordinates), the rotation orthonormal within 1e-3 with determinant +1, focal distance
 * in (0, 1e18], lens radius >= 0; nothing but blank lines after the sixth. Errors name the file, the line, what was expected and what was found
 * (PL_ERR_IO for an unreadable file, PL_ERR_PARSE / PL_ERR_INVALID for its content). */
pl_status camera_file_load(const char *path, camera *out, pl_diag *diag);

#endif
