/* Instructor tooling: not part of any assignment.
 * A tally: labels ("test bvh_build__leaf_size", "too dark by 1/pi"), each with the students it
 * counts, for the class report's tables; sorted most frequent first, then by label. */
#ifndef PL_CLASS_TALLY_H
#define PL_CLASS_TALLY_H

typedef struct {
    char label[200];
    int count;
    int *students;       /* indices into the class's students, in the order added */
} tally_item;

typedef struct {
    tally_item *items;
    int num, cap;
} tally;

/* Counts student under label (a new item when the label is new); student -1 only makes the item. */
void tally_add(tally *t, const char *label, int student);
/* Most frequent first; equal counts by label, in byte order. */
void tally_sort(tally *t);
void tally_free(tally *t);
#endif
