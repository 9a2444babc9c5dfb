/* Instructor tooling: not part of any assignment. A tally of labels and students (class_tally.h). */
#include "class_tally.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tally_add(tally *t, const char *label, int student)
{
    /* A linear search: a part has tens of tests and cases, a class at most a few thousand students. */
    tally_item *it = NULL;
    for (int i = 0; i < t->num && !it; i++)
        if (!strcmp(t->items[i].label, label)) it = &t->items[i];
    if (!it) {
        /* A new label: the array doubles when full (a failed allocation drops the count, never crashes). */
        if (t->num == t->cap) {
            int cap = t->cap ? 2 * t->cap : 16;
            tally_item *grown = realloc(t->items, (size_t)cap * sizeof *grown);
            if (!grown) return;
            t->items = grown, t->cap = cap;
        }
        it = &t->items[t->num++];
        memset(it, 0, sizeof *it);
        snprintf(it->label, sizeof it->label, "%s", label);
    }
    if (student < 0) return;
    /* One more student: the list grows by one (a label rarely counts more than a class). */
    int *grown = realloc(it->students, (size_t)(it->count + 1) * sizeof *grown);
    if (grown) it->students = grown, it->students[it->count++] = student;
}

static int by_count(const void *a, const void *b)
{
    const tally_item *x = a, *y = b;
    return x->count != y->count ? y->count - x->count : strcmp(x->label, y->label);
}

void tally_sort(tally *t)
{
    if (t->num) qsort(t->items, (size_t)t->num, sizeof *t->items, by_count);
}

void tally_free(tally *t)
{
    for (int i = 0; i < t->num; i++) free(t->items[i].students);
    free(t->items);
    *t = (tally){0};
}
