/* Grader machinery: not part of any assignment.
 * The build stage (grade_build.c says what it trusts): a submission's part compiled confined,
 * inspected and linked in a tree the student's code never saw; or a student's own tree built by its
 * own make. Either returns the build's facts. */
#ifndef PL_GRADE_BUILD_H
#define PL_GRADE_BUILD_H

#include "grade_manifest.h"
#include "grade_plan.h"
#include "grade_result.h"

/* Builds the part plan describes from the submission's files (the manifest m) into plan->tree: each
 * submitted .c compiled alone, confined by sandbox, into an object; the objects taken out, inspected,
 * and linked as the grader with the course's own objects of everything else into bin/pathtracer and
 * bin/subject-part<n>. out->built, or out->why and the compiler's lines about the student's own files. */
void grade_build_submission(const grade_plan *plan, const grade_manifest *m, const grade_sandbox *sandbox,
                            grade_build_facts *out);

/* A student's own tree (make grade): built by its own make, as they build it, with the course's
 * warnings whatever they exported and no sanitizer, so `make grade` and `make` share every object.
 * Their own code, on their own machine: nothing here is confined. */
void grade_build_own_tree(const grade_plan *plan, grade_build_facts *out);

#endif
