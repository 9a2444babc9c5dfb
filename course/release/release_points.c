/* Instructor tooling: not part of any assignment.
 * bin/release_points [CASES [HIDDEN]]: each part's points as the grader reads them (the same
 * grade_spec_load as bin/grade), one line per part it lists: "PART UNIT PUBLIC HIDDEN", where UNIT is the
 * unit-test suite's points, PUBLIC the public image cases' and HIDDEN the hidden ones'. The release
 * (course/release/cut) writes the GitHub Classroom workflow (UNIT + PUBLIC per part: what
 * `make grade PARTS=N` grades) and the autograder bundle's fallback results from it.
 * Defaults: grading/cases.json and grading/hidden/cases.json (when it exists). Exit 2 on a bad file.
 *
 * bin/release_points --only "1 2 3 4 5" IN OUT: writes the cases file IN to OUT with only the listed
 * parts (the course's COURSE_PARTS), so that a course that stops after part 5 hands out no case of
 * parts 6-9 (the cut and the bundle copy both cases files through it). Everything else in IN is
 * kept as it is; OUT is written whole or not at all. */
#include "../../grader/grade_spec.h"
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Whether the space-separated list of part numbers `parts` names part n. */
static bool part_listed(const char *parts, long n)
{
    for (const char *p = parts; *p;) {
        char *end;
        long k = strtol(p, &end, 10);
        if (end == p) return false;  /* not a number: the caller checked the list first */
        if (k == n) return true;
        p = end + strspn(end, " ");
    }
    return false;
}

/* --only PARTS IN OUT: IN's "parts" less those PARTS leaves out, written to OUT (a temporary file
 * renamed into place, so a failure leaves no half-written OUT). */
static int only_parts(const char *parts, const char *in, const char *out)
{
    if (!*parts || parts[strspn(parts, "0123456789 ")] != '\0') {
        fprintf(stderr, "release_points: --only \"%s\": expected part numbers, such as \"1 2 3 4 5\"\n", parts);
        return 2;
    }
    json_error_t err;
    json_t *root = json_load_file(in, JSON_REJECT_DUPLICATES, &err);
    json_t *list = root ? json_object_get(root, "parts") : NULL;
    if (!json_is_array(list)) {
        if (root) fprintf(stderr, "release_points: %s: expected an object with a \"parts\" array\n", in);
        else fprintf(stderr, "release_points: %s:%d: %s\n", in, err.line, err.text);
        json_decref(root);
        return 2;
    }
    for (size_t i = json_array_size(list); i-- > 0;) {
        json_t *n = json_object_get(json_array_get(list, i), "part");
        if (!json_is_integer(n) || !part_listed(parts, (long)json_integer_value(n)))
            json_array_remove(list, i);
    }
    char tmp[4096];
    int len = snprintf(tmp, sizeof tmp, "%s.tmp", out);
    int rc = 0;
    if (len < 0 || (size_t)len >= sizeof tmp) {
        fprintf(stderr, "release_points: %s: path too long\n", out);
        rc = 2;
    } else if (json_dump_file(root, tmp, JSON_INDENT(2) | JSON_PRESERVE_ORDER) != 0 || rename(tmp, out) != 0) {
        fprintf(stderr, "release_points: %s: cannot write it\n", out);
        remove(tmp);
        rc = 2;
    }
    json_decref(root);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "--only")) {
        if (argc != 5) {
            fprintf(stderr, "usage: release_points --only \"PARTS\" IN OUT\n");
            return 2;
        }
        return only_parts(argv[2], argv[3], argv[4]);
    }
    const char *cases = argc > 1 ? argv[1] : GRADE_CASES;
    const char *hidden = argc > 2 ? argv[2] : GRADE_HIDDEN_CASES;
    if (argc > 3 || (argc > 1 && !strcmp(argv[1], "--help"))) {
        fprintf(stderr, "usage: release_points [CASES [HIDDEN]] | --only \"PARTS\" IN OUT\n");
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
