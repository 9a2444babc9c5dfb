/* Grader machinery: not part of any assignment. The course's references, checked before anyone is
 * graded: a broken reference is the course's problem, reported as such, never a student's 0. */
#ifndef PL_GRADE_REFS_H
#define PL_GRADE_REFS_H

#include "grade_spec.h"
#include "grade_rate.h"

/* Checks the reference of every case of the parts listed in `parts` ("1,3"; public cases only when
 * public_only), with the run's working folder at root: the film reads strictly and is consistent
 * (exr_read), holds no bad sample, covers 0:N of N for the case's reference_samples at the case's
 * size, and was rendered with the case's reference flags on the case's scene (its command and key
 * recomputed); its JSON parses strictly, names the case, its key and seed, and holds the course's
 * figures the case judges. The error names the file, what is wrong, and what to run. */
pl_status grade_refs_check(const char *root, const grade_spec *spec, const char *parts, bool public_only, pl_diag *diag);

/* The course's figures for case k's own render, from the reference's JSON (strict): the mean samples
 * per pixel (> 0) and the sample-rate map (grade_rate.h), required of an adaptive case. */
typedef struct {
    double spp;
    grade_rate_map map;        /* columns 0 for a case that is not adaptive */
} grade_course_figures;
pl_status grade_refs_figures(const char *ref_exr, const grade_case *k, grade_course_figures *out, pl_diag *diag);

#endif
