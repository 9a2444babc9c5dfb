/* Grader machinery: not part of any assignment.
 * The verdict stage of an image case (grade_image.c): a film against the course's reference, and the
 * figures judged beside it, into the case's facts (grade_result.h). */
#ifndef PL_GRADE_IMAGE_H
#define PL_GRADE_IMAGE_H

#include "grade_plan.h"
#include "grade_result.h"
#include "../framework/film.h"
#include "../framework/image.h"

/* The course's reference of a case (its EXR at path): its mean image and each mean's variance; a
 * reference that cannot be read or holds a bad pixel is the course's problem (why: GRADE_WHY_COURSE). */
pl_status grade_image_reference(const char *path, image *out, image *var, grade_why *why);

/* Judges film f of case pc against the reference (refimg, refvar) into c: c->ran, c->v, the figures,
 * c->pass, c->chance_failure (it failed on its p-value alone), the pixels to trace (a public case that
 * failed), and the two images for the report. A statistical case that fails on chance alone is
 * rendered again by the caller (grade_part.c): a correct render fails about once in a thousand
 * gradings at most (grading/CALIBRATION.md), two independent ones about once in a million; a bug
 * fails both. */
void grade_image_judge(const grade_spec *spec, const grade_plan_case *pc, const film *f, const image *refimg,
                       const image *refvar, grade_case_result *c);

/* A case's figures beside its image, each true where the case does not judge it: the adaptive
 * render's mean samples per pixel and its sample-rate map against the course's, the render's CPU
 * time against the baseline's (GRADE_WORK_FACTOR, GRADE_SCAN_FACTOR), its noise (GRADE_NOISE_FACTOR). */
bool grade_image_spp_ok(const grade_case_result *c);
bool grade_image_rate_ok(const grade_case_result *c);
bool grade_image_work_ok(const grade_case_result *c);
bool grade_image_noise_ok(const grade_case_result *c);

#endif
