/* Instructor tooling: not part of any assignment. Content keys (key.h). */
#include "key.h"
#include "../../framework/file.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define KEY_MAX_SOURCES 512   /* files key_sources reads: the course's largest folder has ~80 */

uint64_t key_bytes(uint64_t h, const void *data, size_t len)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < len; i++) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

uint64_t key_str(uint64_t h, const char *s) { return key_bytes(h, s, strlen(s) + 1); }

uint64_t key_file_as(uint64_t h, const char *path, const char *name)
{
    /* Read through the framework's reader: a FIFO or a device is "missing", never waited on. */
    char *data;
    size_t len;
    if (file_read_all(path, "file", (size_t)1 << 30, &data, &len, NULL) != PL_OK) return key_str(h, "missing");
    h = key_bytes(key_str(h, name), data, len);
    free(data);
    return h;
}

uint64_t key_file(uint64_t h, const char *path) { return key_file_as(h, path, path); }

static int compare_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* A C source or header, by its name. */
static bool is_source(const char *name)
{
    size_t len = strlen(name);
    return len > 2 && (!strcmp(name + len - 2, ".c") || !strcmp(name + len - 2, ".h"));
}

/* Adds dir's .c and .h files to names (at most KEY_MAX_SOURCES in all); with `descend`, those of
 * its folders too, one level down. */
static void list_sources(const char *dir, bool descend, char **names, int *n)
{
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d)) && *n < KEY_MAX_SOURCES;) {
        if (e->d_name[0] == '.') continue;
        char path[1300];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        /* stat follows a link: a linked folder of sources counts as the folder (the course's own tree). */
        if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
            if (descend) list_sources(path, false, names, n);
        }
        else if (is_source(e->d_name) && (names[*n] = strdup(path))) (*n)++;
    }
    if (d) closedir(d);
}

uint64_t key_sources(uint64_t h, const char *dir)
{
    char *names[KEY_MAX_SOURCES];
    int n = 0;
    /* In name order: readdir's order is the file system's, and a key must not depend on it. */
    list_sources(dir, true, names, &n);
    qsort(names, (size_t)n, sizeof *names, compare_names);
    for (int i = 0; i < n; i++) {
        h = key_file(h, names[i]);
        free(names[i]);
    }
    return h;
}

/* Fixed width: keys compare as strings and name folders of equal length. */
void key_hex(uint64_t h, char out[17]) { snprintf(out, 17, "%016llx", (unsigned long long)h); }
