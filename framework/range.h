/* Sample ranges: a render split into `--samples A:B` pieces (on several machines, or a Slurm
 * array) and merged back with `pathtracer --merge` into the same bytes as the render of 0..N.
 *
 * What makes it exact: sample s of a pixel draws only from render_rng(seed, pixel, s), whatever
 * range it is rendered in, and the film adds samples in fixed point (film.h), so the sums of the
 * pieces add up to the sums of the whole, bit for bit. What the merge checks: every piece has the
 * same render key (a hash of everything that changes the image: code version, scene and camera
 * file contents, the flags, the resolution, the seed) and the ranges tile 0..N, with no gap and no
 * overlap.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_RANGE_H
#define PL_RANGE_H

#include "options.h"
#include "exr.h"

/* The EXR provenance of a render with options o: normalised command, render key, version, seed
 * and the sample range. Reads the scene (and camera) file to hash them. */
pl_status range_info(const options *o, exr_info *info, pl_diag *diag);

/* The same with another code version in the key and the record: the grader recomputes a
 * reference's key from the version the reference records (grader/grade_refs.c says why). */
pl_status range_info_as(const options *o, const char *version, exr_info *info, pl_diag *diag);

/* `pathtracer --merge -f OUT IN1.exr IN2.exr ...`, its options in any order (argv holds "--merge"
 * somewhere). Every input is checked as exr_read does (exr.h), the headers of all of them first; the
 * pieces must agree on every provenance field (command, seed, version, size, sample total, render
 * key; the first that differs is named) and tile 0..N. Returns the exit status (0 merged, 2
 * refused: bad arguments, unreadable, malformed, mismatched, overlapping or missing ranges). */
int range_merge_main(int argc, char **argv, const char *prog);

#endif
