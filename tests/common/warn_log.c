/* Test machinery: not part of any assignment. Collected warnings (warn_log.h). */
#include "warn_log.h"
#include <stdio.h>
#include <string.h>

static void collect_warning(void *user, const char *msg)
{
    warn_log *w = user;
    w->count++;
    size_t used = strlen(w->all);
    snprintf(w->all + used, sizeof w->all - used, "%s\n", msg);
}

pl_diag warn_log_diag(warn_log *w)
{
    memset(w, 0, sizeof *w);
    pl_diag d = {{0}, 0, collect_warning, w};
    return d;
}

int warn_log_count(const warn_log *w, const char *needle)
{
    int n = 0;
    for (const char *s = w->all; (s = strstr(s, needle)); s += strlen(needle)) n++;
    return n;
}
