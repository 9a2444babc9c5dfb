/* Instructor tooling: not part of any assignment.
 * Keys: what one graded part (a unit: part P of one student) was made from. A unit is graded again
 * exactly when its key differs from the one its student's record holds, and its key covers:
 *   the submission   every file of the student's part folder as staged (names and bytes)
 *   the seed         the student's (class_seed.c), so a new secret re-grades everyone
 *   the deadline     --timeout: a longer one can turn "timed out" into a score
 *   the course, for part P:
 *     its cases      part P's entries of grading/cases.json and grading/hidden/cases.json (member
 *                    by member, as data: a reformatted file changes nothing) and the family alpha
 *     their files    each case's scene and every flag that names a file (an environment map)
 *     references     reference_images/partP/ and reference_images/hidden/partP/, every file
 *     the judge      tests/partP/, tests/common/, tests/data/ (P's unit tests and their helpers)
 *     the rest       the grader's, the framework's and third_party's sources, the Makefiles, and
 *                    the course's solutions of the other parts (a submission's part is linked with
 *                    them)
 * So editing a case of part 3 or rendering its references again re-grades part 3 of every student
 * and nothing else; a change to the grader or the framework re-grades everything; a student's
 * part folder that changed re-grades that part of that student. */
#include "class.h"
#include "../shared/key.h"
#include <dirent.h>
#include <fnmatch.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define KEY_LABEL "pathlab-class-key/1"

/* ---- a folder's every file ----------------------------------------------------------------- */

static int by_bytes(const struct dirent **a, const struct dirent **b) { return strcmp((*a)->d_name, (*b)->d_name); }
static int not_dots(const struct dirent *e) { return strcmp(e->d_name, ".") && strcmp(e->d_name, ".."); }

/* Every file and folder under dir, in byte order, named relative to it (as `name`), files with
 * their content; a link or a device by its name alone. "missing" when dir is not a folder. */
static uint64_t key_tree(uint64_t h, const char *dir, const char *name, int depth)
{
    struct dirent **list;
    int n = depth > CLASS_DEPTH ? -1 : scandir(dir, &list, not_dots, by_bytes);
    if (n < 0) return key_str(key_str(h, name), "missing");
    h = key_str(h, name);
    for (int i = 0; i < n; i++) {
        char path[CLASS_PATH_MAX * 2], sub[CLASS_PATH_MAX * 2];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, list[i]->d_name);
        snprintf(sub, sizeof sub, "%s/%s", name, list[i]->d_name);
        if (lstat(path, &st) != 0) h = key_str(h, sub);
        else if (S_ISDIR(st.st_mode)) h = key_tree(h, path, sub, depth + 1);
        else if (S_ISREG(st.st_mode)) h = key_file_as(h, path, sub);
        else h = key_str(key_str(h, sub), "not a file");
        free(list[i]);
    }
    free(list);
    return h;
}

/* Every folder dir/<pattern> (the part folders), by key_tree. */
static uint64_t key_matching(uint64_t h, const char *dir, const char *pattern, const char *skip)
{
    struct dirent **list;
    int n = scandir(dir, &list, not_dots, by_bytes);
    for (int i = 0; i < n; i++) {
        char path[CLASS_PATH_MAX * 2];
        snprintf(path, sizeof path, "%s/%s", dir, list[i]->d_name);
        if (!fnmatch(pattern, list[i]->d_name, 0) && (!skip || fnmatch(skip, list[i]->d_name, 0)))
            h = key_tree(h, path, list[i]->d_name, 0);
        free(list[i]);
    }
    if (n >= 0) free(list);
    return h;
}

/* ---- the course's part P ------------------------------------------------------------------- */

/* Part P's entry of a cases file, as data (sorted members, compact), and the file's family alpha. */
static uint64_t key_cases(uint64_t h, const char *path, int part)
{
    json_t *root = json_load_file(path, JSON_REJECT_DUPLICATES, NULL), *p;
    size_t i;
    h = key_str(h, path);
    json_array_foreach(json_object_get(root, "parts"), i, p)
    {
        if (json_integer_value(json_object_get(p, "part")) != part) continue;
        char *text = json_dumps(p, JSON_COMPACT | JSON_SORT_KEYS);
        if (text) h = key_str(h, text);
        free(text);
    }
    char *alpha = json_dumps(json_object_get(root, "family_alpha"), JSON_ENCODE_ANY);
    h = key_str(h, alpha ? alpha : "no alpha");
    free(alpha);
    json_decref(root);
    return h;
}

/* Each case's scene, and each flag that names a file (an environment map). */
static uint64_t key_case_files(uint64_t h, const grade_part_spec *p)
{
    for (int i = 0; i < p->num_cases; i++) {
        const grade_case *c = &p->cases[i];
        h = key_file(h, c->scene);
        for (int f = 0; f < c->num_flags; f++) {
            struct stat st;
            if (stat(c->flags[f], &st) == 0 && S_ISREG(st.st_mode)) h = key_file(h, c->flags[f]);
        }
    }
    return h;
}

/* What every part shares: the grader, the framework, vendored code, the Makefiles. */
static uint64_t key_shared(void)
{
    uint64_t h = key_str(KEY_START, KEY_LABEL);
    static const char *const sources[] = {"grader", "framework", "third_party"};
    static const char *const files[] = {"Makefile", "grader/grader.mk", "grader/seam/seam.mk"};
    for (size_t i = 0; i < sizeof sources / sizeof *sources; i++) h = key_sources(h, sources[i]);
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) h = key_file(h, files[i]);
    return key_tree(key_tree(h, "tests/common", "tests/common", 0), "tests/data", "tests/data", 0);
}

bool class_key_course(class_run *r)
{
    pl_diag diag = pl_diag_default();
    /* The grader's own loader: the same cases, points and tasks bin/grade will read. */
    grade_spec spec;
    if (grade_spec_load(GRADE_CASES, GRADE_HIDDEN_CASES, &spec, &diag) != PL_OK) {
        fprintf(stderr, "grade-class: %s\n", diag.error);
        return false;
    }
    uint64_t shared = key_shared();
    for (int k = 0; k < GRADE_MAX_PART; k++) {
        const grade_part_spec *p = &spec.parts[k];
        char dir[64], own[32];
        r->part_max[k] = p->unit_points;
        r->num_tasks[k] = p->num_tasks;
        memcpy(r->tasks[k], p->tasks, sizeof r->tasks[k]);
        for (int i = 0; i < p->num_cases; i++) r->part_max[k] += p->cases[i].points;
        snprintf(own, sizeof own, "part%d_*", k + 1);
        uint64_t h = key_bytes(shared, &k, sizeof k);
        h = key_cases(key_cases(h, GRADE_CASES, k + 1), GRADE_HIDDEN_CASES, k + 1);
        h = key_case_files(h, p);
        snprintf(dir, sizeof dir, "reference_images/part%d", k + 1);
        h = key_tree(h, dir, dir, 0);
        snprintf(dir, sizeof dir, "reference_images/hidden/part%d", k + 1);
        h = key_tree(h, dir, dir, 0);
        snprintf(dir, sizeof dir, "tests/part%d", k + 1);
        h = key_tree(h, dir, dir, 0);
        r->course_key[k] = key_matching(h, "parts", "part[1-9]_*", own);
    }
    grade_spec_free(&spec);
    return true;
}

void class_key_units(const class_run *r, class_student *s, const char *stage)
{
    char parts[1500], own[32];
    snprintf(parts, sizeof parts, "%s/parts", stage);
    for (int u = 0; u < s->num_units; u++) {
        class_unit *unit = &s->units[u];
        int k = unit->part - 1;
        /* The course's part, this student's seed and the deadline, then their part folder. */
        uint64_t h = key_bytes(r->course_key[k], &s->seed, sizeof s->seed);
        h = key_bytes(h, &r->o->timeout, sizeof r->o->timeout);
        snprintf(own, sizeof own, "part%d_*", unit->part);
        key_hex(key_matching(h, parts, own, NULL), unit->key);
    }
}
