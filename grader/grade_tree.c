/* Grader machinery: not part of any assignment.
 * The course's side of the grading trees (grade_tree.h): once per grading, before any student code
 * runs, the grader copies the course's tree into its private work folder (work/course, root's alone)
 * and builds there, with the course's make, every object with the graded build's flags, the
 * programs the parts' grading needs and the recipes that build a submission without make
 * (grade_build.c, which lays out each part's tree from these pieces). */
#include "grade_tree.h"
#include "../framework/file.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static bool run_quiet(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = GRADE_LINK_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
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
    static const char *const copied[] = {"Makefile", "framework", "grader", "parts", "tests", "tools", "third_party", "scenes",
                                         "VERSION"};
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        char from[4200];
        struct stat st;
        grade_path(from, sizeof from, "%s/%s", env->root, copied[k]);
        char *cp[] = {"cp", "-a", from, course, NULL};
        if (stat(from, &st) == 0 && !run_quiet(cp, log)) return grade_msg(why, size, "cannot copy %s", from), false;
    }
    /* Objects and programs `bin/grade --prebuild` made when the image was set up (setup.sh): copied
     * with their times, make finds them newer than the sources and does nothing (a source edited
     * since is rebuilt, and what depends on it relinked). */
    char self[4200];
    grade_path(self, sizeof self, "%s/" GRADE_PREBUILD, env->root);
    for (int k = 0; k < 2 && strcmp(self, env->work); k++) {
        char prebuilt[4300];
        struct stat st;
        grade_path(prebuilt, sizeof prebuilt, "%s/course/%s", self, k ? "bin" : "build");
        char *seed[] = {"cp", "-a", prebuilt, course, NULL};
        if (stat(prebuilt, &st) == 0 && S_ISDIR(st.st_mode) && !run_quiet(seed, log))
            return grade_msg(why, size, "cannot copy %s", prebuilt), false;
    }
    /* The renderer, the recipes, and the split suites of the parts to grade only: each part's
     * subject (whose objects a submission's link reuses) and judge. */
    char programs[2 * GRADE_MAX_PART][32];
    char *make[16 + 2 * GRADE_MAX_PART] = {"make", "-C", course, GRADE_MAKE_ARGS, "bin/pathtracer",
                                            GRADE_OBJECTS "/grade-recipes.txt"};
    int argc = 10;  /* after make -C course, the 5 arguments, bin/pathtracer and the recipes */
    static const char *const per_part[] = {"bin/subject-part%d", "bin/judge-part%d"};
    for (int k = 1; k <= GRADE_MAX_PART; k++)
        for (int j = 0; j < 2 && strchr(parts, '0' + k); j++) {
            snprintf(programs[2 * (k - 1) + j], sizeof programs[0], per_part[j], k);
            make[argc++] = programs[2 * (k - 1) + j];
        }
    make[argc] = NULL;
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(make, &o);
    if (!rr.exited || rr.status != 0)
        return grade_msg(why, size, "the course's own tree does not build with the grader's flags (see %s)", log), false;
    return true;
}

void grade_tree_remove(const char *tree)
{
    /* Only what lies in a sandbox folder this grader made: a path gone wrong (a tree never set, the
     * course's own root) is left alone, never removed. */
    if (!strstr(tree, "/" GRADE_SANDBOX_NAME) || strstr(tree, "/..")) {
        fprintf(stderr, "grade: not removing %s: not in a sandbox folder\n", tree);
        return;
    }
    char *rm[] = {"rm", "-rf", (char *)tree, NULL};  /* rm never follows a link it deletes */
    run_quiet(rm, NULL);
}
