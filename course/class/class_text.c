/* Instructor tooling: not part of any assignment. Hostile bytes made safe to show (class_text.h). */
#include "class_text.h"
#include "../../framework/utf8.h"
#include <math.h>
#include <string.h>

/* The length of the UTF-8 sequence s starts, when it is one whole valid character; else 0. */
static size_t char_length(const unsigned char *s, size_t left)
{
    size_t n = s[0] < 0x80 ? 1 : (s[0] & 0xe0) == 0xc0 ? 2 : (s[0] & 0xf0) == 0xe0 ? 3 : (s[0] & 0xf8) == 0xf0 ? 4 : 0;
    return n && n <= left && utf8_valid_prefix((const char *)s, n) == n ? n : 0;
}

/* The escape of the character at s (n bytes long, n 0 for an invalid byte) into esc, or "" when
 * it is shown as it is. */
static void escape_of(const unsigned char *s, size_t n, char esc[16])
{
    esc[0] = '\0';
    if (n == 0 || s[0] < 0x20 || s[0] == 0x7f) snprintf(esc, 16, "\\x%02X", s[0]);
    else if (s[0] == '\\') snprintf(esc, 16, "\\\\");
    else if (n == 2 && s[0] == 0xc2 && s[1] < 0xa0) snprintf(esc, 16, "\\u%04X", s[1]);  /* C1 controls */
    else if (n == 3 && s[0] == 0xe2) {
        unsigned cp = ((s[0] & 0x0fu) << 12) | ((s[1] & 0x3fu) << 6) | (s[2] & 0x3fu);
        if ((cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069) || cp == 0x200e || cp == 0x200f)
            snprintf(esc, 16, "\\u%04X", cp);  /* the marks and overrides that reorder a line */
    }
}

char *class_text_shown(const char *s, size_t len, char *out, size_t size)
{
    /* Character by character: a whole valid character is copied or escaped whole, an invalid byte
     * escaped alone, and the output stops before an escape or a character that would not fit. */
    size_t o = 0;
    const unsigned char *u = (const unsigned char *)s;
    for (size_t i = 0; i < len;) {
        size_t n = char_length(u + i, len - i);
        char esc[16];
        escape_of(u + i, n, esc);
        size_t add = esc[0] ? strlen(esc) : n;
        if (o + add + 1 > size) break;
        memcpy(out + o, esc[0] ? esc : s + i, add);
        o += add;
        i += n ? n : 1;
    }
    out[o] = '\0';
    return out;
}

void class_text_html(FILE *f, const char *s)
{
    for (; *s; s++) switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*s, f);
        }
}

void class_text_csv(FILE *f, const char *s)
{
    /* Quoted always: a comma, a quote or a line break in a name stays inside its cell. */
    fputc('"', f);
    if (*s && strchr("=+-@\t\r", *s)) fputc('\'', f);  /* a formula, to a spreadsheet: shown as text */
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

char *class_text_number(double x, char *out, size_t size)
{
    /* Rounded to the cent first, so that 2.675 prints the same wherever it was computed. */
    if (!isfinite(x)) x = 0.0;
    snprintf(out, size, "%.2f", round(x * 100.0) / 100.0);
    /* Trailing zeros and a bare point go: "7.50" -> "7.5", "10.00" -> "10". */
    char *dot = strchr(out, '.');
    if (dot) {
        char *end = out + strlen(out) - 1;
        while (end > dot && *end == '0') *end-- = '\0';
        if (end == dot) *end = '\0';
    }
    if (!strcmp(out, "-0")) snprintf(out, size, "0");
    return out;
}
