/* Growable arrays: the one helper behind every array built by appending (the scene's arrays, the
 * COLLADA loader's number lists, the release stripper's task list). Not part of any assignment.
 *
 * The array stays an ordinary typed pointer with an int count and an int capacity beside it, so
 * code that reads it (s->triangles[i]) never sees the helper. Appending one element x:
 *
 *     if (buf_append(&list->v, &list->count, &list->cap, sizeof x, &x) < 0) return out_of_memory;
 * Parts may not call: none of these (every function here is static inline).
 */
#ifndef PL_BUF_H
#define PL_BUF_H

#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The room a first append makes: small arrays (a scene's few lights) stay small. */
#define BUF_FIRST_CAPACITY 16

/* Makes room for one element more than `count` in data, an array of `size`-byte elements with
 * room for *cap of them (NULL and 0 when empty). With room to spare it returns data unchanged.
 * Otherwise it doubles the room (to at least count + 1), reallocs, updates *cap and returns the
 * grown array, which replaces data. NULL when the array cannot grow: no memory, or the count would
 * pass INT_MAX or the bytes SIZE_MAX. Then data and *cap are unchanged and data is still the
 * caller's to free. */
static inline void *buf_grow(void *data, int count, int *cap, size_t size)
{
    if (count < *cap) return data;
    if (count < 0 || count == INT_MAX || size == 0) return NULL;
    /* Doubling keeps appending n elements O(n) in all; the checks keep every size representable. */
    size_t room = *cap < BUF_FIRST_CAPACITY / 2 ? BUF_FIRST_CAPACITY : 2 * (size_t)*cap;
    if (room <= (size_t)count) room = (size_t)count + 1;
    if (room > INT_MAX) room = INT_MAX;  /* still > count, since count < INT_MAX */
    if (room > SIZE_MAX / size) return NULL;
    void *grown = realloc(data, room * size);
    if (!grown) return NULL;
    *cap = (int)room;
    return grown;
}

/* Appends a copy of elem (size bytes) to the array whose address is array_address (a T ** for a
 * T * array with *count elements and room for *cap), growing it by buf_grow. Returns the new
 * element's index, or -1 (nothing changed) when the array cannot grow. */
static inline int buf_append(void *array_address, int *count, int *cap, size_t size, const void *elem)
{
    /* The caller's pointer is read and written with memcpy: a T * and a void * share their
     * representation on every platform pathlab builds on, and a (void **) cast would break C's
     * aliasing rule. */
    void *data;
    memcpy(&data, array_address, sizeof data);
    void *grown = buf_grow(data, *count, cap, size);
    if (!grown) return -1;
    memcpy(array_address, &grown, sizeof grown);
    memcpy((char *)grown + (size_t)*count * size, elem, size);
    return (*count)++;
}

#endif
