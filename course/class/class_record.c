/* Instructor tooling: not part of any assignment.
 * What is kept of a grading. Each unit's folder, students/STUDENT/partP-KEY/, holds its outcome,
 * unit.json (status, score; written before the folder is moved into place, so a unit there is
 * whole): a unit whose folder is there under its current key is not graded again, even when the
 * run that made it was killed before the student's other parts. The student's record,
 * students/STUDENT/record.json, is every part's outcome in one atomic write, made once all their
 * parts are there; only then are the part folders it no longer names removed, so a run killed at
 * any moment leaves the old record with the folders it names, or the new one with its own. The
 * grade book and the report show a student's scores only when every part of theirs is there. A unit
 * that timed out stays (its submission hangs: a result); one whose grader failed is graded again. */
#include "class.h"
#include "../../framework/file.h"
#include <dirent.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define RECORD_SCHEMA "pathlab-class-record/1"
#define RECORD_MAX (256 * 1024)   /* a record is ~1 KB */

static void record_path(const class_run *r, const class_student *s, char *out, size_t size)
{
    snprintf(out, size, "%s/students/%s/record.json", r->o->out, s->folder);
}

/* ---- a unit's outcome, unit.json in its folder ---------------------------------------------- */

static json_t *unit_json(const class_unit *u)
{
    return json_pack("{s:i, s:s, s:s, s:s, s:f, s:f}", "part", u->part, "key", u->key, "status", u->status, "why", u->why,
                     "score", u->score, "max_score", u->max_score);
}

bool class_record_unit_write(const class_unit *u, const char *folder)
{
    char path[1600];
    snprintf(path, sizeof path, "%s/unit.json", folder);
    json_t *j = unit_json(u);
    char *text = j ? json_dumps(j, JSON_INDENT(2) | JSON_SORT_KEYS) : NULL;
    json_decref(j);
    pl_diag diag = pl_diag_default();
    bool ok = text && file_write_atomic(path, text, strlen(text), &diag) == PL_OK;
    free(text);
    return ok;
}

/* Unit u's outcome from its folder (the one its key names), when it is there and is u's. */
static void read_unit(const class_run *r, const class_student *s, class_unit *u)
{
    /* The folder its current key names: a folder of an older key is another unit's. */
    char path[1600], *text;
    size_t len;
    class_unit_folder(r, s, u, path, sizeof path);
    strcat(path, "/unit.json");
    if (file_read_all(path, "unit", RECORD_MAX, &text, &len, NULL) != PL_OK) return;
    json_t *j = json_loadb(text, len, JSON_REJECT_DUPLICATES, NULL);
    free(text);
    const char *key = json_string_value(json_object_get(j, "key"));
    const char *status = json_string_value(json_object_get(j, "status"));
    const char *why = json_string_value(json_object_get(j, "why"));
    if (json_integer_value(json_object_get(j, "part")) == u->part && key && !strcmp(key, u->key) && status) {
        snprintf(u->status, sizeof u->status, "%s", status);
        snprintf(u->why, sizeof u->why, "%s", why ? why : "");
        u->score = json_number_value(json_object_get(j, "score"));
        u->max_score = json_number_value(json_object_get(j, "max_score"));
        u->current = strcmp(status, "grader_failed") != 0;
    }
    json_decref(j);
}

void class_record_read(const class_run *r, class_student *s)
{
    if (strcmp(s->status, "ok")) return;
    for (int u = 0; u < s->num_units; u++) read_unit(r, s, &s->units[u]);
}

/* ---- the student's record ------------------------------------------------------------------------ */

bool class_record_complete(const class_student *s)
{
    for (int u = 0; u < s->num_units; u++)
        if (!s->units[u].status[0]) return false;
    return s->num_units > 0;
}

/* Removes the student's part folders the record does not name (older keys). */
static void remove_stale(const class_run *r, const class_student *s)
{
    char dir[1500];
    snprintf(dir, sizeof dir, "%s/students/%s", r->o->out, s->folder);
    /* Only folders named part*: record.json and anything else stay. */
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));) {
        if (strncmp(e->d_name, "part", 4)) continue;
        bool named = false;
        for (int u = 0; u < s->num_units && !named; u++) {
            char name[64];
            snprintf(name, sizeof name, "part%d-%s", s->units[u].part, s->units[u].key);
            named = !strcmp(name, e->d_name);
        }
        char path[1800];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (!named) class_remove_tree(path);
    }
    if (d) closedir(d);
}

bool class_record_write(const class_run *r, const class_student *s)
{
    json_t *units = json_array();
    for (int u = 0; units && u < s->num_units; u++) json_array_append_new(units, unit_json(&s->units[u]));
    json_t *root = json_pack("{s:s, s:s, s:s, s:o}", "schema", RECORD_SCHEMA, "id", s->shown, "submission",
                             s->entry_shown, "units", units);
    char *text = root ? json_dumps(root, JSON_INDENT(2) | JSON_SORT_KEYS) : NULL;
    json_decref(root);
    char path[1500];
    record_path(r, s, path, sizeof path);
    pl_diag diag = pl_diag_default();
    bool ok = text && file_write_atomic(path, text, strlen(text), &diag) == PL_OK;
    free(text);
    if (!ok) fprintf(stderr, "grade-class: cannot write %s\n", path);
    else remove_stale(r, s);
    return ok;
}
