/* Attack (course/judge/split_check.sh), on part 2: bvh_build answers with a record of its own that
 * claims a tree of 2^30 nodes (and sends 8 bytes of it), then exits; the other tasks are the stubs.
 * Expected: the judge refuses the size before allocating anything, and the tests fail.
 * Graded on test_bvh_build* (the tests of the build alone).
 * part: 2
 * replaces: parts/part2_bvh/bvh.c
 * tests: test_bvh_build*
 * expect: passes=0
 */
#include "part2.h"
#include "../../framework/todo.h"
#include "../../grader/seam/seam.h"
#include <unistd.h>

bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    *t_enter = 0.0f, *t_exit = 0.0f;
    return PL_TODO_FALSE("2.1", "aabb_intersect");
}

pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    struct { seam_header h; int32_t status, num_nodes, num_prims; char tree[8]; } r = {
        {SEAM_MAGIC, SEAM_bvh_build, 0, {0, 0, 0}, 0, -1, {0, 0}, 0, 0, 0, 12 + 8}, PL_OK, 1 << 30, 0, {0}};
    /* The judge's own hash of the call (seam_part2.c), so the record reaches the size check. */
    uint64_t k = seam_hash_int(seam_hash_scene(SEAM_HASH_START, s), max_leaf_size);
    k = seam_hash(k, s->triangles, (size_t)s->num_triangles * sizeof *s->triangles);
    k = seam_hash(k, s->spheres, (size_t)s->num_spheres * sizeof *s->spheres);
    r.h.inputs = seam_hash_int(k, out != NULL);
    (void)!write(3, &r, sizeof r);
    _exit(0);
}

bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h) { return PL_TODO_FALSE("2.3", "bvh_intersect"); }
bool bvh_occluded(const bvh *b, const scene *s, const ray *r) { return PL_TODO_FALSE("2.4", "bvh_occluded"); }
