/* Formatting into the grader's fixed buffers, two ways, chosen by what a cut would do.
 *
 * A path that does not fit must never be cut: "work/part1/tree" cut short names another file, and
 * the grader would read or remove the wrong one. grade_path refuses instead, loudly.
 * A message that does not fit may lose its tail: a reason shown in the report is still useful cut,
 * and the report must never overflow. grade_msg cuts, and marks the cut so nobody mistakes the
 * shortened text for the whole.
 *
 * Both go through vsnprintf in a function of their own, which is also why GCC's truncation warning
 * (-Wformat-truncation, on for the grader) does not flag them: the decision about a cut is made
 * here, once, instead of at 160 call sites. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "grade.h"

bool grade_path(char *out, size_t size, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int n = vsnprintf(out, size, format, ap);
    va_end(ap);
    if (n >= 0 && (size_t)n < size) return true;
    /* What was formatted so far is a prefix of the path: enough to recognise it in the log. */
    fprintf(stderr, "grade: path too long (%d bytes, room for %zu): %.200s...\n", n, size ? size - 1 : 0, size ? out : "");
    if (size) out[0] = '\0';  /* an empty path opens nothing, rather than a wrong file */
    return false;
}

void grade_msg(char *out, size_t size, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int n = vsnprintf(out, size, format, ap);
    va_end(ap);
    if (n < 0 || (size_t)n < size || size < 4) return;
    /* Cut: end with "...", placed on a character boundary (backing over UTF-8 continuation bytes)
     * so a cut inside a multi-byte character leaves valid UTF-8 for results.json. */
    size_t at = size - 4;
    while (at > 0 && ((unsigned char)out[at] & 0xC0) == 0x80) at--;
    memcpy(out + at, "...", 4);
}
