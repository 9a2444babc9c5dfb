/* Grader machinery: not part of any assignment.
 * A set of names (symbols, for the object inspection): add and look up in constant time on
 * average, so that an object of 100,000 symbols is inspected in time linear in its size, where a
 * search through a listing of names grew with the square. Open addressing with FNV-1a; the names
 * are copied in. */
#ifndef PL_GRADE_NAMES_H
#define PL_GRADE_NAMES_H

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    char **slots;     /* capacity entries, NULL where empty; each a malloc'd copy */
    size_t capacity;  /* a power of two, at least twice count */
    size_t count;
} grade_names;

/* Adds name (a copy); true when it is in the set afterwards, false only when out of memory. */
bool grade_names_add(grade_names *set, const char *name);
/* Whether name is in the set (an empty set holds nothing). */
bool grade_names_has(const grade_names *set, const char *name);
/* Frees every name and the table; the set is empty again. NULL-safe. */
void grade_names_free(grade_names *set);

#endif
