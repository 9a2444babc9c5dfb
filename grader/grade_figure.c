/* Grader machinery: not part of any assignment. Figures shown to a student: grade_figure.h. */
#include "grade_figure.h"
#include <math.h>

double grade_figure(double x, int digits, double lo, double hi)
{
    if (isnan(x)) return x;
    x = fmin(fmax(x, lo), hi);
    if (fabs(x) < GRADE_FIGURE_FLOOR) return 0.0;
    /* Round in decimal: the scale is a power of ten, so 0.0123 keeps 0.0123, not its binary
     * neighbour's longer expansion; then clamp again, as rounding may step past a bound. */
    double scale = pow(10.0, digits - 1 - (int)floor(log10(fabs(x))));
    return fmin(fmax(round(x * scale) / scale, lo), hi);
}

long grade_figure_count(long count, long pixels)
{
    return (long)grade_figure((double)count, GRADE_FIGURE_DIGITS, 0.0, (double)(pixels > 0 ? pixels : 0));
}

int grade_figure_pixel(int coordinate, int size)
{
    return coordinate < 0 ? 0 : coordinate >= size ? (size > 0 ? size - 1 : 0) : coordinate;
}
