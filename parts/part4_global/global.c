/* Part 4 placeholder: the solution is being written. */
#include "part4.h"
#include "../../framework/todo.h"

rgb at_least_one_bounce_radiance(const struct render_ctx *ctx, const ray *r, const hit *h, rng *g)
{
    return PL_TODO_RGB("4.1", "at_least_one_bounce_radiance");
}
