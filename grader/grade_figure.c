/* Grader machinery: not part of any assignment. Figures shown to a student: grade_figure.h. */
#include "grade_figure.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Appends text (n bytes) to out if it fits whole; false when it does not. */
static bool append(char *out, size_t size, size_t *used, const char *text, size_t n)
{
    if (*used + n + 1 > size) return false;
    memcpy(out + *used, text, n);
    *used += n;
    out[*used] = '\0';
    return true;
}

void grade_figure_text(const char *in, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (const char *p = in; *p;) {
        /* A number starts at a digit that does not continue a name ("part1", "vec3") or a number. */
        bool starts = isdigit((unsigned char)*p) &&
                      (p == in || !(isalnum((unsigned char)p[-1]) || p[-1] == '_' || p[-1] == '.'));
        if (!starts) {
            size_t n = 1;
            while ((p[n] & 0xC0) == 0x80) n++;  /* a whole character, never half of one */
            if (!append(out, size, &used, p, n)) return;
            p += n;
            continue;
        }
        char shown[48];
        const char *end;
        if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
            end = p + 2;
            while (isxdigit((unsigned char)*end)) end++;
            if (end - p > 6) snprintf(shown, sizeof shown, "0x...");
            else snprintf(shown, sizeof shown, "%.*s", (int)(end - p), p);
        }
        else {
            char *stop;
            double x = strtod(p, &stop);
            end = stop;
            size_t whole = strspn(p, "0123456789");
            bool wide = (size_t)(end - p) != whole || whole > 4;
            double rounded = grade_figure(x, GRADE_FIGURE_DIGITS, -1e300, 1e300);
            /* A count stays a count: 20000 rays, 11300 pixels, not 2e+04 (the same digits kept). */
            if (wide && (size_t)(end - p) == whole && whole <= 9) snprintf(shown, sizeof shown, "%.0f", rounded);
            else if (wide) snprintf(shown, sizeof shown, "%.*g", GRADE_FIGURE_DIGITS, rounded);
            else snprintf(shown, sizeof shown, "%.*s", (int)(end - p), p);
        }
        if (!append(out, size, &used, shown, strlen(shown))) return;
        p = end;
    }
}
