/* Grader machinery: not part of any assignment.
 * The sample-rate map of an adaptive render: the mean number of samples its pixels took, block by
 * block. Part 5's answer is where a render spends its samples, so an adaptive case compares the
 * candidate's map with the course's region by region: a part that stops every pixel at one fixed
 * count is not adaptive, however close its mean. Both maps come from films (the per-pixel sample
 * counts the framework accumulated: the render's answer, like its pixels); the course's is the mean
 * of GRADE_RATE_RUNS renders of the course's part, recorded with the reference (course/references). */
#ifndef PL_GRADE_RATE_H
#define PL_GRADE_RATE_H

#include "../framework/film.h"
#include <jansson.h>
#include <stdbool.h>

#define GRADE_RATE_BLOCK 16      /* pixels square, about: a w x h image has w / 16 x h / 16 blocks */
#define GRADE_RATE_MAX_BLOCKS 4096
#define GRADE_RATE_RUNS 8        /* the course's renders the reference's map is the mean of */

typedef struct {
    int columns, rows;                     /* blocks across and down; 0 for none */
    double mean[GRADE_RATE_MAX_BLOCKS];    /* each block's mean samples per pixel, top row first */
} grade_rate_map;

/* The map of f: blocks of about GRADE_RATE_BLOCK pixels (the last of a row or column takes the rest). */
void grade_rate_map_of(const film *f, grade_rate_map *out);
/* Adds `from` into `into` with weight w (into = into + w from; both of one shape). */
void grade_rate_map_add(grade_rate_map *into, const grade_rate_map *from, double w);

/* The map as JSON ({"columns", "rows", "mean": [...]}), and back: false unless it is one of width x
 * height's shape with every mean >= 1. */
json_t *grade_rate_map_json(const grade_rate_map *m);
bool grade_rate_map_read(const json_t *j, int width, int height, grade_rate_map *out);

/* How far the candidate's map is from the course's, as the share of the course's own variation from
 * block to block that the candidate's does not follow: the sum over blocks of
 * (log candidate - log course)^2 over the sum of (log course - its mean)^2. About 0 for a correct
 * part (it differs from the course's mean map by its own render's noise only); 1 or more for one
 * that spends the same everywhere (a fixed count is at best the course's geometric mean, whose
 * squared distance is the whole of that variation), whatever the count. */
double grade_rate_map_distance(const grade_rate_map *candidate, const grade_rate_map *course);

#endif
