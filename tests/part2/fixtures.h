/* Test machinery: not part of any assignment.
 * What part 2's tests share: the shipped scenes, random triangle soups, a reference tree. The BVH's
 * invariants are checked by the framework's one validator, bvh_validate (framework/bvh.h). */
#ifndef PL_PART2_FIXTURES_H
#define PL_PART2_FIXTURES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "../../framework/scene.h"
#include "../../parts/part2_bvh/part2.h"

/* Calls visit on every .dae file under scenes/ (one folder deep), in sorted order, each loaded and
 * freed afterwards; tests run from the repository root. Fails the current test when there are no
 * scenes or one does not load (with the loader's message). */
void fixture_for_each_scene(void (*visit)(const scene *s, const char *path));

/* A soup of n primitives in about [-1, 1]^3 from the seed: triangles small, large, long and thin,
 * axis-aligned (flat boxes), degenerate (collinear, repeated or identical vertices), duplicated,
 * and a few spheres. Material 0 exists. */
void fixture_random_soup(scene *s, int n, uint64_t seed);

/* A plain median-split BVH (sort by centroid along the longest axis, halve), independent of
 * bvh_build, so the traversal tasks can be tested on a valid tree whatever state task 2.2 is in.
 * Release with bvh_free. Fails the current test without memory. */
void fixture_build_median(bvh *out, const scene *s, int max_leaf_size);

#endif
