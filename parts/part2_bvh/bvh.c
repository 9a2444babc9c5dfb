/* Part 2 placeholder: the solution is being written. */
#include "part2.h"
#include "../../framework/todo.h"

bool aabb_intersect(const aabb *b, const ray *r, float *t_enter, float *t_exit)
{
    /* STUB: return PL_TODO_FALSE("2.1", "aabb_intersect"); */
    return PL_TODO_FALSE("2.1", "aabb_intersect");
}
pl_status bvh_build(bvh *out, const scene *s, int max_leaf_size)
{
    return PL_TODO("2.2", "bvh_build");
}
bool bvh_intersect(const bvh *b, const scene *s, ray *r, hit *h)
{
    return PL_TODO_FALSE("2.3", "bvh_intersect");
}
bool bvh_occluded(const bvh *b, const scene *s, const ray *r)
{
    return PL_TODO_FALSE("2.4", "bvh_occluded");
}
