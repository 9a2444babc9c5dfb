/* Instructor tooling: not part of any assignment.
 * bin/release_points [CASES [HIDDEN]]: each part's points as the grader reads them (the same
 * grade_spec_load as bin/grade), one line per part it lists: "PART UNIT PUBLIC HIDDEN", where UNIT is the
 * unit-test suite's points, PUBLIC the public image cases' and HIDDEN the hidden ones'. The release
 * (course/release/cut) writes the GitHub Classroom workflow (UNIT + PUBLIC per part: what
 * `make grade PARTS=N` grades) and the autograder bundle's fallback results from it.
 * Defaults: grading/cases.json and grading/hidden/cases.json (when it exists). Exit 2 on a bad file. */
#include "../../grader/grade.h"
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    const char *cases = argc > 1 ? argv[1] : GRADE_CASES;
    const char *hidden = argc > 2 ? argv[2] : GRADE_HIDDEN_CASES;
    if (argc > 3 || (argc > 1 && !strcmp(argv[1], "--help"))) {
        fprintf(stderr, "usage: release_points [CASES [HIDDEN]]\n");
        return 2;
    }
    if (access(hidden, R_OK) != 0) hidden = NULL;
    pl_diag diag = pl_diag_default();
    grade_spec spec;
    if (grade_spec_load(cases, hidden, &spec, &diag) != PL_OK) {
        fprintf(stderr, "release_points: %s\n", diag.error);
        return 2;
    }
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        const grade_part_spec *p = &spec.parts[k];
        if (!p->part) continue;  /* not a part cases.json lists */
        double pub = 0, hid = 0;
        for (int i = 0; i < p->num_cases; i++) *(p->cases[i].hidden ? &hid : &pub) += p->cases[i].points;
        printf("%d %g %g %g\n", p->part, p->unit_points, pub, hid);
    }
    grade_spec_free(&spec);
    return 0;
}
