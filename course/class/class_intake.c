/* Instructor tooling: not part of any assignment.
 * Intake: the submissions folder as a list of students, in the order of their names' bytes.
 *
 * A submission is a folder or a .zip in the folder (a platform's export, a set of repository
 * clones); anything else is listed as ignored, and names starting with '.' are skipped. The
 * student's id is the submission's name (less .zip), or the roster's id for that name. What
 * stops a submission from being graded here, as a status with words:
 *   link            the entry is a symbolic link: never followed
 *   no_id           no usable id (empty, or over CLASS_ID_MAX bytes)
 *   duplicate_id    two or more submissions with one id: none is graded, the instructor keeps one
 *   not_in_roster   a roster was given and does not name the submission
 *   no_submission   a roster's student with no submission in the folder
 * (class_unpack.c adds the refusals of a submission's content.) */
#include "class.h"
#include "class_text.h"
#include "../shared/key.h"
#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* ---- the roster: "SUBMISSION,ID[,NAME]" lines ---------------------------------------------- */

typedef struct {
    char entry[CLASS_NAME_MAX], id[CLASS_ID_MAX], name[CLASS_NAME_MAX];
    bool used;
} roster_line;

/* The next CSV field of *p into out (RFC 4180 quotes allowed); false when it does not fit. */
static bool csv_field(const char **p, char *out, size_t size)
{
    size_t n = 0;
    const char *s = *p;
    bool quoted = *s == '"';
    if (quoted) s++;
    for (; *s && (quoted || *s != ','); s++) {
        if (quoted && *s == '"') {
            if (s[1] != '"') { s++; break; }
            s++;
        }
        if (n + 1 >= size) return false;
        out[n++] = *s;
    }
    out[n] = '\0';
    *p = *s == ',' ? s + 1 : s;
    return true;
}

/* One line into l: false with why (the line is the instructor's to fix). */
static bool roster_parse(char *line, roster_line *l, const char **why)
{
    /* A line from Windows keeps its CR out of the last field. */
    line[strcspn(line, "\r\n")] = '\0';
    const char *p = line;
    memset(l, 0, sizeof *l);
    if (!csv_field(&p, l->entry, sizeof l->entry) || !csv_field(&p, l->id, sizeof l->id) ||
        !csv_field(&p, l->name, sizeof l->name))
        return *why = "a field is too long", false;
    if (!l->entry[0] || !l->id[0]) return *why = "expected SUBMISSION,ID[,NAME]", false;
    return true;
}

/* Whether an earlier line names the same submission (then why says so: which line counts?). */
static bool roster_named(const roster_line *lines, int n, const char *entry, const char **why)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(lines[i].entry, entry)) return *why = "names a submission an earlier line names", true;
    return false;
}

/* The roster's lines into *lines (malloc'd); -1 with a located message when it cannot be used. */
static int roster_read(const char *path, roster_line **lines)
{
    FILE *f = fopen(path, "r");
    struct stat st;
    if (!f || fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        if (f) fclose(f);
        return fprintf(stderr, "grade-class: %s: cannot read the roster (a regular file)\n", path), -1;
    }
    *lines = calloc(CLASS_MAX_STUDENTS, sizeof **lines);
    /* Line by line, each bounded: a line longer than the buffer is refused, never split in two. */
    char line[CLASS_ROSTER_LINE + 2];
    int n = 0, number = 0;
    const char *why = NULL;
    while (*lines && !why && fgets(line, sizeof line, f)) {
        number++;
        if (!strchr(line, '\n') && !feof(f)) why = "longer than 4096 bytes";
        else if (line[strspn(line, " \t\r\n")] == '\0' || line[0] == '#') continue;
        else if (number == 1 && !strncasecmp(line, "submission,", 11)) continue;  /* a header line */
        else if (n == CLASS_MAX_STUDENTS) why = "more lines than CLASS_MAX_STUDENTS (4096)";
        else if (roster_parse(line, &(*lines)[n], &why) && !roster_named(*lines, n, (*lines)[n].entry, &why)) n++;
    }
    fclose(f);
    if (!*lines) return fprintf(stderr, "grade-class: out of memory\n"), -1;
    if (why) {
        fprintf(stderr, "grade-class: %s:%d: %s\n", path, number, why);
        free(*lines);
        return -1;
    }
    return n;
}

/* The roster's line for a submission: its name, or its name less ".zip". */
static roster_line *roster_find(roster_line *lines, int n, const char *entry, bool is_zip)
{
    /* A roster may name "alice" or "alice.zip" for the submission alice.zip. */
    size_t len = strlen(entry) - (is_zip ? 4 : 0);
    for (int i = 0; i < n; i++)
        if (!strcmp(lines[i].entry, entry) || (strlen(lines[i].entry) == len && !strncmp(lines[i].entry, entry, len)))
            return &lines[i];
    return NULL;
}

/* ---- one student ---------------------------------------------------------------------------- */

static void refuse(class_student *s, const char *status, const char *why)
{
    if (strcmp(s->status, "ok")) return;  /* the first reason stands */
    snprintf(s->status, sizeof s->status, "%s", status);
    snprintf(s->why, sizeof s->why, "%s", why);
}

/* Its folder under students/: the id when it is a plain short name, else "_" and the id's key (no
 * plain name starts with "_"), so that no id becomes a path ("..", "/", a name the file system
 * would alter). */
static void results_folder(class_student *s)
{
    size_t len = strlen(s->id);
    bool plain = len > 0 && len <= 64 && isalnum((unsigned char)s->id[0]);
    for (size_t i = 0; plain && i < len; i++) plain = isalnum((unsigned char)s->id[i]) || strchr("._@+-", s->id[i]);
    if (plain) snprintf(s->folder, sizeof s->folder, "%s", s->id);
    else {
        char hex[17];
        key_hex(key_str(KEY_START, s->id), hex);
        snprintf(s->folder, sizeof s->folder, "_%s", hex);
    }
}

/* A student from a submission's name (and the roster's line for it, or NULL). */
static void student_init(class_student *s, const char *entry, bool is_zip, const roster_line *l, bool roster)
{
    memset(s, 0, sizeof *s);
    snprintf(s->status, sizeof s->status, "ok");
    snprintf(s->entry, sizeof s->entry, "%s", entry);
    s->is_zip = is_zip;
    class_text_shown(entry, strlen(entry), s->entry_shown, sizeof s->entry_shown);
    size_t len = strlen(entry) - (is_zip ? 4 : 0);
    if (l) {
        snprintf(s->id, sizeof s->id, "%s", l->id);
        class_text_shown(l->name, strlen(l->name), s->name, sizeof s->name);
    }
    else if (len < sizeof s->id) memcpy(s->id, entry, len), s->id[len] = '\0';
    class_text_shown(s->id, strlen(s->id), s->shown, sizeof s->shown);
    if (roster && !l) refuse(s, "not_in_roster", "the roster does not name this submission: add it to the roster");
    if (!s->id[0]) refuse(s, "no_id", len ? "its name is too long to be an id (over 127 bytes)" : "its name gives no id");
    results_folder(s);
}

/* ---- the folder ------------------------------------------------------------------------------ */

static int compare_entries(const void *a, const void *b)
{
    return strcmp(((const class_student *)a)->entry, ((const class_student *)b)->entry);
}

static int compare_ids(const void *a, const void *b)
{
    const class_student *const *x = a, *const *y = b;
    int c = strcmp((*x)->id, (*y)->id);
    return c ? c : strcmp((*x)->entry, (*y)->entry);
}

/* Two submissions with one id: each is refused, naming the others. */
static void mark_duplicates(class_run *r)
{
    /* Sorted by id, equal ids are neighbours: each run of two or more is one duplicate. */
    class_student **by_id = malloc((size_t)r->num_students * sizeof *by_id);
    if (!by_id) return;
    for (int i = 0; i < r->num_students; i++) by_id[i] = &r->students[i];
    qsort(by_id, (size_t)r->num_students, sizeof *by_id, compare_ids);
    for (int i = 0, j; i < r->num_students; i = j) {
        for (j = i + 1; j < r->num_students && !strcmp(by_id[i]->id, by_id[j]->id); j++) continue;
        if (j - i < 2 || !by_id[i]->id[0]) continue;
        for (int k = i; k < j; k++) {
            char why[600];
            int n = snprintf(why, sizeof why, "%d submissions have the id %s (", j - i, by_id[k]->shown);
            for (int m = i; m < j && n < (int)sizeof why; m++)
                n += snprintf(why + n, sizeof why - (size_t)n, "%s%s", m > i ? ", " : "", by_id[m]->entry_shown);
            if (n < (int)sizeof why) snprintf(why + n, sizeof why - (size_t)n, "): none is graded; keep one");
            refuse(by_id[k], "duplicate_id", why);
        }
    }
    free(by_id);
}

/* Notes an entry that is no submission in r->ignored (escaped, cut with "..."). */
static void note_ignored(class_run *r, const char *name)
{
    char shown[CLASS_SHOWN_MAX];
    size_t n = strlen(r->ignored);
    class_text_shown(name, strlen(name), shown, sizeof shown);
    if (n + strlen(shown) + 8 < sizeof r->ignored) snprintf(r->ignored + n, sizeof r->ignored - n, "%s%s", n ? ", " : "", shown);
    else if (n + 4 < sizeof r->ignored && !strstr(r->ignored, "...")) strcat(r->ignored, " ...");
}

/* One entry of the folder: a student, an ignored name, or nothing (a dot name). */
static void read_entry(class_run *r, const char *dir, const char *name, roster_line *lines, int num_lines)
{
    char path[CLASS_PATH_MAX + CLASS_NAME_MAX];
    struct stat st;
    /* lstat: a link is seen as a link, never as what it points to. */
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (name[0] == '.' || lstat(path, &st) != 0) return;
    size_t len = strlen(name);
    bool zip = len > 4 && !strcasecmp(name + len - 4, ".zip");
    bool link = S_ISLNK(st.st_mode);
    if ((!link && !S_ISDIR(st.st_mode) && !(S_ISREG(st.st_mode) && zip)) || r->num_students == CLASS_MAX_STUDENTS) {
        note_ignored(r, name);
        return;
    }
    roster_line *l = num_lines >= 0 ? roster_find(lines, num_lines, name, zip) : NULL;
    if (l) l->used = true;
    class_student *s = &r->students[r->num_students++];
    student_init(s, name, zip && !link, l, num_lines >= 0);
    if (link) refuse(s, "link", "a symbolic link: not followed");
}

/* A roster's students with no submission, after the submissions. */
static void add_absent(class_run *r, const roster_line *lines, int n)
{
    for (int i = 0; i < n && r->num_students < CLASS_MAX_STUDENTS; i++) {
        if (lines[i].used) continue;
        class_student *s = &r->students[r->num_students++];
        student_init(s, lines[i].entry, false, &lines[i], true);
        refuse(s, "no_submission", "the roster names this student, and the folder holds no submission of that name");
    }
}

bool class_intake(class_run *r)
{
    roster_line *lines = NULL;
    int num_lines = r->o->roster ? roster_read(r->o->roster, &lines) : -1;
    if (r->o->roster && num_lines < 0) return false;
    DIR *d = opendir(r->o->submissions);
    r->students = calloc(CLASS_MAX_STUDENTS, sizeof *r->students);
    if (!d || !r->students) {
        fprintf(stderr, "grade-class: %s: cannot read the submissions folder\n", r->o->submissions);
        if (d) closedir(d);
        free(lines);
        return false;
    }
    /* The folder's entries, then in byte order (readdir's order is the file system's: a Slurm task
     * finds its student by index, so every run must list them alike). */
    for (struct dirent *e; (e = readdir(d));) read_entry(r, r->o->submissions, e->d_name, lines, num_lines);
    closedir(d);
    qsort(r->students, (size_t)r->num_students, sizeof *r->students, compare_entries);
    add_absent(r, lines, num_lines);
    mark_duplicates(r);
    free(lines);
    return true;
}
