/* Test machinery: not part of any assignment.
 * One false-alarm convention for every statistical check. A suite declares its family alpha (the
 * chance that a correct implementation fails a run) and its budget (the most statistical checks
 * one run makes) in one header; each check asks alpha_check() for its level, which is the Sidak
 * share 1 - (1 - family)^(1/budget) and counts the check. When the suite exits, the count is
 * compared with the budget: a suite that ran more checks than its budget fails loudly, because its
 * stated alpha would be a lie. The real false-failure rate is measured over fresh PL_TEST_SEED values. */
#ifndef PL_ALPHA_H
#define PL_ALPHA_H

/* The per-check level for a suite with this family alpha and budget; counts one check. Every call
 * in one process must pass the same pair (one convention per suite), or the run fails. */
double alpha_check(double family_alpha, int budget);

/* Checks counted so far in this process (for tests of this module). */
int alpha_checks_run(void);

#endif
