/* Test machinery: not part of any assignment. The run-time alpha budget (alpha.h). */
#include "alpha.h"
#include "../../framework/stats.h"
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* ---- the suite's one convention, fixed by the first check -------------------------------------- */
static double family = 0.0;
static int budget = 0;
static int checks = 0;

/* At exit: a suite that ran more checks than its budget has a larger false-alarm rate than it
 * states. Exiting from an atexit handler must use _exit, so flush first. */
static void verify_budget(void)
{
    if (checks > budget) {
        fprintf(stderr, "ALPHA BUDGET EXCEEDED: %d statistical checks ran, the budget is %d: each check ran at "
                        "%.3g, so the suite's false-alarm rate is above its stated %g. Raise the budget in the "
                        "suite's alpha header.\n", checks, budget, stats_sidak(family, budget), family);
        fflush(stdout);
        fflush(stderr);
        _exit(1);
    }
    printf("alpha: %d statistical checks of a budget of %d, %.3g each: family alpha %g\n", checks, budget,
           stats_sidak(family, budget), family);
}

double alpha_check(double family_alpha, int checks_budget)
{
    if (budget == 0) {
        family = family_alpha;
        budget = checks_budget;
        atexit(verify_budget);
    } else if (family != family_alpha || budget != checks_budget) {
        fprintf(stderr, "ALPHA CONVENTION: a check asked for family alpha %g over %d checks, the suite declared "
                        "%g over %d: declare them once, in the suite's alpha header.\n",
                family_alpha, checks_budget, family, budget);
        fflush(stdout);
        _exit(1);
    }
    checks++;
    return stats_sidak(family, budget);
}

int alpha_checks_run(void) { return checks; }
