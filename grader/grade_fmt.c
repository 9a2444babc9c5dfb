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
#include "grade_fmt.h"

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

bool grade_join(const char *dir, const char *name, char *out, size_t size)
{
    return grade_path(out, size, "%s/%s", dir, name);
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

/* The characters that can start markup anywhere in a CommonMark line: code, emphasis, links and
 * images, raw HTML and autolinks, entities, table cells and strike-through (GitHub's flavour), and
 * the backslash itself. Each is escaped with a backslash, which CommonMark defines for every ASCII
 * punctuation character, so the text reads back as itself. (The rest of the punctuation, which
 * readers of the raw JSON meet in every sentence, is left as it is: alone it makes no markup.) */
static bool markup_character(char c)
{
    return c && strchr("\\`*_[]<>&|~!", c) != NULL;
}

/* Where the line starting at s opens a block in CommonMark (a heading, a list item, a quote, a
 * thematic break or setext underline): the offset of the character that makes it one (the '#',
 * '-', '+', '=' or '>' after at most three blanks, or the '.' or ')' after a list item's digits),
 * which is escaped too; -1 when the line opens none. */
static long block_marker(const char *s, size_t len)
{
    size_t i = 0;
    while (i < len && i < 3 && s[i] == ' ') i++;
    if (i >= len) return -1;
    if (strchr("#-+=>", s[i])) return (long)i;
    size_t d = i;
    while (d < len && s[d] >= '0' && s[d] <= '9') d++;
    return d > i && d < len && (s[d] == '.' || s[d] == ')') ? (long)d : -1;
}

void grade_md_escape(const char *in, size_t len, char *out, size_t size)
{
    size_t n = 0;
    long marker = -1;
    for (size_t i = 0; i < len && in[i] && size > 0; i++) {
        if (i == 0 || in[i - 1] == '\n') {
            long at = block_marker(in + i, len - i);
            marker = at < 0 ? -1 : (long)i + at;
        }
        size_t need = markup_character(in[i]) || (long)i == marker ? 2 : 1;
        /* Never cut inside a character: a continuation byte goes only with its lead byte's room. */
        if (n + need + 1 > size) break;
        if (need == 2) out[n++] = '\\';
        out[n++] = in[i];
    }
    if (size == 0) return;
    /* A character whose bytes did not all fit goes whole: back to its lead byte, if it is short. */
    size_t lead = n;
    while (lead > 0 && ((unsigned char)out[lead - 1] & 0xC0) == 0x80) lead--;
    if (lead > 0 && ((unsigned char)out[lead - 1] & 0xC0) == 0xC0) {
        unsigned char b = (unsigned char)out[lead - 1];
        size_t want = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2;
        if (n - (lead - 1) < want) n = lead - 1;
    }
    out[n] = '\0';
}
