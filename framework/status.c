/* The diagnostics channel: located errors and warnings, never printed by library code itself. */
#include "status.h"
#include <stdarg.h>
#include <stdio.h>

/* The default destination of warnings: the console, one line each. */
static void print_warning(void *user, const char *msg)
{
    (void)user;
    fprintf(stderr, "warning: %s\n", msg);
}

pl_diag pl_diag_default(void)
{
    pl_diag d = {{0}, 0, print_warning, NULL};
    return d;
}

/* Formats into the channel and hands the status back, so a failure is one line at its call site:
 * `return pl_fail(diag, PL_ERR_PARSE, ...)`. The message is cut at PL_DIAG_MSG_MAX, never overflows. */
pl_status pl_fail(pl_diag *d, pl_status status, const char *fmt, ...)
{
    if (d) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(d->error, sizeof d->error, fmt, ap);
        va_end(ap);
    }
    return status;
}

/* A warning goes to the channel's collector (tests count them) or is printed; either way the
 * count goes up, so a caller can tell a clean load from one that needed warnings. */
void pl_warn(pl_diag *d, const char *fmt, ...)
{
    char msg[PL_DIAG_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (d) {
        d->num_warnings++;
        (d->on_warning ? d->on_warning : print_warning)(d->user, msg);
    } else {
        print_warning(NULL, msg);
    }
}

/* Names for messages; a value outside the enum (memory gone wrong) still gets a string. */
const char *pl_status_name(pl_status s)
{
    switch (s) {
    case PL_OK: return "ok";
    case PL_ERR_TODO: return "not implemented";
    case PL_ERR_IO: return "i/o error";
    case PL_ERR_PARSE: return "parse error";
    case PL_ERR_INVALID: return "invalid input";
    case PL_ERR_NOMEM: return "out of memory";
    }
    return "unknown status";
}
