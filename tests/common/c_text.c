/* Test machinery: not part of any assignment. C source as text (c_text.h). */
#include "c_text.h"
#include <stdlib.h>
#include <string.h>

/* Blanks from p to stop, line breaks kept; returns where it stopped. */
static char *blank(char *p, const char *stop)
{
    for (; p < stop; p++)
        if (*p != '\n') *p = ' ';
    return p;
}

char *c_text_code(const char *text, bool directives)
{
    char *c = strdup(text);
    if (!c) return NULL;
    bool line_start = true;  /* only blanks since the last line break: where a directive may start */
    for (char *p = c; *p; p++) {
        if (p[0] == '/' && p[1] == '*') {
            char *end = strstr(p + 2, "*/");
            p = blank(p, end ? end + 2 : p + strlen(p)) - 1;
        } else if (p[0] == '/' && p[1] == '/') {
            p = blank(p, p + strcspn(p, "\n")) - 1;
        } else if (*p == '"' || *p == '\'') {
            char q = *p++;
            for (; *p && *p != q; p++) {
                if (*p == '\\' && p[1]) *p++ = ' ';
                if (*p != '\n') *p = ' ';
            }
            if (!*p) break;
        } else if (*p == '#' && line_start && directives) {
            char *end = p;
            while (*end && !(*end == '\n' && end[-1] != '\\')) end++;
            p = blank(p, end) - 1;
        }
        if (*p == '\n') line_start = true;
        else if (*p != ' ' && *p != '\t') line_start = false;
    }
    return c;
}
