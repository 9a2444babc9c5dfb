/* Grader machinery: not part of any assignment.
 * The manifest (grade_manifest.h): a submitted part's folder, read as data. Only files named
 * [a-z0-9_]+.c or .h, of bounded size and number, valid UTF-8 text without NUL bytes, are taken;
 * anything else that ends like code is refused, so a student never loses a file silently; what does
 * not end like code (a patch's .orig, notes, .DS_Store) is passed over, never read or named. */
#include "grade_manifest.h"
#include "grade_fmt.h"
#include "../framework/file.h"
#include "../framework/utf8.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Whether name is [a-z0-9_]{1,GRADE_SOURCE_NAME-2} followed by .c or .h. */
static bool source_name(const char *name)
{
    size_t n = strlen(name);
    if (n < 3 || n > GRADE_SOURCE_NAME || name[n - 2] != '.' || (name[n - 1] != 'c' && name[n - 1] != 'h')) return false;
    return strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789_") == n - 2;
}

/* Whether name ends like C code (.c or .h, any case): a file the student meant to be built. */
static bool looks_like_code(const char *name)
{
    size_t n = strlen(name);
    return n >= 2 && name[n - 2] == '.' && strchr("cChH", name[n - 1]);
}

/* What a refused entry is (its name is never quoted: a name is the student's choice, and results.json
 * is Markdown a course platform renders), as the why's count: 1 a folder, 2 a link, 3 another kind. */
static long entry_kind(const struct stat *st)
{
    return S_ISDIR(st->st_mode) ? 1 : S_ISLNK(st->st_mode) ? 2 : 3;
}

/* A why of code about the submitted file name (one the manifest took: safe to name). */
static bool refused(grade_why *why, grade_why_code code, const char *name)
{
    *why = grade_why_of(code);
    if (name) snprintf(why->file, sizeof why->file, "%s", name);
    return false;
}

/* One entry of the part's folder: taken into m, passed over (*ignored: never read, never named to a
 * tool), or refused with why. Anything that ends like code and is not a plain file with a plain
 * name is refused, so a student never loses a file silently; everything else (direct.c.orig,
 * notes.txt, a folder, a hidden file) is no code and is passed over. */
static bool manifest_entry(const char *dir, const char *name, grade_manifest *m, bool *ignored, grade_why *why)
{
    grade_path_buf path;
    struct stat st;
    bool code = looks_like_code(name) && name[0] != '.';
    *ignored = false;
    if (!grade_join(dir, name, path, sizeof path) || lstat(path, &st) != 0)
        return refused(why, GRADE_WHY_ENTRY_UNREADABLE, NULL);
    if (!code) return *ignored = true;
    if (!S_ISREG(st.st_mode)) {
        refused(why, GRADE_WHY_NOT_A_FILE, NULL);
        why->count = entry_kind(&st);
        return false;
    }
    if (!source_name(name)) return refused(why, GRADE_WHY_BAD_NAME, NULL);
    if (st.st_size > GRADE_SOURCE_BYTES) return refused(why, GRADE_WHY_FILE_TOO_BIG, name);
    if (m->count == GRADE_SOURCE_FILES) return refused(why, GRADE_WHY_TOO_MANY_FILES, NULL);
    size_t n = strlen(name);  /* fits: source_name bounds it; a longer name is refused all the same */
    if (n >= sizeof m->names[0]) return refused(why, GRADE_WHY_BAD_NAME, NULL);
    memcpy(m->names[m->count++], name, n + 1);
    return true;
}

bool grade_manifest_read(const char *dir, const char *folder, grade_manifest *m, grade_why *why)
{
    m->count = 0;
    *why = grade_why_of(GRADE_WHY_NONE);
    DIR *d = opendir(dir);
    if (!d) return refused(why, GRADE_WHY_NO_FOLDER, NULL);
    bool ok = true;
    int passed_over = 0;
    for (struct dirent *e; ok && (e = readdir(d));) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        bool ignored;
        ok = manifest_entry(dir, e->d_name, m, &ignored, why);
        passed_over += ignored;
    }
    if (passed_over) fprintf(stderr, "grade: parts/%s: %d entries that are not C code passed over\n", folder, passed_over);
    closedir(d);
    /* Text, read as data: UTF-8 and no NUL byte (a compiler would read on past a NUL). */
    for (int i = 0; ok && i < m->count; i++) {
        grade_path_buf path;
        char *data = NULL;
        size_t len = 0;
        pl_diag diag = pl_diag_default();
        grade_join(dir, m->names[i], path, sizeof path);
        if (file_read_all(path, "submitted file", GRADE_SOURCE_BYTES, &data, &len, &diag) != PL_OK)
            ok = refused(why, GRADE_WHY_FILE_UNREADABLE, m->names[i]);
        else if (memchr(data, '\0', len) || utf8_valid_prefix(data, len) != len)
            ok = refused(why, GRADE_WHY_NOT_TEXT, m->names[i]);
        free(data);
    }
    if (ok && m->count == 0) ok = refused(why, GRADE_WHY_NO_C_FILE, NULL);
    return ok;
}
