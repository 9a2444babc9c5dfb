/* Grader machinery: not part of any assignment. A set of names (grade_names.h). */
#include "grade_names.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static uint64_t name_hash(const char *s)
{
    uint64_t h = 0xcbf29ce484222325ull;  /* FNV-1a */
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 0x100000001b3ull;
    return h;
}

/* The slot that holds name, or the empty slot where it would go (the table is never full). */
static size_t slot_of(char *const *slots, size_t capacity, const char *name)
{
    size_t i = (size_t)name_hash(name) & (capacity - 1);
    while (slots[i] && strcmp(slots[i], name)) i = (i + 1) & (capacity - 1);
    return i;
}

/* Doubles the table (or makes the first one), moving every name to its new slot. */
static bool grow(grade_names *set)
{
    size_t capacity = set->capacity ? 2 * set->capacity : 64;
    char **slots = calloc(capacity, sizeof *slots);
    if (!slots) return false;
    for (size_t i = 0; i < set->capacity; i++)
        if (set->slots[i]) slots[slot_of(slots, capacity, set->slots[i])] = set->slots[i];
    free(set->slots);
    set->slots = slots;
    set->capacity = capacity;
    return true;
}

bool grade_names_add(grade_names *set, const char *name)
{
    if (2 * (set->count + 1) > set->capacity && !grow(set)) return false;
    size_t i = slot_of(set->slots, set->capacity, name);
    if (set->slots[i]) return true;
    if (!(set->slots[i] = strdup(name))) return false;
    set->count++;
    return true;
}

bool grade_names_has(const grade_names *set, const char *name)
{
    return set->capacity && set->slots[slot_of(set->slots, set->capacity, name)];
}

void grade_names_free(grade_names *set)
{
    if (!set) return;
    for (size_t i = 0; i < set->capacity; i++) free(set->slots[i]);
    free(set->slots);
    *set = (grade_names){0};
}
