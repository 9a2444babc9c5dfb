/* Failed framework invariants (check.h): the default handler prints and aborts. */
#include "check.h"
#include <stdio.h>
#include <stdlib.h>

/* Mutable by necessity (the tests replace it), and set only before threads start. */
static pl_check_handler current_handler;

void pl_check_set_handler(pl_check_handler handler) { current_handler = handler; }

void pl_check_failed(const char *what, const char *file, int line)
{
    if (current_handler) {
        current_handler(what, file, line);
        return;
    }
    /* A bug, not bad input: the one place library code prints, since no caller can recover. */
    fprintf(stderr, "%s:%d: check failed: %s\n", file, line, what);
    fflush(stderr);
    abort();
}
