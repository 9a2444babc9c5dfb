/* UTF-8 validation and a valid copy of any text (utf8.h). */
#include "utf8.h"
#include <stdio.h>
#include <string.h>

/* The length of the valid character at p (left bytes remain), or 0 when the bytes there are not one. */
static size_t char_length(const unsigned char *p, size_t left)
{
    if (p[0] < 0x80) return 1;
    size_t n = p[0] >= 0xf0 ? 4 : p[0] >= 0xe0 ? 3 : p[0] >= 0xc2 ? 2 : 0;  /* 0x80..0xc1: never a lead byte */
    if (n == 0 || n > left || p[0] > 0xf4) return 0;
    for (size_t i = 1; i < n; i++)
        if ((p[i] & 0xc0) != 0x80) return 0;
    /* The second byte's range rules out overlong forms, surrogates (U+D800..DFFF) and > U+10FFFF. */
    if ((p[0] == 0xe0 && p[1] < 0xa0) || (p[0] == 0xed && p[1] > 0x9f) || (p[0] == 0xf0 && p[1] < 0x90) ||
        (p[0] == 0xf4 && p[1] > 0x8f))
        return 0;
    return n;
}

size_t utf8_valid_prefix(const char *s, size_t len)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t i = 0;
    for (size_t n; i < len && (n = char_length(p + i, len - i)) > 0;) i += n;
    return i;
}

char *utf8_sanitize(const char *s, char *out, size_t size)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t len = strlen(s), used = 0;
    for (size_t i = 0; i < len;) {
        size_t n = char_length(p + i, len - i);
        size_t need = n ? n : 4;  /* a bad byte becomes \xNN */
        if (used + need >= size) break;
        if (n) memcpy(out + used, p + i, n);
        else snprintf(out + used, 5, "\\x%02x", p[i]);
        used += need;
        i += n ? n : 1;
    }
    out[used] = '\0';
    return out;
}
