/* Test machinery: not part of any assignment. */
#include "test.h"
#include <stdio.h>
#include <math.h>

static bool far(float a, float b, float eps) { return !(fabsf(a - b) <= eps); }  /* NaN is far */

void check_vec3_near(vec3 e, vec3 g, float eps, const char *what, const char *file, int line)
{
    if (far(e.x, g.x, eps) || far(e.y, g.y, eps) || far(e.z, g.z, eps)) {
        print_error("%s: wrong: expected (%.6g, %.6g, %.6g), got (%.6g, %.6g, %.6g) (tolerance %g)\n",
                    what, e.x, e.y, e.z, g.x, g.y, g.z, eps);
        _fail(file, line);
    }
}

void check_rgb_near(rgb e, rgb g, float eps, const char *what, const char *file, int line)
{
    if (far(e.r, g.r, eps) || far(e.g, g.g, eps) || far(e.b, g.b, eps)) {
        print_error("%s: wrong: expected rgb(%.6g, %.6g, %.6g), got rgb(%.6g, %.6g, %.6g) (tolerance %g)\n",
                    what, e.r, e.g, e.b, g.r, g.g, g.b, eps);
        _fail(file, line);
    }
}

void check_float_near(double e, double g, double eps, const char *what, const char *file, int line)
{
    if (!(fabs(e - g) <= eps)) {
        print_error("%s: wrong: expected %.9g, got %.9g (tolerance %g)\n", what, e, g, eps);
        _fail(file, line);
    }
}

void check_implemented(const char *file, int line)
{
    if (pl_todo_count() > 0) {
        print_error("not implemented: %s is still a stub\n", pl_todo_last() ? pl_todo_last() : "a task");
        _fail(file, line);
    }
}

int test_setup(void **state)
{
    (void)state;
    pl_todo_set_quiet(true);
    pl_todo_reset();
    return 0;
}

void check_hit(bool found, bool expected, const char *what, const char *file, int line)
{
    check_implemented(file, line);
    if (found != expected) {
        print_error("%s: wrong: expected a %s, got a %s\n", what, expected ? "hit" : "miss", found ? "hit" : "miss");
        _fail(file, line);
    }
}
