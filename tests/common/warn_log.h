/* Test machinery: not part of any assignment. Warnings collected instead of printed, so a test can
 * count them and look for a kind: a pl_diag whose warn callback appends to a warn_log. */
#ifndef PL_TEST_WARN_LOG_H
#define PL_TEST_WARN_LOG_H

#include "../../framework/status.h"

typedef struct {
    int count;
    char all[8192];  /* every message, one per line (cut when full) */
} warn_log;

/* A diag that collects into w, emptied first. */
pl_diag warn_log_diag(warn_log *w);
/* How many collected warnings contain needle. */
int warn_log_count(const warn_log *w, const char *needle);

#endif
