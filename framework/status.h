/* Status codes and the diagnostics channel.
 * Library functions never print and never exit: they return a pl_status (PL_OK == 0) and put a
 * located message ("scene.dae:212: <polylist>: vcount has 5 entries, count says 6") in a pl_diag.
 * Warnings go through the same channel, so a test can collect them and the CLI can print them.
 * Parts may not call: none of these (every function here is marked PL_PART_API). */
#ifndef PL_STATUS_H
#define PL_STATUS_H

#include "part_api.h"

typedef enum {
    PL_OK = 0,
    PL_ERR_TODO,     /* a student task is not implemented yet (a stub ran) */
    PL_ERR_IO,       /* a file could not be read or written */
    PL_ERR_PARSE,    /* malformed input: the message says where and what was expected */
    PL_ERR_INVALID,  /* well-formed input with values out of range */
    PL_ERR_NOMEM     /* an allocation failed */
} pl_status;

#define PL_DIAG_MSG_MAX 1024

typedef struct pl_diag {
    char error[PL_DIAG_MSG_MAX];  /* the last error, located; empty when none */
    int num_warnings;             /* warnings reported so far */
    /* Where warnings go: NULL prints "warning: <msg>" to stderr. Tests install a collector. */
    void (*on_warning)(void *user, const char *msg);
    void *user;
} pl_diag;

/* A diagnostics channel that prints warnings to stderr. */
PL_PART_API pl_diag pl_diag_default(void);

/* Records a formatted error in d (if d is not NULL) and returns status, so callers can write
 * `return pl_fail(d, PL_ERR_PARSE, "%s:%d: <%s>: expected ...", ...);`. */
PL_PART_API pl_status pl_fail(pl_diag *d, pl_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Reports a warning through d (to stderr when d is NULL). */
PL_PART_API void pl_warn(pl_diag *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* A short name for a status, e.g. "parse error". */
PL_PART_API const char *pl_status_name(pl_status s);

#endif
