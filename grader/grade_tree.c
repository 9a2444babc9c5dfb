/* Grader machinery: not part of any assignment.
 * The grading trees (grade_tree.h). Nothing secret may be in reach of student code, so a part's tree
 * is assembled from pieces, never copied whole from the course:
 * - once per grading, before any student code runs, the grader builds the course's own tree in its
 *   private work folder (work/course, root's alone): every object with the graded build's flags;
 * - part N's tree, in the sandbox folder (the only place the sandbox's user can reach), holds the
 *   framework, the tests, the scenes (public ones), every part's headers, the submission's part N,
 *   and the other parts only as those prebuilt objects (no source, no dependency file); part N's
 *   own course objects and the course's programs (bin/) are left out;
 * - the tree is removed as soon as its part is graded, so part N+1 finds nothing of part N. */
#include "grade_tree.h"
#include "../framework/file.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SUBMITTED_FILE_MAX (4L << 20)

static bool run_quiet(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = GRADE_BUILD_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* The folder name of part n in root, e.g. "part2_bvh". */
bool grade_part_folder(const char *root, int n, char *out, size_t size)
{
    char parts[4096], prefix[16];
    grade_path(parts, sizeof parts, "%s/parts", root);
    snprintf(prefix, sizeof prefix, "part%d_", n);
    DIR *d = opendir(parts);
    if (!d) return false;
    bool found = false;
    for (struct dirent *e; !found && (e = readdir(d));)
        if (!strncmp(e->d_name, prefix, strlen(prefix))) found = snprintf(out, size, "%s", e->d_name) < (int)size;
    closedir(d);
    return found;
}


bool grade_tree_course_build(const grade_env *env, const char *parts, char *why, size_t size)
{
    char course[4200], log[4200];
    grade_path(course, sizeof course, "%s/course", env->work);
    grade_path(log, sizeof log, "%s/course-build.log", env->work);
    char *rm[] = {"rm", "-rf", course, NULL}, *mk[] = {"mkdir", "-p", course, NULL};
    if (!run_quiet(rm, NULL) || !run_quiet(mk, NULL))
        return grade_msg(why, size, "cannot create %s", course), false;
    static const char *const copied[] = {"Makefile", "framework", "parts", "tests", "tools", "third_party", "scenes",
                                         "VERSION"};
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        char from[4200];
        struct stat st;
        grade_path(from, sizeof from, "%s/%s", env->root, copied[k]);
        char *cp[] = {"cp", "-a", from, course, NULL};
        if (stat(from, &st) == 0 && !run_quiet(cp, log)) return grade_msg(why, size, "cannot copy %s", from), false;
    }
    /* Objects `bin/grade --prebuild` made when the image was set up (setup.sh): copied with their
     * times, make finds them newer than the sources and only links (a source edited since is rebuilt). */
    char prebuilt[4200], self[4200];
    struct stat st;
    grade_path(prebuilt, sizeof prebuilt, "%s/" GRADE_PREBUILD "/course/build", env->root);
    grade_path(self, sizeof self, "%s/" GRADE_PREBUILD, env->root);
    char *seed[] = {"cp", "-a", prebuilt, course, NULL};
    if (strcmp(self, env->work) && stat(prebuilt, &st) == 0 && S_ISDIR(st.st_mode) && !run_quiet(seed, log))
        return grade_msg(why, size, "cannot copy %s", prebuilt), false;
    /* The renderer, and the suites of the parts to grade only (the other suites' objects are unused). */
    char suites[GRADE_NUM_PARTS][32];
    char *make[12 + GRADE_NUM_PARTS] = {"make", "-C", course, GRADE_MAKE_ARGS, "bin/pathtracer"};
    int argc = 10;  /* after make -C course, the 6 arguments and bin/pathtracer */
    for (int k = 1; k <= GRADE_NUM_PARTS; k++)
        if (strchr(parts, '0' + k)) snprintf(suites[k - 1], sizeof suites[k - 1], "bin/test-part%d", k), make[argc++] = suites[k - 1];
    make[argc] = NULL;
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(make, &o);
    if (!rr.exited || rr.status != 0)
        return grade_msg(why, size, "the course's own tree does not build with the grader's flags (see %s)", log), false;
    return true;
}

/* The submission's part folder into `to`: its regular files only, each read through the framework's
 * file reader (regular files, a size cap) and written by this process. A symbolic link is refused,
 * never copied: `direct.c -> /autograder/source/parts/part3_direct/direct.c` would otherwise build
 * the course's solution as the student's. Subfolders are left out (the build reads none). */
#define SUBMITTED_FILE_MAX (4L << 20)

static bool copy_submitted_part(const char *from, const char *to, const char *folder, grade_part_result *r)
{
    DIR *d = opendir(from);
    if (!d) {
        grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot read the submission's parts/%s", folder);
        return false;
    }
    bool ok = mkdir(to, 0755) == 0;
    if (!ok) grade_msg(r->suite_reason, sizeof r->suite_reason, "cannot create %s", to);
    for (struct dirent *e; ok && (e = readdir(d));) {
        if (e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2]))) continue;
        char src[4400], dst[4400];
        struct stat st;
        if (!grade_path(src, sizeof src, "%s/%s", from, e->d_name) || !grade_path(dst, sizeof dst, "%s/%s", to, e->d_name)) {
            grade_msg(r->suite_reason, sizeof r->suite_reason, "parts/%s/%.100s...: the path is too long", folder, e->d_name);
            ok = false;
            break;
        }
        if (lstat(src, &st) != 0 || S_ISDIR(st.st_mode)) continue;
        if (!S_ISREG(st.st_mode)) {
            grade_msg(r->suite_reason, sizeof r->suite_reason,
                     "parts/%s/%.100s is %s, not a file: submit the file itself", folder, e->d_name,
                     S_ISLNK(st.st_mode) ? "a symbolic link" : "a special file");
            ok = false;
            break;
        }
        char *data = NULL;
        size_t len = 0;
        pl_diag diag = pl_diag_default();
        ok = file_read_all(src, "submitted file", SUBMITTED_FILE_MAX, &data, &len, &diag) == PL_OK &&
             file_write_atomic(dst, data, len, &diag) == PL_OK;
        if (!ok) grade_msg(r->suite_reason, sizeof r->suite_reason, "%.250s", diag.error);
        free(data);
    }
    closedir(d);
    return ok;
}

/* Every .c file of parts/<folder> under base, as "parts/<folder>/<name>.c " entries appended to
 * list (the build's PARTS_SRC: the Makefile would otherwise find only the sources present). */
static bool list_sources(const char *base, const char *folder, char *list, size_t size)
{
    char dir[4200];
    grade_path(dir, sizeof dir, "%s/parts/%s", base, folder);
    DIR *d = opendir(dir);
    bool ok = d != NULL;
    for (struct dirent *e; ok && (e = readdir(d));) {
        size_t n = strlen(e->d_name), len = strlen(list);
        if (n > 2 && !strcmp(e->d_name + n - 2, ".c"))
            ok = (size_t)snprintf(list + len, size - len, "parts/%s/%s ", folder, e->d_name) < size - len;
    }
    if (d) closedir(d);
    return ok;
}

bool grade_tree_sources(const grade_env *env, const char *tree, int n, char *list, size_t size)
{
    char course[4200];
    grade_path(course, sizeof course, "%s/course", env->work);
    snprintf(list, size, "PARTS_SRC=");
    for (int k = 1; k <= GRADE_NUM_PARTS; k++) {
        char folder[256];
        if (!grade_part_folder(course, k, folder, sizeof folder) ||
            !list_sources(k == n ? tree : course, folder, list, size))
            return false;
    }
    return true;
}

/* The course's pieces of part n's tree: its build folder less part n's objects and every dependency
 * file of a part (each names a source the tree does not hold), and every part's headers, the course's
 * over any the submission brought (framework files include them: a header could otherwise put code
 * into a framework object, which the allow-list does not inspect). Runs after the submitted part is
 * in place. */
static bool add_course_pieces(const grade_env *env, const char *tree, const char *folder, const char *log)
{
    static const char script[] =
        "course=$1 tree=$2 own=$3\n"
        "for d in \"$course\"/parts/*/; do\n"
        "  f=$(basename \"$d\"); mkdir -p \"$tree/parts/$f\" || exit 1\n"
        "  for h in \"$d\"*.h; do [ ! -e \"$h\" ] || cp -p \"$h\" \"$tree/parts/$f/\" || exit 1; done\n"
        "done\n"
        "rm -rf \"$tree/build/release/parts/$own\" && rm -f \"$tree\"/build/release/parts/*/*.d\n";
    char course[4200];
    grade_path(course, sizeof course, "%s/course", env->work);
    char *argv[] = {"sh", "-c", (char *)script, "sh", course, (char *)tree, (char *)folder, NULL};
    return run_quiet(argv, log);
}

bool grade_tree_make(const grade_env *env, int n, char *tree, size_t size, grade_part_result *r)
{
    char folder[256], from[4200], to[4300], log[4200], course[4200];
    grade_path(tree, size, "%s/part%d", env->sandbox_dir, n);
    grade_path(log, sizeof log, "%s/part%d/tree.log", env->work, n);
    grade_path(course, sizeof course, "%s/course", env->work);
    if (!grade_part_folder(course, n, folder, sizeof folder))
        return grade_msg(r->suite_reason, sizeof r->suite_reason, "no folder for part %d under parts/", n), false;
    grade_tree_remove(tree);
    char *mk[] = {"mkdir", "-p", tree, NULL};
    if (!run_quiet(mk, NULL)) return false;
    static const char *const copied[] = {"Makefile", "framework", "tests", "tools", "third_party", "scenes", "VERSION",
                                         "build"};
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        struct stat st;
        grade_path(from, sizeof from, "%s/%s", course, copied[k]);
        char *cp[] = {"cp", "-a", from, tree, NULL};
        if (stat(from, &st) == 0 && !run_quiet(cp, log)) return false;
    }
    grade_path(from, sizeof from, "%s/parts/%s", env->submission, folder);
    grade_path(to, sizeof to, "%s/parts", tree);
    struct stat st;
    if (stat(from, &st) != 0 || !S_ISDIR(st.st_mode))
        return grade_msg(r->suite_reason, sizeof r->suite_reason, "the submission has no parts/%s folder", folder), false;
    if (mkdir(to, 0755) != 0) return false;
    grade_path(to, sizeof to, "%s/parts/%s", tree, folder);
    if (!copy_submitted_part(from, to, folder, r) || !add_course_pieces(env, tree, folder, log)) return false;
    /* Student code runs as `nobody` when the grader is root: give it the tree, only. */
    if (env->sandbox.as_other_user) {
        char owner[64];
        snprintf(owner, sizeof owner, "%u:%u", env->sandbox.uid, env->sandbox.gid);
        char *chown[] = {"chown", "-R", owner, tree, NULL};
        if (!run_quiet(chown, log)) return false;
    }
    return true;
}

bool grade_tree_seal(const grade_env *env, const char *tree)
{
    if (!env->sandbox.as_other_user) return true;
    char bin[4200], objs[4200];
    grade_path(bin, sizeof bin, "%s/bin", tree);
    grade_path(objs, sizeof objs, "%s/build", tree);
    char *chown[] = {"chown", "-R", "0:0", bin, objs, NULL};
    return run_quiet(chown, NULL);
}

void grade_tree_remove(const char *tree)
{
    char *rm[] = {"rm", "-rf", (char *)tree, NULL};  /* rm never follows a link it deletes */
    run_quiet(rm, NULL);
}
