/* Grader machinery: not part of any assignment.
 * Every number the grader shows a student about a render (the terminal table, results.json, the
 * HTML report, a case's reason) goes through grade_figure first: rounded to a few significant
 * digits and clamped to a range the course chose. A render is student code, and one that reads a
 * hidden scene or its own memory could otherwise send 8 bytes out through each double it makes the
 * grader print; rounded and clamped, a figure carries about log2 of the values it can take, a dozen
 * bits (grading/README.md, "What reaches the student", counts them). */
#ifndef PL_GRADE_FIGURE_H
#define PL_GRADE_FIGURE_H

#include <stdbool.h>
#include <stddef.h>

#define GRADE_FIGURE_DIGITS 3         /* significant digits of a public case's figure */
#define GRADE_FIGURE_COARSE_DIGITS 2  /* of a hidden case's (its mean ratio alone) */
/* A figure smaller in magnitude shows as 0: no figure of a render means anything below it (one
 * step of the 8-bit output is 4e-3), and it bounds the decades, so the values a figure can take
 * are countable (the README counts them). */
#define GRADE_FIGURE_FLOOR 1e-6

/* The ranges of the figures shown (the course's choice: far beyond what a render honestly has). */
#define GRADE_RATIO_MAX 1000.0   /* mean ratios, the noise ratio, a pixel's difference */
#define GRADE_HIDDEN_RATIO_MAX 10.0  /* a hidden case's mean ratio */
#define GRADE_REL_MSE_MAX 1e6
#define GRADE_T_MAX 1000.0       /* a block's t statistic, either sign */
#define GRADE_SPP_MAX 1e6        /* samples per pixel */
#define GRADE_WORK_MAX 1e9       /* node visits + primitive tests per camera ray */
#define GRADE_SECONDS_MAX 1e6    /* the run's time */

/* x clamped to [lo, hi] and rounded to `digits` significant digits; 0 when its magnitude is below
 * GRADE_FIGURE_FLOOR. NaN stays NaN (an unlit channel's ratio: the reference's fact, not the
 * candidate's); infinities clamp. Print it with %.3g (%.2g for the coarse digits). */
double grade_figure(double x, int digits, double lo, double hi);

/* A count of pixels the candidate decides (pixels beyond a tolerance, bad pixels): rounded as a
 * figure and clamped to [0, pixels], the image's size (the course's). */
long grade_figure_count(long count, long pixels);

/* A pixel coordinate the candidate's image decides, clamped into [0, size - 1]. */
int grade_figure_pixel(int coordinate, int size);

/* A message of the course's tests about the candidate's answers (a failed unit test's "expected
 * 0.318310, got 0.999999"), copied into out (size >= 1, always NUL-terminated, cut at a character
 * boundary): every number in it with a fraction or an exponent, and every whole number of more than
 * 4 digits, rounded to GRADE_FIGURE_DIGITS significant digits; a hexadecimal one of more than 4
 * digits shown as "0x...". Line numbers, test names and the like keep their digits. */
void grade_figure_text(const char *in, char *out, size_t size);

#endif
