/* Attack (course/judge/split_check.sh), on part 2: the course's BVH, except that bvh_occluded also
 * reports, through the framework's counters (which the grader's allow-list would refuse, and a
 * subject may call anyway), a visit to node 2^30 and a test of primitive -5. The work check of the
 * judge indexes its arrays with the trace's entries: the judge must refuse them, not write there.
 * Graded on test_bvh_occluded__counts_its_work_through_the_framework, which fails.
 * part: 2
 * replaces: parts/part2_bvh/bvh.c
 * tests: test_bvh_occluded__counts_its_work_through_the_framework
 * expect: passes=0
 */
#include "part2.h"
#include "../../framework/counters.h"

/* The course's own part 2 (split_check.sh puts a copy of bvh.c beside this file), with its
 * bvh_occluded renamed so that the one below wraps it. */
#define bvh_occluded course_bvh_occluded
#include "bvh.c.inc"
#undef bvh_occluded

bool bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    counters_add_visit(1 << 30);
    counters_add_prim(-5);
    return course_bvh_occluded(b, s, r);
}
