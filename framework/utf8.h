/* UTF-8 text that came from a file pathlab did not write (a film's header, a test's message): how
 * much of it is valid, and a copy of it that is. JSON must be valid UTF-8 (jansson refuses a string
 * that is not, and a refused string would silently drop its entry), and so must any message shown.
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_UTF8_H
#define PL_UTF8_H

#include <stddef.h>

/* The bytes of s[0..len) that form whole, valid characters from the start (no overlong form, no
 * surrogate, nothing above U+10FFFF): len when all of s is valid. */
size_t utf8_valid_prefix(const char *s, size_t len);

/* Copies the C string s into out (size >= 1 bytes, always NUL-terminated): valid characters as they
 * are, every other byte as the four characters \xNN; when out is too small the copy ends at a
 * character boundary, never inside a character or an escape. Returns out. */
char *utf8_sanitize(const char *s, char *out, size_t size);

#endif
