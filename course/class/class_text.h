/* Instructor tooling: not part of any assignment.
 * Hostile bytes made safe to show (class.h: every name a submission brings is hostile). A name is
 * first escaped into text a person can read unambiguously (class_text_shown); that text is then
 * written into HTML or a CSV cell with the escaping each needs. */
#ifndef PL_CLASS_TEXT_H
#define PL_CLASS_TEXT_H
#include <stddef.h>
#include <stdio.h>

/* s[0..len) as shown: valid UTF-8 kept; every other byte, every control character (C0, DEL, C1),
 * every bidirectional override and the backslash itself escaped (\xNN, \u202E, \\), so that a
 * shown name is one line, reads left to right, and two different names never show alike. Cut at
 * a character boundary to fit size (>= 1). Returns out. */
char *class_text_shown(const char *s, size_t len, char *out, size_t size);
/* Writes s into HTML text or an attribute value: & < > " ' as character references. */
void class_text_html(FILE *f, const char *s);
/* Writes s as one CSV cell (RFC 4180): in double quotes, each quote doubled; a cell a spreadsheet
 * would read as a formula (its first character = + - @, a tab or a carriage return) starts with '. */
void class_text_csv(FILE *f, const char *s);
/* A score as the book and the report print it: at most 2 decimals, no trailing zeros ("7.5", "10"). */
char *class_text_number(double x, char *out, size_t size);
#endif
