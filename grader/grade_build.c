/* Grader machinery: not part of any assignment.
 * The build stage of a submission: the pipeline's first untrusted stage. Whatever a build runs,
 * names or writes while it reads student files is not trusted afterwards, so:
 *
 *   manifest   the part's folder is read as data first: only files named [a-z0-9_]+.c or .h, of
 *              bounded size and number, valid UTF-8 text (grade_manifest_read). No submitted name
 *              ever reaches make, a shell or anything else that interprets text.
 *   compile    each .c alone, with one fixed argument vector (the course's flags, from the recipes
 *              the course's own make wrote: grader.mk), as the sandbox's user, under limits, in a
 *              scratch folder that holds the part's files and the framework's and parts' headers
 *              and nothing else: no other part's sources or objects, no build folder. In a mount
 *              namespace it sees the machine read-only but for its output folder, with its own
 *              /tmp (grade_run.c); everywhere, nothing secret is readable by its user.
 *   take out   only <name>.o and <name>.d for each submitted <name>.c come out, regular files under
 *              the size limit, copied by the grader into a tree the sandbox's user cannot write.
 *   inspect    the objects against the allow-list (grade_inspect.c) before anything reads them as
 *              a program: machine code only, the symbols a part may use, no constructor, no syscall.
 *   link       as the grader, bounded, from the course's prebuilt objects of everything else (the
 *              framework's always: a submission cannot change a framework object) and those objects.
 *
 * The tree (env->sandbox_dir/part<n>) then holds what the part's suite and renders run from, the
 * other parts' objects closed to the sandbox's user. */
#include "grade_build.h"
#include "grade_diag.h"
#include "grade_inspect.h"
#include "grade_tree.h"
#include "../framework/file.h"
#include "../framework/utf8.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define RECIPE_WORDS 1024     /* words of one recipe line: a link names ~150 objects */

/* ---- the manifest -------------------------------------------------------------------------- */

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

/* What a refused entry is, in words: its name is never quoted (a name is the student's choice, and
 * results.json is Markdown that a course platform renders: a name holding markup would come back
 * as markup), so the entry is described by kind. */
static const char *entry_kind(const struct stat *st)
{
    return S_ISDIR(st->st_mode) ? "a folder" : S_ISLNK(st->st_mode) ? "a symbolic link" : "a special file";
}

/* One entry of the part's folder: taken into m, passed over (*ignored: never read, never named to a
 * tool), or refused with why. Anything that ends like code and is not a plain file with a plain
 * name is refused, so a student never loses a file silently; everything else (direct.c.orig,
 * notes.txt, a folder, a hidden file) is no code and is passed over. */
static bool manifest_entry(const char *dir, const char *folder, const char *name, grade_manifest *m, bool *ignored,
                           char *why, size_t size)
{
    char path[4400];
    struct stat st;
    bool code = looks_like_code(name) && name[0] != '.';
    *ignored = false;
    if (!grade_path(path, sizeof path, "%s/%s", dir, name) || lstat(path, &st) != 0)
        return grade_msg(why, size, "parts/%s holds an entry that cannot be read", folder), false;
    if (!code) return *ignored = true;
    if (!S_ISREG(st.st_mode))
        return grade_msg(why, size, "parts/%s holds %s named like C code (.c or .h): submit the file itself",
                         folder, entry_kind(&st)), false;
    if (!source_name(name))
        return grade_msg(why, size, "parts/%s holds a .c or .h file whose name has characters other than a-z, 0-9 and "
                                    "_ (or more than %d of them): only files named so are built; rename it", folder,
                         GRADE_SOURCE_NAME - 2), false;
    if (st.st_size > GRADE_SOURCE_BYTES)
        return grade_msg(why, size, "parts/%s/%s is over %ld KiB: a part's file is far smaller", folder, name,
                         GRADE_SOURCE_BYTES >> 10), false;
    if (m->count == GRADE_SOURCE_FILES)
        return grade_msg(why, size, "parts/%s holds over %d .c and .h files", folder, GRADE_SOURCE_FILES), false;
    grade_path(m->names[m->count++], sizeof m->names[0], "%s", name);  /* fits: source_name bounds it */
    return true;
}

bool grade_manifest_read(const char *dir, const char *folder, grade_manifest *m, char *why, size_t size)
{
    m->count = 0;
    DIR *d = opendir(dir);
    if (!d) return grade_msg(why, size, "the submission has no parts/%s folder", folder), false;
    bool ok = true;
    int passed_over = 0;
    for (struct dirent *e; ok && (e = readdir(d));) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        bool ignored;
        ok = manifest_entry(dir, folder, e->d_name, m, &ignored, why, size);
        passed_over += ignored;
    }
    if (passed_over) fprintf(stderr, "grade: parts/%s: %d entries that are not C code passed over\n", folder, passed_over);
    closedir(d);
    /* Text, read as data: UTF-8 and no NUL byte (a compiler would read on past a NUL). */
    for (int i = 0; ok && i < m->count; i++) {
        char path[4400], *data = NULL;
        size_t len = 0;
        pl_diag diag = pl_diag_default();
        grade_path(path, sizeof path, "%s/%s", dir, m->names[i]);
        if (file_read_all(path, "submitted file", GRADE_SOURCE_BYTES, &data, &len, &diag) != PL_OK)
            ok = (grade_msg(why, size, "parts/%s/%s cannot be read as a file", folder, m->names[i]), false);
        else if (memchr(data, '\0', len) || utf8_valid_prefix(data, len) != len)
            ok = (grade_msg(why, size, "parts/%s/%s is not UTF-8 text (a NUL byte or an invalid byte sequence)", folder,
                            m->names[i]), false);
        free(data);
    }
    if (ok && m->count == 0) ok = (grade_msg(why, size, "parts/%s holds no .c file", folder), false);
    return ok;
}

/* ---- the recipes --------------------------------------------------------------------------- */

typedef struct {
    char *text;                /* the file, its words cut apart in place */
    char *words[RECIPE_WORDS];
    int num_words;
} recipe;

/* The line of the recipes file (course tree's GRADE_RECIPES) that starts with `key` and a space,
 * split into words (a recipe holds no quoted words: the course's paths have no spaces). */
static bool recipe_read(const char *course, const char *key, recipe *out)
{
    char path[4200];
    size_t len = 0, k = strlen(key);
    pl_diag diag = pl_diag_default();
    out->num_words = 0;
    out->text = NULL;
    grade_path(path, sizeof path, "%s/" GRADE_RECIPES, course);
    if (file_read_all(path, "recipes", GRADE_TOOL_LOG_MAX, &out->text, &len, &diag) != PL_OK) return false;
    for (char *save = NULL, *line = strtok_r(out->text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        if (strncmp(line, key, k) || line[k] != ' ') continue;
        for (char *s2 = NULL, *w = strtok_r(line + k + 1, " ", &s2); w && out->num_words < RECIPE_WORDS - 1;
             w = strtok_r(NULL, " ", &s2))
            out->words[out->num_words++] = w;
        out->words[out->num_words] = NULL;
        return true;
    }
    return false;
}

/* ---- files between the trees --------------------------------------------------------------- */

/* Copies from/name to to/name through the grader (a regular file, at most max bytes), 0644. */
static bool copy_file(const char *from, const char *to, const char *name, long max)
{
    char src[4400], dst[4400], *data = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    bool ok = grade_path(src, sizeof src, "%s/%s", from, name) && grade_path(dst, sizeof dst, "%s/%s", to, name) &&
              file_read_all(src, name, (size_t)max, &data, &len, &diag) == PL_OK &&
              file_write_atomic(dst, data, len, &diag) == PL_OK && chmod(dst, 0644) == 0;
    free(data);
    return ok;
}

/* Every header of from (a course folder) into to. */
static bool copy_headers(const char *from, const char *to)
{
    DIR *d = opendir(from);
    bool ok = d && (mkdir(to, 0755) == 0 || errno == EEXIST);
    for (struct dirent *e; ok && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n > 2 && !strcmp(e->d_name + n - 2, ".h")) ok = copy_file(from, to, e->d_name, GRADE_SOURCE_BYTES);
    }
    if (d) closedir(d);
    return ok;
}

/* The compile's source folder: the framework's headers, every part's headers, and the submitted
 * files of part <folder>, the course's headers over any of the same name (the contract is the
 * course's). Root's, readable by the sandbox's user. */
static bool lay_out_sources(const char *course, const char *submitted, const char *folder, const grade_manifest *m,
                            const char *src)
{
    char from[4200], to[4200], parts[4200];
    grade_path(from, sizeof from, "%s/framework", course);
    grade_path(to, sizeof to, "%s/framework", src);
    grade_path(parts, sizeof parts, "%s/parts", src);
    if (mkdir(src, 0755) != 0 || !copy_headers(from, to) || mkdir(parts, 0755) != 0) return false;
    grade_path(to, sizeof to, "%s/parts/%s", src, folder);
    if (mkdir(to, 0755) != 0) return false;
    for (int i = 0; i < m->count; i++)
        if (!copy_file(submitted, to, m->names[i], GRADE_SOURCE_BYTES)) return false;
    for (int k = 1; k <= GRADE_MAX_PART; k++) {
        char other[256];
        if (!grade_part_folder(course, k, other, sizeof other)) continue;  /* not in this course */
        grade_path(from, sizeof from, "%s/parts/%s", course, other);
        grade_path(to, sizeof to, "%s/parts/%s", src, other);
        if (!copy_headers(from, to)) return false;
    }
    return true;
}

/* ---- compile ------------------------------------------------------------------------------- */

/* Whether the compiler's log says it ran out of memory (cc1 reports it; the kernel's kill is a signal). */
static bool out_of_memory(const char *log)
{
    char tail[4096];
    grade_log_tail(log, 20, tail, sizeof tail);
    return strstr(tail, "out of memory") || strstr(tail, "memory exhausted") || strstr(tail, "Killed signal");
}

/* The build's verdict when a step failed, in the grader's words: what limit it ran past, or that
 * it does not compile (the compiler's own lines for the part's files are shown beside it). */
static void build_verdict(const grade_run_result *rr, int n, const char *step, const char *name, double limit,
                          const char *log, grade_part_result *r)
{
    if (rr->out_of_time) grade_msg(r->suite_reason, sizeof r->suite_reason, "part %d's build did not finish: %s (the %s "
                                   "of %s)", n, GRADE_OUT_OF_TIME, step, name);
    else if (rr->timed_out) grade_msg(r->suite_reason, sizeof r->suite_reason, "part %d's build ran past %.0f s: the %s of %s",
                                      n, limit, step, name);
    else if (rr->output_cut)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "part %d's build printed more than %d KiB: the %s of %s", n,
                  GRADE_LOG_MAX / 1024, step, name);
    else if (out_of_memory(log) || !rr->exited)
        grade_msg(r->suite_reason, sizeof r->suite_reason, "part %d's build ran past its memory limit (%ld MiB) or its "
                  "CPU time: the %s of %s", n, GRADE_COMPILER_MEMORY >> 20, step, name);
    else grade_msg(r->suite_reason, sizeof r->suite_reason, "part %d does not %s: %s", n, step, name);
}

/* Appends the file at from to the one at to (the build log the diagnostics are read from). */
static void append_log(const char *from, const char *to)
{
    char *data = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    FILE *f = file_read_all(from, "log", GRADE_LOG_MAX + 64, &data, &len, &diag) == PL_OK ? fopen(to, "ab") : NULL;
    if (f) fwrite(data, 1, len, f), fclose(f);
    free(data);
}

/* One compile: its argument vector (the recipes' words and its own paths) and its log. */
typedef struct {
    char obj[4400], dep[4400], source[4400], log[4400], name[GRADE_SOURCE_NAME + 1];
    char *argv[RECIPE_WORDS + 16];
} compile_job;

/* Each submitted .c compiled alone into scratch/out, confined, two at a time; false with the
 * verdict in r (the first file that failed, in the manifest's order). */
static bool compile_all(const grade_env *env, int n, const char *folder, const grade_manifest *m, const char *scratch,
                        grade_part_result *r)
{
    char course[4200], src[4200], out[4200], tmpdir[4300];
    grade_path(course, sizeof course, "%s/course", env->work);
    grade_path(src, sizeof src, "%s/src", scratch);
    grade_path(out, sizeof out, "%s/out", scratch);
    grade_path(tmpdir, sizeof tmpdir, "TMPDIR=%s", out);
    recipe cc = {0}, flags = {0};
    compile_job *jobs = calloc(GRADE_SOURCE_FILES, sizeof *jobs);
    char *const *argvs[GRADE_SOURCE_FILES] = {0};
    grade_run_opts opts[GRADE_SOURCE_FILES] = {{0}};
    grade_run_result results[GRADE_SOURCE_FILES];
    char *envv[] = {tmpdir, NULL};
    bool ok = jobs && recipe_read(course, "cc", &cc) && cc.num_words == 1 && recipe_read(course, "compile", &flags);
    if (!ok) grade_msg(r->suite_reason, sizeof r->suite_reason, "the course's build recipes are missing (%s): the "
                       "course's problem, please tell the staff", GRADE_RECIPES);
    int count = 0;
    for (int i = 0; ok && i < m->count; i++) {
        size_t len = strlen(m->names[i]);
        if (m->names[i][len - 1] != 'c') continue;
        compile_job *j = &jobs[count];
        snprintf(j->name, sizeof j->name, "%s", m->names[i]);
        grade_path(j->obj, sizeof j->obj, "%s/%.*s.o", out, (int)len - 2, m->names[i]);
        grade_path(j->dep, sizeof j->dep, "%s/%.*s.d", out, (int)len - 2, m->names[i]);
        grade_path(j->source, sizeof j->source, "parts/%s/%s", folder, m->names[i]);
        grade_path(j->log, sizeof j->log, "%s/part%d/compile-%s.log", env->work, n, m->names[i]);
        int argc = 0;
        j->argv[argc++] = cc.words[0];
        for (int w = 0; w < flags.num_words; w++) j->argv[argc++] = flags.words[w];
        char *tail[] = {"-MMD", "-MF", j->dep, "-c", "-o", j->obj, j->source, NULL};
        for (int w = 0; tail[w]; w++) j->argv[argc++] = tail[w];
        j->argv[argc] = NULL;
        argvs[count] = j->argv;
        opts[count] = (grade_run_opts){.wall_seconds = GRADE_COMPILE_SECONDS, .deadline = env->deadline, .cwd = src, .log_path = j->log,
                                       .log_max = GRADE_LOG_MAX, .env = envv, .untrusted = env->submission != NULL,
                                       .compiler = true, .writable = out};
        count++;
    }
    if (ok) grade_run_jobs(count, argvs, opts, results, true);
    for (int k = 0; ok && k < count; k++) {
        append_log(jobs[k].log, r->build_log);
        if (!results[k].exited || results[k].status != 0) {
            build_verdict(&results[k], n, "compile", jobs[k].name, GRADE_COMPILE_SECONDS, jobs[k].log, r);
            ok = false;
        }
    }
    free(cc.text);
    free(flags.text);
    free(jobs);
    return ok;
}

/* Takes <name>.o and <name>.d of each submitted .c out of the compile's folder into the tree's
 * object folder: regular files only (the compile's user may have left links), under the file limit. */
static bool take_objects(const grade_manifest *m, const char *out, const char *objects, grade_part_result *r)
{
    for (int i = 0; i < m->count; i++) {
        size_t len = strlen(m->names[i]);
        if (m->names[i][len - 1] != 'c') continue;
        for (int k = 0; k < 2; k++) {
            char name[GRADE_SOURCE_NAME + 4], path[4400];
            struct stat st;
            snprintf(name, sizeof name, "%.*s.%s", (int)len - 2, m->names[i], k ? "d" : "o");
            grade_path(path, sizeof path, "%s/%s", out, name);
            if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode) || !copy_file(out, objects, name, GRADE_FILE_BYTES))
                return grade_msg(r->suite_reason, sizeof r->suite_reason, "the compiler made no usable %s from %s", name,
                                 m->names[i]), false;
        }
    }
    return true;
}

/* ---- the tree, and the link ---------------------------------------------------------------- */

static bool run_trusted(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = GRADE_LINK_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(argv, &o);
    return rr.exited && rr.status == 0;
}

/* Part n's tree from the course's built tree: what its suite and renders read at run time
 * (framework, tests, scenes, ...) and the course's objects, less part n's; every part's headers
 * (the course's); the other parts' object folders closed to everyone but the grader. */
static bool lay_out_tree(const char *course, const char *folder, const char *tree, const char *log)
{
    static const char *const copied[] = {"Makefile", "framework", "tests", "tools", "third_party", "scenes", "VERSION",
                                         "build"};
    char bin[4200];
    grade_path(bin, sizeof bin, "%s/bin", tree);
    char *mk[] = {"mkdir", "-p", bin, NULL};
    if (!run_trusted(mk, NULL)) return false;
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        char from[4200];
        struct stat st;
        grade_path(from, sizeof from, "%s/%s", course, copied[k]);
        char *cp[] = {"cp", "-a", from, (char *)tree, NULL};
        if (stat(from, &st) == 0 && !run_trusted(cp, log)) return false;
    }
    for (int k = 1; k <= GRADE_MAX_PART; k++) {
        char other[256], from[4200], to[4200], objects[4200];
        if (!grade_part_folder(course, k, other, sizeof other)) continue;  /* not in this course */
        grade_path(from, sizeof from, "%s/parts/%s", course, other);
        grade_path(to, sizeof to, "%s/parts/%s", tree, other);
        grade_path(objects, sizeof objects, "%s/" GRADE_OBJECTS "/parts/%s", tree, other);
        char *mkp[] = {"mkdir", "-p", to, NULL}, *rm[] = {"rm", "-rf", objects, NULL};
        if (!run_trusted(mkp, NULL) || !copy_headers(from, to)) return false;
        if (!strcmp(other, folder)) {
            /* Part n's objects are the submission's, and only they: the course's go. */
            char *mko[] = {"mkdir", "-p", objects, NULL};
            if (!run_trusted(rm, NULL) || !run_trusted(mko, NULL)) return false;
        }
        else if (chmod(objects, 0700) != 0 && errno != ENOENT) return false;
    }
    return true;
}

/* One link: program `bin`'s recipe with part <folder>'s course objects replaced by the
 * submission's, run in the tree as the grader, bounded: it reads objects a confined compiler wrote. */
typedef struct {
    recipe cc, line;
    char objs[GRADE_SOURCE_FILES][GRADE_SOURCE_NAME + 128], log[4400];
    char *argv[RECIPE_WORDS + GRADE_SOURCE_FILES + 2];
} link_job;

static bool link_job_make(const char *course, const char *folder, const grade_manifest *m, const char *bin,
                          link_job *j)
{
    char key[128], own[300];
    snprintf(key, sizeof key, "link %s", bin);
    bool ok = recipe_read(course, "cc", &j->cc) && recipe_read(course, key, &j->line);
    int argc = 0;
    bool placed = false;
    grade_path(own, sizeof own, GRADE_OBJECTS "/parts/%s/", folder);
    if (ok) j->argv[argc++] = j->cc.words[0];
    for (int w = 0; ok && w < j->line.num_words; w++) {
        if (strncmp(j->line.words[w], own, strlen(own))) {
            j->argv[argc++] = j->line.words[w];
            continue;
        }
        for (int i = 0; !placed && i < m->count; i++) {
            size_t len = strlen(m->names[i]);
            if (m->names[i][len - 1] != 'c') continue;
            grade_path(j->objs[i], sizeof j->objs[i], "%s%.*s.o", own, (int)len - 2, m->names[i]);
            j->argv[argc++] = j->objs[i];
        }
        placed = true;
    }
    j->argv[argc] = NULL;
    return ok && placed;
}

/* The renderer and the split suite's subject (grade_judge.c), linked side by side in the tree; false
 * with the verdict in r. A submission's suite never runs whole, so its test-part<n> is not linked. */
static bool link_all(const grade_env *env, int n, const char *folder, const grade_manifest *m, const char *tree,
                     grade_part_result *r)
{
    static const char *const programs[] = {"bin/pathtracer", "bin/subject-part%d"};
    char course[4200];
    grade_path(course, sizeof course, "%s/course", env->work);
    link_job *links = calloc(2, sizeof *links);
    char *const *argvs[2] = {0};
    grade_run_opts opts[2] = {{0}};
    grade_run_result results[2];
    bool ok = links != NULL;
    if (!ok) grade_msg(r->suite_reason, sizeof r->suite_reason, "the grader ran out of memory linking part %d", n);
    for (int k = 0; ok && k < 2; k++) {
        char bin[64];
        snprintf(bin, sizeof bin, programs[k], n);
        grade_path(links[k].log, sizeof links[k].log, "%s/part%d/link-%d.log", env->work, n, k);
        if (!link_job_make(course, folder, m, bin, &links[k]))
            ok = (grade_msg(r->suite_reason, sizeof r->suite_reason, "the course's build recipes have no link of %s: the "
                            "course's problem, please tell the staff", bin), false);
        argvs[k] = links[k].argv;
        opts[k] = (grade_run_opts){.wall_seconds = GRADE_LINK_SECONDS, .deadline = env->deadline, .cwd = tree, .log_path = links[k].log,
                                   .log_max = GRADE_LOG_MAX, .bounded = true};
    }
    if (ok) grade_run_jobs(2, argvs, opts, results, false);
    for (int k = 0; ok && k < 2; k++) {
        append_log(links[k].log, r->build_log);
        if (!results[k].exited || results[k].status != 0) {
            build_verdict(&results[k], n, "link", k ? "the suite" : "the renderer", GRADE_LINK_SECONDS, links[k].log, r);
            ok = false;
        }
    }
    for (int k = 0; links && k < 2; k++) free(links[k].cc.text), free(links[k].line.text);
    free(links);
    return ok;
}

bool grade_build_submission(const grade_env *env, int n, const char *tree, grade_part_result *r)
{
    char course[4200], folder[256], submitted[4400], scratch[4200], src[4300], out[4300], objects[4400], log[4200];
    grade_path(course, sizeof course, "%s/course", env->work);
    grade_path(r->build_log, sizeof r->build_log, "%s/part%d/build.log", env->work, n);
    if (!grade_part_folder(course, n, folder, sizeof folder))
        return grade_msg(r->suite_reason, sizeof r->suite_reason, "no folder for part %d under parts/", n), false;
    grade_path(submitted, sizeof submitted, "%s/parts/%s", env->submission, folder);
    grade_manifest m;
    if (!grade_manifest_read(submitted, folder, &m, r->suite_reason, sizeof r->suite_reason)) return false;

    /* The compile: a scratch folder of headers and the submitted files, an output folder of the
     * sandbox user's own; nothing else of the grading is there. */
    grade_path(scratch, sizeof scratch, "%s/part%d-build", env->sandbox_dir, n);
    grade_path(src, sizeof src, "%s/src", scratch);
    grade_path(out, sizeof out, "%s/out", scratch);
    grade_tree_remove(scratch);
    bool ok = mkdir(scratch, 0755) == 0 && lay_out_sources(course, submitted, folder, &m, src) && mkdir(out, 0700) == 0 &&
              (!env->sandbox.as_other_user || chown(out, env->sandbox.uid, env->sandbox.gid) == 0);
    if (!ok) grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot lay out part %d's build under %s", n, scratch);
    unlink(r->build_log);
    ok = ok && compile_all(env, n, folder, &m, scratch, r);

    /* The tree: the course's pieces, then the objects the compile made, then the link. */
    grade_path(log, sizeof log, "%s/part%d/tree.log", env->work, n);
    grade_path(objects, sizeof objects, "%s/" GRADE_OBJECTS "/parts/%s", tree, folder);
    grade_tree_remove(tree);
    if (ok && !lay_out_tree(course, folder, tree, log))
        ok = (grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot lay out part %d's tree under %s", n, tree), false);
    ok = ok && take_objects(&m, out, objects, r);
    grade_tree_remove(scratch);  /* nothing the compile wrote stays */
    char to[4400];
    grade_path(to, sizeof to, "%s/parts/%s", tree, folder);
    for (int i = 0; ok && i < m.count; i++)  /* the sources the inspection names (grade_inspect.c) */
        if (m.names[i][strlen(m.names[i]) - 1] == 'c') ok = copy_file(submitted, to, m.names[i], GRADE_SOURCE_BYTES);
    /* The objects against the allow-list, before the linker reads them as the grader. */
    char work[4300], why[sizeof r->suite_reason];
    grade_path(work, sizeof work, "%s/part%d", env->work, n);
    if (ok && !grade_inspect_part(tree, course, folder, n, work, env->deadline, why, sizeof why))
        ok = (grade_msg(r->suite_reason, sizeof r->suite_reason, "%s", why), false);
    ok = ok && link_all(env, n, folder, &m, tree, r);
    if (!ok) grade_diagnostics(r->build_log, folder, GRADE_DIAG_LINES, r->build_output, sizeof r->build_output);
    return ok;
}
