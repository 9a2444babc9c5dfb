/* Grader machinery: not part of any assignment. The sample-rate map (grade_rate.h). */
#include "grade_rate.h"
#include <math.h>
#include <string.h>

/* Blocks across a side of n pixels: about n / GRADE_RATE_BLOCK, at least 1. */
static int blocks_along(int n)
{
    return n / GRADE_RATE_BLOCK > 0 ? n / GRADE_RATE_BLOCK : 1;
}

static bool shape_fits(int width, int height)
{
    return width > 0 && height > 0 && (long)blocks_along(width) * blocks_along(height) <= GRADE_RATE_MAX_BLOCKS;
}

void grade_rate_map_of(const film *f, grade_rate_map *out)
{
    memset(out, 0, sizeof *out);
    if (!shape_fits(f->width, f->height)) return;
    out->columns = blocks_along(f->width);
    out->rows = blocks_along(f->height);
    long pixels[GRADE_RATE_MAX_BLOCKS] = {0};
    for (int y = 0; y < f->height; y++)
        for (int x = 0; x < f->width; x++) {
            /* A pixel's block, proportionally: the last block of a row takes the pixels left over. */
            long b = (long)(y * out->rows / f->height) * out->columns + x * out->columns / f->width;
            out->mean[b] += f->pixels[(long)y * f->width + x].n;
            pixels[b]++;
        }
    for (int b = 0; b < out->columns * out->rows; b++) out->mean[b] /= (double)pixels[b];
}

void grade_rate_map_add(grade_rate_map *into, const grade_rate_map *from, double w)
{
    for (int b = 0; b < into->columns * into->rows; b++) into->mean[b] += w * from->mean[b];
}

json_t *grade_rate_map_json(const grade_rate_map *m)
{
    json_t *mean = json_array();
    for (int b = 0; mean && b < m->columns * m->rows; b++)
        if (json_array_append_new(mean, json_real(m->mean[b])) != 0) {
            json_decref(mean);
            return NULL;
        }
    return mean ? json_pack("{s:i, s:i, s:o}", "columns", m->columns, "rows", m->rows, "mean", mean) : NULL;
}

bool grade_rate_map_read(const json_t *j, int width, int height, grade_rate_map *out)
{
    memset(out, 0, sizeof *out);
    json_t *mean = json_object_get(j, "mean");
    if (!shape_fits(width, height) || json_integer_value(json_object_get(j, "columns")) != blocks_along(width) ||
        json_integer_value(json_object_get(j, "rows")) != blocks_along(height) ||
        json_array_size(mean) != (size_t)blocks_along(width) * (size_t)blocks_along(height))
        return false;
    out->columns = blocks_along(width);
    out->rows = blocks_along(height);
    for (int b = 0; b < out->columns * out->rows; b++) {
        json_t *v = json_array_get(mean, (size_t)b);
        out->mean[b] = json_is_number(v) ? json_number_value(v) : 0.0;
        if (!(out->mean[b] >= 1.0) || !isfinite(out->mean[b])) return false;
    }
    return true;
}

double grade_rate_map_distance(const grade_rate_map *candidate, const grade_rate_map *course)
{
    int n = course->columns * course->rows;
    if (candidate->columns != course->columns || candidate->rows != course->rows || n < 2) return INFINITY;
    double mean = 0.0, spread = 0.0, off = 0.0;
    for (int b = 0; b < n; b++) mean += log(course->mean[b]) / n;
    for (int b = 0; b < n; b++) {
        double c = log(course->mean[b]), d = log(candidate->mean[b]) - c;
        spread += (c - mean) * (c - mean);
        off += d * d;
    }
    /* A course's map without variation (every block alike) has nothing to follow: any candidate
     * off it is infinitely far, one equal to it at 0. */
    double distance = off / spread;
    return isnan(distance) ? (off == 0.0 ? 0.0 : INFINITY) : distance;
}
