/* The command line: CS184's flags plus pathlab's long options, parsed into options.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_CLI_H
#define PL_CLI_H

#include <stdio.h>
#include "options.h"
#include "status.h"

typedef enum { CLI_RUN = 0, CLI_HELP } cli_action;

/* Parses argv into *out. Returns PL_OK (and *action) or PL_ERR_INVALID with a one-line message
 * in diag ("-s: expected a positive integer, got 'abc'"). Strings in *out point into argv, except
 * command_line, which must be released with cli_free. */
pl_status cli_parse(int argc, char **argv, options *out, cli_action *action, pl_diag *diag);
void cli_free(options *o);
void cli_print_usage(FILE *f, const char *prog);

/* ---- what the run says about the scene, once it is loaded ---------------------------------- */
struct scene;

/* Options and a scene that render without complaint yet do less than they seem to ask, each said
 * once through d (one "warning: ..." line on stderr by default): a scene with no lights (named by
 * its file), -d with no lens to focus (part 9's thin lens), or -b / -d where the course has no
 * part 9 (accepted for CS184's command line). Returns how many warnings it gave. */
int cli_warn_noops(const options *o, const struct scene *s, pl_diag *d);


#endif
