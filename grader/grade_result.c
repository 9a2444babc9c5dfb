/* Grader machinery: not part of any assignment. A grading's facts: made, emptied, freed (grade_result.h). */
#include "grade_result.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

grade_result *grade_result_new(void)
{
    grade_result *r = calloc(1, sizeof *r);
    for (int i = 0; r && i < GRADE_MAX_PART; i++)
        if (!(r->parts[i].suite.tests = calloc(GRADE_MAX_TESTS, sizeof *r->parts[i].suite.tests))) {
            grade_result_free(r);
            return NULL;
        }
    return r;
}

void grade_result_clear_case(grade_case_result *c)
{
    verdict_free(&c->v);
    image_free(&c->candidate);
    image_free(&c->reference);
    const grade_case *spec = c->spec;
    memset(c, 0, sizeof *c);
    c->spec = spec;
}

void grade_result_free(grade_result *r)
{
    if (!r) return;
    for (int i = 0; i < GRADE_MAX_PART; i++) {
        free(r->parts[i].suite.tests);
        for (int k = 0; k < r->parts[i].num_cases; k++) grade_result_clear_case(&r->parts[i].cases[k]);
    }
    free(r);
}

double grade_result_mean_ratio(const verdict *v)
{
    double sum = 0.0;
    int lit = 0;
    for (int ch = 0; ch < 3; ch++)
        if (!isnan(v->ratio[ch])) sum += v->ratio[ch], lit++;
    return lit ? sum / lit : NAN;
}
