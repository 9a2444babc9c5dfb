/* Grader machinery: not part of any assignment.
 * The words stage (grade_words.c): every sentence a student, a TA or the staff log reads about a
 * grading, made from its facts (grade_result.h) and nothing else. One sentence per fact, so the
 * terminal table, results.json and the HTML report say the same thing in the same words. Every
 * number a render decides goes through grade_figure (grade_figure.h) before it is formatted; every
 * text a student's code or a course test made goes through grade_md_escape before it reaches
 * Markdown. A hidden case is worded by its verdict alone. */
#ifndef PL_GRADE_WORDS_H
#define PL_GRADE_WORDS_H

#include <stddef.h>
#include "grade_result.h"

/* The words for running out of the grading's time, the same everywhere. */
#define GRADE_WORDS_OUT_OF_TIME "the grading ran out of time (each part gets its share of the autograder's limit)"

/* ---- why something did not happen (plain text) ------------------------------------------------- */

/* A child's ending: its kind only (timed out, a memory error, a forbidden system call...), never the
 * status or signal a child running student code chose. */
void grade_words_ending(const grade_run_result *r, char *out, size_t size);
/* A why of part `part` (its folder in the course, "part2_bvh"), in one sentence. */
void grade_words_why(const grade_why *w, int part, const char *folder, char *out, size_t size);
/* What the inspection found wrong in an object (after the file's name). */
void grade_words_inspection(const grade_inspect_verdict *v, char *out, size_t size);
/* The protections this machine could not give student code ("" when none is missing), and those in
 * force (for the staff log). */
void grade_words_protections_missing(const grade_sandbox *s, char *out, size_t size);
void grade_words_protections_in_force(const grade_sandbox *s, char *out, size_t size);

/* ---- the unit tests (Markdown) ------------------------------------------------------------------- */

/* Why part p's unit tests earned nothing as a whole (it did not build, or its suite could not be
 * judged), plain text; false when they were judged test by test. */
bool grade_words_unit_zero(const grade_part_result *p, char *out, size_t size);
/* The failed tests, one Markdown line each: "- `name`: message" (the course test's message, its
 * numbers rounded and escaped; or why the test did not finish). */
void grade_words_failures(const grade_part_result *p, char *out, size_t size);
/* The part's unit points task by task, one Markdown line each, and the cascade advice. */
int grade_words_tasks(const grade_part_result *p, char *out, size_t size);
/* How many of the part's tasks lost their share; when several did, the advice that one bug can fail
 * another task's tests, with the part's own tasks ("" when at most one did). */
int grade_words_tasks_failed(const grade_part_result *p);
void grade_words_cascade(const grade_part_result *p, char *out, size_t size);

/* ---- an image case (Markdown) -------------------------------------------------------------------- */

/* Its verdict: matches or not, its statistics, where it differs and the hint, its figures. */
void grade_words_case(const grade_case_result *c, int part, const char *folder, char *out, size_t size);
/* A failing public case's cause in one line (make grade's). */
void grade_words_case_cause(const grade_case_result *c, int part, const char *folder, char *out, size_t size);
/* A failing public case's pixels, one line each with the command that replays the render of that
 * pixel (framework/trace.h) at the seed of the render judged; "" when none. Plain text. */
void grade_words_trace(const grade_case_result *c, char *out, size_t size);

/* ---- the run ------------------------------------------------------------------------------------- */

/* The run's time as shown (a figure: a render that sleeps chooses it). */
double grade_words_seconds(const grade_result *r);

#endif
