/* Instructor tooling: not part of any assignment.
 * Unpack: a submission's part folders, copied (a folder) or extracted (a .zip) into a staging
 * folder the grader reads, as the autograder's run_autograder stages an upload.
 *
 * Both kinds are read through libarchive (a zip with its zip reader, a folder with its disk
 * reader, links never followed), so one loop checks every entry the same way, in two passes:
 *   1. list: every entry's path is made relative and checked (an absolute path or a ".." refuses
 *      the submission whole: it was made to escape its folder); entries are counted (a zip of more
 *      than CLASS_ENTRIES is refused before anything is decompressed);
 *   2. copy: only the part folders (part<N>_*) under the folder that holds them, found by
 *      run_autograder's rule: the top's parts/, the top itself, or one folder down, exactly one;
 *      regular files and folders only (a link, a device or a pipe is left out and said so), their
 *      declared sizes summed and bounded first, then the bytes actually written counted and bounded
 *      again as they come (a zip's header may lie: a zip bomb stops at the bound).
 * A file is created with O_EXCL | O_NOFOLLOW in folders this code made, so nothing a submission
 * names can write outside the staging folder. Refusals (s->status):
 *   empty        no file at all          no_parts      no part folder where run_autograder looks
 *   unsafe_path  an entry leaves its folder (absolute, "..")
 *   too_large    over a bound (entries, bytes, depth, a path's length)
 *   bad_zip      a zip libarchive cannot read, or an entry twice */
#include "class.h"
#include "class_text.h"
#include <archive.h>
#include <archive_entry.h>
#include <errno.h>
#include <fcntl.h>
#include <fnmatch.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define UNPACK_TOP_DEPTH 3    /* components that can lead to a part folder: X/parts/part1_raygen */

/* Why a submission is refused: a status code (the list above) and words naming the entry. */
typedef struct {
    const char *status;
    char why[400];
} refusal;

/* Sets r from a status, a reason and the entry's raw name (shown escaped); returns false. */
static bool refuse(refusal *r, const char *status, const char *reason, const char *raw)
{
    char shown[CLASS_SHOWN_MAX];
    r->status = status;
    if (raw) snprintf(r->why, sizeof r->why, "%s: %s", reason, class_text_shown(raw, strlen(raw), shown, 200));
    else snprintf(r->why, sizeof r->why, "%s", reason);
    return false;
}

/* ---- reading a submission: a zip or a folder, entry by entry ------------------------------- */

typedef struct {
    struct archive *a;
    bool disk;
    size_t prefix;            /* a folder's entries are named "FOLDER/...": this many bytes */
    int unnamed;              /* entries whose name libarchive could not convert: skipped */
    const class_student *s;
} source;

static bool source_open(source *src, const class_student *s, const char *path)
{
    /* One interface for both: libarchive's disk reader yields a folder's entries as its zip reader
     * yields a zip's, with the same types and names to check. */
    memset(src, 0, sizeof *src);
    src->s = s;
    src->disk = !s->is_zip;
    src->a = src->disk ? archive_read_disk_new() : archive_read_new();
    if (!src->a) return false;
    if (src->disk) {
        archive_read_disk_set_symlink_physical(src->a);  /* a link is an entry, never followed */
        archive_read_disk_set_behavior(src->a, ARCHIVE_READDISK_NO_XATTR | ARCHIVE_READDISK_NO_ACL |
                                                   ARCHIVE_READDISK_NO_FFLAGS | ARCHIVE_READDISK_NO_TRAVERSE_MOUNTS);
        src->prefix = strlen(path) + 1;
        return archive_read_disk_open(src->a, path) == ARCHIVE_OK;
    }
    archive_read_support_format_zip(src->a);
    return archive_read_open_filename(src->a, path, 64 * 1024) == ARCHIVE_OK;
}

static void source_close(source *src)
{
    if (src->a) archive_read_free(src->a);
    src->a = NULL;
}

/* The part folder an entry lies in, as the index of its component: rel's components split into
 * comp[0..n), the first that matches part[1-9]_* within UNPACK_TOP_DEPTH; -1 when none. */
static int part_component(char *const comp[], int n)
{
    for (int i = 0; i < n && i < UNPACK_TOP_DEPTH; i++)
        if (!fnmatch("part[1-9]_*", comp[i], 0)) return i;
    return -1;
}

/* rel made from a raw path: components without "" and "."; false (refused) on "..", an absolute
 * path, too deep or too long. */
static bool normalise(const char *raw, char rel[CLASS_PATH_MAX], refusal *why)
{
    if (raw[0] == '/') return refuse(why, "unsafe_path", "an entry with an absolute path", raw);
    if (strlen(raw) >= CLASS_PATH_MAX) return refuse(why, "too_large", "an entry's path is over 1024 bytes", NULL);
    char copy[CLASS_PATH_MAX];
    snprintf(copy, sizeof copy, "%s", raw);
    size_t n = 0;
    int depth = 0;
    rel[0] = '\0';
    for (char *save, *c = strtok_r(copy, "/", &save); c; c = strtok_r(NULL, "/", &save)) {
        if (!strcmp(c, ".")) continue;
        if (!strcmp(c, "..")) return refuse(why, "unsafe_path", "an entry leaves its folder (\"..\")", raw);
        if (++depth > CLASS_DEPTH) return refuse(why, "too_large", "an entry over 24 folders deep", NULL);
        n += (size_t)snprintf(rel + n, CLASS_PATH_MAX - n, "%s%s", n ? "/" : "", c);
    }
    return true;
}

/* Splits rel (modified) into its components; returns how many. */
static int split(char *rel, char *comp[CLASS_DEPTH + 1])
{
    int n = 0;
    for (char *save, *c = strtok_r(rel, "/", &save); c && n <= CLASS_DEPTH; c = strtok_r(NULL, "/", &save)) comp[n++] = c;
    return n;
}

/* Whether a folder's walk goes into this folder: near the top (where part folders are looked for:
 * not a dot folder or macOS's __MACOSX, as run_autograder's glob) or inside a part folder. */
static bool worth_descending(const char *rel)
{
    char copy[CLASS_PATH_MAX], *comp[CLASS_DEPTH + 1];
    snprintf(copy, sizeof copy, "%s", rel);
    int n = split(copy, comp);
    if (part_component(comp, n) >= 0) return true;
    return n < UNPACK_TOP_DEPTH && comp[n - 1][0] != '.' && strcmp(comp[n - 1], "__MACOSX");
}

/* The next entry: 1 with *e and its relative path, 0 at the end, -1 with why when the submission
 * is refused (unreadable, or an entry that leaves its folder). A folder's own entry is skipped. */
static int source_next(source *src, struct archive_entry **e, char rel[CLASS_PATH_MAX], refusal *why)
{
    for (;;) {
        int rc = archive_read_next_header(src->a, e);
        if (rc == ARCHIVE_EOF) return 0;
        if (rc < ARCHIVE_WARN) return refuse(why, "bad_zip", "libarchive cannot read it", NULL), -1;
        /* A name libarchive cannot convert (a UTF-8 name where no UTF-8 locale exists) is skipped,
         * and said so: it cannot be checked, so it is never written. */
        const char *raw = archive_entry_pathname(*e);
        if (!raw) raw = archive_entry_pathname_utf8(*e);
        if (!raw) {
            src->unnamed++;
            continue;
        }
        if (src->disk) raw = strlen(raw) > src->prefix ? raw + src->prefix : "";
        if (!normalise(raw, rel, why)) return -1;
        bool dir = archive_entry_filetype(*e) == AE_IFDIR;
        if (src->disk && dir && (!rel[0] || worth_descending(rel))) archive_read_disk_descend(src->a);
        if (rel[0]) return 1;  /* else the folder itself, or a zip entry "./" */
    }
}

/* ---- pass 1: the listing, and the folder that holds the part folders ------------------------ */

typedef struct {
    char (*dirs)[CLASS_PATH_MAX / 4];  /* folders within UNPACK_TOP_DEPTH components, implied or listed */
    int num_dirs, entries, files;
} listing;

static void add_dir(listing *l, const char *dir)
{
    for (int i = 0; i < l->num_dirs; i++)
        if (!strcmp(l->dirs[i], dir)) return;
    if (l->num_dirs < CLASS_ENTRIES && strlen(dir) < sizeof l->dirs[0]) snprintf(l->dirs[l->num_dirs++], sizeof l->dirs[0], "%s", dir);
}

/* Each folder an entry implies near the top: "a/b/c.c" implies a and a/b. */
static void add_entry(listing *l, const char *rel, bool is_dir)
{
    char copy[CLASS_PATH_MAX], *comp[CLASS_DEPTH + 1], dir[CLASS_PATH_MAX] = "";
    snprintf(copy, sizeof copy, "%s", rel);
    int n = split(copy, comp), upto = is_dir ? n : n - 1;
    size_t len = 0;
    for (int i = 0; i < upto && i < UNPACK_TOP_DEPTH; i++) {
        len += (size_t)snprintf(dir + len, sizeof dir - len, "%s%s", i ? "/" : "", comp[i]);
        add_dir(l, dir);
    }
}

/* Whether folder p ("" the top) holds a part folder. */
static bool has_parts(const listing *l, const char *p)
{
    size_t len = strlen(p);
    for (int i = 0; i < l->num_dirs; i++) {
        const char *d = l->dirs[i];
        if (len && (strncmp(d, p, len) || d[len] != '/')) continue;
        const char *rest = len ? d + len + 1 : d;
        if (!strchr(rest, '/') && !fnmatch("part[1-9]_*", rest, 0)) return true;
    }
    return false;
}

/* run_autograder's rule: TOP/parts, TOP, or exactly one folder X one down with X/parts or X. */
static bool find_root(const listing *l, char root[CLASS_PATH_MAX])
{
    if (has_parts(l, "parts")) return snprintf(root, CLASS_PATH_MAX, "parts"), true;
    if (has_parts(l, "")) return root[0] = '\0', true;
    int found = 0;
    for (int i = 0; i < l->num_dirs; i++) {
        const char *d = l->dirs[i];
        if (strchr(d, '/') || d[0] == '.' || !strcmp(d, "__MACOSX")) continue;
        char sub[CLASS_PATH_MAX];
        snprintf(sub, sizeof sub, "%s/parts", d);
        if (has_parts(l, sub)) found++, snprintf(root, CLASS_PATH_MAX, "%s", sub);
        else if (has_parts(l, d)) found++, snprintf(root, CLASS_PATH_MAX, "%s", d);
    }
    return found == 1;
}

/* Lists the submission; false when it is refused. */
static bool list_all(source *src, listing *l, refusal *why)
{
    struct archive_entry *e;
    char rel[CLASS_PATH_MAX];
    int rc;
    while ((rc = source_next(src, &e, rel, why)) == 1) {
        if (++l->entries > CLASS_ENTRIES) return refuse(why, "too_large", "more than 20000 entries", NULL);
        bool dir = archive_entry_filetype(e) == AE_IFDIR;
        l->files += !dir;
        add_entry(l, rel, dir);
    }
    return rc == 0;
}

/* ---- passes 2 and 3: the part folders' sizes, then their copy -------------------------------- */

typedef struct {
    const char *root;          /* the folder holding the part folders, "" the top */
    const char *dest;          /* STAGE/parts, or NULL: only sum the declared sizes */
    long long declared, written;
    int left_out;
    char left_names[240];      /* the first entries left out, escaped */
} copying;

/* Where an entry goes below dest ("part1_raygen/camera.c"), or false when it is not in a part
 * folder directly under the root. */
static bool target_of(const copying *c, const char *rel, char out[CLASS_PATH_MAX])
{
    size_t len = strlen(c->root);
    if (len && (strncmp(rel, c->root, len) || rel[len] != '/')) return false;
    const char *rest = len ? rel + len + 1 : rel;
    char first[CLASS_PATH_MAX];
    snprintf(first, sizeof first, "%.*s", (int)strcspn(rest, "/"), rest);
    if (fnmatch("part[1-9]_*", first, 0)) return false;
    snprintf(out, CLASS_PATH_MAX, "%s", rest);
    return true;
}

/* Makes dest/target's folders (all of them when the entry is a folder itself). */
static bool make_folders(const char *dest, const char *target, bool is_dir)
{
    char path[CLASS_PATH_MAX * 2];
    int n = snprintf(path, sizeof path, "%s/%s", dest, target);
    for (char *p = path + strlen(dest) + 1; n > 0 && *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(path, 0755) != 0 && errno != EEXIST) return false;
            *p = '/';
        }
    return !is_dir || mkdir(path, 0755) == 0 || errno == EEXIST;
}

/* Copies the entry's data into a new file dest/target, counting every byte against the bounds. */
static bool copy_file(source *src, copying *c, const char *target, refusal *why)
{
    char path[CLASS_PATH_MAX * 2];
    snprintf(path, sizeof path, "%s/%s", c->dest, target);
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) return refuse(why, "bad_zip", errno == EEXIST ? "an entry given twice" : "an entry cannot be written", target);
    static char buf[64 * 1024];
    long long mine = 0;
    ssize_t got;
    bool ok = true;
    while (ok && (got = archive_read_data(src->a, buf, sizeof buf)) > 0) {
        mine += got, c->written += got;
        if (mine > CLASS_FILE_BYTES) ok = refuse(why, "too_large", "a file over 2 MiB", target);
        else if (c->written > CLASS_EXTRACT_BYTES) ok = refuse(why, "too_large", "its part folders hold over 64 MiB", NULL);
        else ok = write(fd, buf, (size_t)got) == got || refuse(why, "bad_zip", "an entry cannot be written", target);
    }
    if (ok && got < 0) ok = refuse(why, "bad_zip", "an entry's data cannot be read", target);
    return close(fd) == 0 && ok;
}

/* Notes an entry left out (a link, a device, a pipe): counted, the first few named. */
static void leave_out(copying *c, const char *target)
{
    char shown[CLASS_SHOWN_MAX];
    size_t n = strlen(c->left_names);
    class_text_shown(target, strlen(target), shown, 100);
    if (c->left_out++ < 3 && n + strlen(shown) + 3 < sizeof c->left_names)
        snprintf(c->left_names + n, sizeof c->left_names - n, "%s%s", n ? ", " : "", shown);
}

/* One pass over the part folders' entries: the declared sizes (c->dest NULL), or the copy. */
static bool walk_parts(source *src, copying *c, refusal *why)
{
    struct archive_entry *e;
    char rel[CLASS_PATH_MAX], target[CLASS_PATH_MAX];
    int rc;
    while ((rc = source_next(src, &e, rel, why)) == 1) {
        if (!target_of(c, rel, target)) continue;
        mode_t type = archive_entry_filetype(e);
        bool regular = type == AE_IFREG && !archive_entry_hardlink(e), dir = type == AE_IFDIR;
        if (!c->dest) {
            c->declared += regular && archive_entry_size_is_set(e) ? archive_entry_size(e) : 0;
            if (c->declared > CLASS_EXTRACT_BYTES) return refuse(why, "too_large", "its part folders declare over 64 MiB", NULL);
            continue;
        }
        if (!regular && !dir) leave_out(c, target);
        else if (!make_folders(c->dest, target, dir)) return refuse(why, "bad_zip", "a folder cannot be made", target);
        else if (regular && !copy_file(src, c, target, why)) return false;
    }
    return rc == 0;
}

/* ---- a submission ------------------------------------------------------------------------------ */

/* Lists the submission and finds the folder holding its part folders (root); false refused. */
static bool find_parts(const class_student *s, const char *path, char root[CLASS_PATH_MAX], refusal *why)
{
    listing l = {.dirs = calloc(CLASS_ENTRIES, sizeof *l.dirs)};
    source src = {0};
    bool ok = l.dirs != NULL || refuse(why, "bad_zip", "out of memory", NULL);
    ok = ok && (source_open(&src, s, path) || refuse(why, "bad_zip", "libarchive cannot open it", NULL));
    ok = ok && list_all(&src, &l, why);
    source_close(&src);
    if (ok && l.files == 0) ok = refuse(why, "empty", "the submission holds no file", NULL);
    if (ok && !find_root(&l, root))
        ok = refuse(why, "no_parts", "no part folder was found (looked for parts/part1_raygen ... or the part folders "
                                     "themselves, at the top and one folder down, as the autograder does)", NULL);
    free(l.dirs);
    return ok;
}

void class_unpack(const class_run *r, class_student *s, const char *dest)
{
    if (strcmp(s->status, "ok")) return;
    char path[CLASS_PATH_MAX + CLASS_NAME_MAX], root[CLASS_PATH_MAX], parts[1500];
    snprintf(path, sizeof path, "%s/%s", r->o->submissions, s->entry);
    snprintf(parts, sizeof parts, "%s/parts", dest);
    refusal why = {0};
    copying c = {.root = root};
    source src = {0};
    bool ok = find_parts(s, path, root, &why);
    /* The declared sizes first, headers only; then the copy, each byte counted again. */
    for (int pass = 0; ok && pass < 2; pass++) {
        c.dest = pass ? parts : NULL;
        if (pass && ((mkdir(dest, 0755) != 0 && errno != EEXIST) || mkdir(parts, 0755) != 0))
            ok = refuse(&why, "bad_zip", "the staging folder cannot be made", NULL);
        ok = ok && (source_open(&src, s, path) || refuse(&why, "bad_zip", "libarchive cannot open it", NULL));
        ok = ok && walk_parts(&src, &c, &why);
        if (pass) c.left_out += src.unnamed;
        source_close(&src);
    }
    if (c.left_out)
        snprintf(s->left_out, sizeof s->left_out, "%d entr%s left out (links, devices, pipes, unreadable names): %s%s", c.left_out,
                 c.left_out == 1 ? "y" : "ies", c.left_names, c.left_out > 3 ? ", ..." : "");
    if (!ok) {
        snprintf(s->status, sizeof s->status, "%s", why.status);
        snprintf(s->why, sizeof s->why, "%s", why.why);
    }
}
