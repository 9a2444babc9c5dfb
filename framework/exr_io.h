/* Framework-internal: what the film's files (exr.c) and any RGB image's (exr_rgb.c) share of
 * OpenEXR's C API: a write context on a FILE (OpenEXR writes at offsets, through pwrite on its
 * descriptor), errors reported once with the file's name instead of printed, and a result code
 * as pathlab's status. Prefix exrio_: OpenEXR's own functions are exr_*.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_EXR_IO_H
#define PL_EXR_IO_H

#include <stdio.h>
#include <openexr.h>
#include "status.h"

/* A write context on file's descriptor, stored in *fd (the write callback reads it there, so it
 * must outlive the context). Whatever file has buffered goes first: OpenEXR writes at offsets from 0. */
exr_result_t exrio_start_write(FILE *file, int *fd, const char *name, exr_context_t *x);
/* OpenEXR's error handler for every context pathlab opens: silent (pathlab reports the result). */
void exrio_quiet_errors(exr_const_context_t ctxt, exr_result_t code, const char *msg);
/* An OpenEXR result code as pathlab's status and message: "what: OpenEXR: why". */
pl_status exrio_fail(pl_diag *diag, const char *what, exr_result_t r);

#endif
