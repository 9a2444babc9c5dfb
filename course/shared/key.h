/* Instructor tooling: not part of any assignment.
 * Content keys: what a result was made from, as one 64-bit FNV-1a hash, so that a tool redoes a
 * result only when one of its inputs changed (bin/references: a reference; bin/grade-class: a
 * student's graded part). A key detects change; it is no defence against anyone forging inputs
 * (the files hashed are the course's own, or a submission the tool staged itself). */
#ifndef PL_COURSE_KEY_H
#define PL_COURSE_KEY_H
#include <stddef.h>
#include <stdint.h>

#define KEY_START 1469598103934665603ull  /* FNV-1a's offset basis: the key of nothing */

/* Each returns the key h extended by its input. */
uint64_t key_bytes(uint64_t h, const void *data, size_t len);
uint64_t key_str(uint64_t h, const char *s);  /* the string and its NUL: "ab","c" differs from "a","bc" */
/* The file's name as `name` and its content (up to 1 GiB), or the name and "missing" when it cannot
 * be read: a file that appears or disappears changes the key. key_file names it by its path. */
uint64_t key_file_as(uint64_t h, const char *path, const char *name);
uint64_t key_file(uint64_t h, const char *path);
/* Every .c and .h file in dir and in its folders one level down, in name order. */
uint64_t key_sources(uint64_t h, const char *dir);
/* The key as 16 hexadecimal digits. */
void key_hex(uint64_t h, char out[17]);
#endif
