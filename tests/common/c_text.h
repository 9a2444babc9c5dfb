/* Test machinery: not part of any assignment. C source read as text by the tests that check the
 * project's own code (the grader's layout rules, the framework headers' word on what parts may call):
 * its code alone, so that a word in a comment or a string is never taken for a call or a declaration. */
#ifndef PL_TEST_C_TEXT_H
#define PL_TEST_C_TEXT_H

#include <stdbool.h>

/* A copy of text (to free) of the same length, with its comments, strings and character constants
 * blanked (their quotes kept, line breaks kept, so offsets and line numbers still hold) and, when
 * directives is true, its preprocessor lines too (a line continued by '\' with them); NULL without
 * memory. */
char *c_text_code(const char *text, bool directives);

#endif
