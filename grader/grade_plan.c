/* Grader machinery: not part of any assignment.
 * The plan (grade_plan.h): every path and command of a grading, formatted here and nowhere else.
 * Each path goes through grade_path, which refuses one that does not fit rather than cutting it (a
 * cut path names another file), so a plan that cannot be made is refused whole, before any stage
 * runs, and a stage never meets a half-made path. */
#include "grade_plan.h"
#include "../framework/file.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the run's folders --------------------------------------------------------------------- */

/* mkdir -p: the default out/grade may be the first thing made under out/. */
static bool make_dir(const char *path)
{
    grade_path_buf buf;
    if (!grade_path(buf, sizeof buf, "%s", path)) return false;
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST) return false;
            *p = '/';
        }
    return mkdir(buf, 0755) == 0 || errno == EEXIST;
}

/* A folder given on the command line, absolute, at most GRADE_ROOT_MAX bytes: every path joined onto
 * it then fits a grade_path_buf. */
static bool absolute(const char *given, char *out)
{
    char real[4096];  /* realpath writes at most PATH_MAX bytes: 4096 on Linux, 1024 on macOS */
    return realpath(given, real) && strlen(real) < GRADE_ROOT_MAX && grade_path(out, GRADE_PATH, "%s", real);
}

const char *grade_plan_run(const char *out, const char *submission, grade_run_plan *rp)
{
    memset(rp, 0, sizeof *rp);
    if (!getcwd(rp->root, GRADE_ROOT_MAX)) return "cannot read the current folder (or its path is over 1 KiB)";
    if (!make_dir(out) || !absolute(out, rp->out)) return "--out: cannot create the folder, or its path is over 1 KiB";
    bool ok = grade_path(rp->work, GRADE_PATH, "%s/work", rp->out) && grade_path(rp->report, GRADE_PATH, "%s/report", rp->out) &&
              grade_path(rp->results, GRADE_PATH, "%s/results.json", rp->out) &&
              grade_path(rp->facts, GRADE_PATH, "%s/facts.json", rp->out) &&
              grade_path(rp->course, GRADE_PATH, "%s/course", rp->work) &&
              grade_path(rp->course_log, GRADE_PATH, "%s/course-build.log", rp->work) &&
              grade_path(rp->prebuilt, GRADE_PATH, "%s/" GRADE_PREBUILD, rp->root);
    if (!ok || !make_dir(rp->work) || !make_dir(rp->report)) return "--out: cannot create its work/ and report/ folders";
    if (submission && !absolute(submission, rp->submission)) return "--submission: no such folder, or its path is over 1 KiB";
    return NULL;
}

const char *grade_plan_prebuild(grade_run_plan *rp)
{
    memset(rp, 0, sizeof *rp);
    if (!getcwd(rp->root, GRADE_ROOT_MAX)) return "cannot read the current folder (or its path is over 1 KiB)";
    bool ok = grade_path(rp->work, GRADE_PATH, "%s/" GRADE_PREBUILD, rp->root) &&
              grade_path(rp->prebuilt, GRADE_PATH, "%s", rp->work) &&
              grade_path(rp->course, GRADE_PATH, "%s/course", rp->work) &&
              grade_path(rp->course_log, GRADE_PATH, "%s/course-build.log", rp->work);
    if (!ok || !make_dir(rp->work) || chmod(rp->work, 0700) != 0) return "--prebuild: cannot create " GRADE_PREBUILD;
    return NULL;
}

void grade_plan_sandbox_template(grade_run_plan *rp)
{
    const char *tmp = getenv("TMPDIR") && getenv("TMPDIR")[0] == '/' && strlen(getenv("TMPDIR")) < GRADE_ROOT_MAX
                          ? getenv("TMPDIR") : "/tmp";
    grade_path(rp->sandbox, GRADE_PATH, "%s/" GRADE_SANDBOX_NAME "XXXXXX", tmp);
}

void grade_plan_sandbox_made(grade_run_plan *rp)
{
    grade_path(rp->own_tmp, GRADE_PATH, "%s/tmp", rp->sandbox);
}

void grade_plan_secrets(const grade_run_plan *rp, grade_secrets *out)
{
    /* parts/: the course's solutions, which a submission could otherwise #include or link to; bin/ and
     * build/: the course's programs and objects (the solution as machine code); course/ and release/:
     * the course's own tools, its catalogues of bugs and the bundle's copy of everything; the prebuilt
     * objects; .git/: a checkout's history holds every solution and reference. Then the grading's own
     * outputs: the report (it shows references) and results.json. */
    static const char *const in_root[] = {"reference_images", "grading/hidden", "parts", "bin", "build", "course",
                                          "release", ".git", GRADE_PREBUILD};
    out->count = 0;
    for (size_t k = 0; k < sizeof in_root / sizeof in_root[0]; k++, out->count++)
        grade_path(out->path[out->count], GRADE_PATH, "%s/%s", rp->root, in_root[k]), out->file[out->count] = false;
    grade_path(out->path[out->count], GRADE_PATH, "%s", rp->report), out->file[out->count++] = false;
    grade_path(out->path[out->count], GRADE_PATH, "%s", rp->results), out->file[out->count++] = true;
}

void grade_plan_course_build(const grade_run_plan *rp, const char *parts, grade_course_build *out)
{
    static const char *const copied[GRADE_PLAN_COPIED] = {"Makefile", "framework", "grader", "parts", "tests", "tools",
                                                          "third_party", "scenes", "VERSION"};
    out->count = 0;
    for (int k = 0; k < GRADE_PLAN_COPIED; k++) grade_path(out->from[out->count++], GRADE_PATH, "%s/%s", rp->root, copied[k]);
    /* What `bin/grade --prebuild` made when the image was set up: copied with their times, so make
     * finds them newer than the sources and does nothing (unless the work folder is that very one). */
    out->prebuilt = 0;
    for (int k = 0; k < 2 && strcmp(rp->prebuilt, rp->work); k++, out->prebuilt++)
        grade_path(out->from[out->count++], GRADE_PATH, "%s/course/%s", rp->prebuilt, k ? "bin" : "build");
    /* The renderer, the recipes, and the split suites of the parts to grade only. */
    int argc = 0;
    const char *head[] = {"make", "-C", rp->course, GRADE_MAKE_ARGS, "bin/pathtracer", GRADE_RECIPES};
    for (size_t k = 0; k < sizeof head / sizeof head[0]; k++) out->make[argc++] = (char *)head[k];
    static const char *const per_part[] = {"bin/subject-part%d", "bin/judge-part%d"};
    for (int k = 1; k <= GRADE_MAX_PART; k++)
        for (int j = 0; j < 2 && strchr(parts, '0' + k); j++) {
            snprintf(out->programs[2 * (k - 1) + j], sizeof out->programs[0], per_part[j], k);
            out->make[argc++] = out->programs[2 * (k - 1) + j];
        }
    out->make[argc] = NULL;
}

bool grade_plan_part_folder(const char *tree, int n, char *out, size_t size)
{
    grade_path_buf parts;
    char prefix[16];
    if (!grade_path(parts, sizeof parts, "%s/parts", tree)) return false;
    snprintf(prefix, sizeof prefix, "part%d_", n);
    DIR *d = opendir(parts);
    if (!d) return false;
    bool found = false;
    for (struct dirent *e; !found && (e = readdir(d));)
        if (!strncmp(e->d_name, prefix, strlen(prefix))) found = snprintf(out, size, "%s", e->d_name) < (int)size;
    closedir(d);
    return found;
}

bool grade_plan_submitted(const grade_env *env, const char *folder, char *out, size_t size)
{
    return grade_path(out, size, "%s/parts/%s", env->submission, folder);
}

bool grade_plan_reference(const char *root, const grade_case *k, int part, char *out, size_t size)
{
    return grade_path(out, size, "%s/reference_images/%spart%d/%s.exr", root, k->hidden ? "hidden/" : "", part, k->name);
}

bool grade_plan_reference_json(const char *ref_exr, char *out, size_t size)
{
    size_t n = strlen(ref_exr);
    return n > 4 && grade_path(out, size, "%.*s.json", (int)(n - 4), ref_exr);
}

void grade_plan_suite_sources(int n, char *out, size_t size)
{
    grade_path(out, size, "%s/part%d", "tests", n);  /* (split: the release check reads paths in code) */
}

void grade_plan_handout(int n, char *out, size_t size)
{
    grade_path(out, size, "%s/part%d%s", "handout", n, ".md");  /* (split: the release check reads paths in code) */
}

/* ---- a part's plan ---------------------------------------------------------------------------- */

/* The line of the recipes (the file's text, in plan->text) that starts with `key` and a space, copied
 * into the plan's text and cut into words there (a recipe holds no quoted words: the course's paths
 * have no spaces), into words from index `first`; the new count, or -1 when there is no such line
 * or no room. */
static int recipe_words(grade_plan *plan, size_t file_len, const char *key, char **words, int first, int room)
{
    size_t k = strlen(key);
    for (const char *line = plan->text; line < plan->text + file_len;) {
        const char *end = memchr(line, '\n', (size_t)(plan->text + file_len - line));
        size_t len = end ? (size_t)(end - line) : (size_t)(plan->text + file_len - line);
        if (len > k && !strncmp(line, key, k) && line[k] == ' ' && plan->text_used + len + 1 <= plan->text_size) {
            char *copy = plan->text + plan->text_used;
            memcpy(copy, line + k + 1, len - k - 1);
            copy[len - k - 1] = '\0';
            plan->text_used += len - k;
            int n = first;
            for (char *save = NULL, *w = strtok_r(copy, " ", &save); w; w = strtok_r(NULL, " ", &save))
                if (n < room - 1) words[n++] = w;
                else return -1;
            words[n] = NULL;
            return n;
        }
        line += len + 1;
    }
    return -1;
}

/* The course's recipes (written by the course's make before any student file was read), whole into
 * plan->text, with room after them for the lines the commands take. */
static bool recipes_read(const char *course, grade_plan *plan, size_t *len)
{
    grade_path_buf path;
    char *data = NULL;
    pl_diag diag = pl_diag_default();
    if (!grade_path(path, sizeof path, "%s/" GRADE_RECIPES, course) ||
        file_read_all(path, "recipes", GRADE_TOOL_LOG_MAX, &data, len, &diag) != PL_OK)
        return false;
    plan->text_size = 4 * *len + 1024;  /* the file, then the lines of the compile and two links */
    plan->text = malloc(plan->text_size);
    if (plan->text) memcpy(plan->text, data, *len), plan->text_used = *len;
    free(data);
    return plan->text != NULL;
}

/* A submitted file's compile: the recipes' compiler and flags, then its own dependency file, object
 * and source, with TMPDIR in its output folder (the caller's environment). */
static bool plan_source(grade_plan *plan, size_t recipes_len, const char *name, grade_plan_source *src)
{
    size_t n = strlen(name);
    snprintf(src->name, sizeof src->name, "%s", name);
    bool ok = grade_path(src->source, GRADE_PATH, "parts/%s/%s", plan->folder, name) &&
              grade_path(src->compiled_obj, GRADE_PATH, "%s/%.*s.o", plan->scratch_out, (int)n - 2, name) &&
              grade_path(src->compiled_dep, GRADE_PATH, "%s/%.*s.d", plan->scratch_out, (int)n - 2, name) &&
              grade_path(src->obj, GRADE_PATH, "%s/%.*s.o", plan->objects, (int)n - 2, name) &&
              grade_path(src->dep, GRADE_PATH, "%s/%.*s.d", plan->objects, (int)n - 2, name) &&
              grade_path(src->log, GRADE_PATH, "%s/compile-%s.log", plan->work, name);
    char **argv = src->compile.argv;
    int argc = ok ? recipe_words(plan, recipes_len, "cc", argv, 0, 2) : -1;
    if (argc != 1) return false;
    argc = recipe_words(plan, recipes_len, "compile", argv, 1, GRADE_PLAN_WORDS - 8);
    if (argc < 1) return false;
    char *tail[] = {"-MMD", "-MF", src->compiled_dep, "-c", "-o", src->compiled_obj, src->source, NULL};
    for (int w = 0; tail[w]; w++) argv[argc++] = tail[w];
    argv[argc] = NULL;
    return true;
}

/* A link of program bin: the recipes' line with the course's objects of the part replaced by the
 * submitted ones (the part's own object folder, in the tree). */
static bool plan_link(grade_plan *plan, size_t recipes_len, const char *bin, const char *what, int k)
{
    grade_plan_link *l = &plan->links[k];
    char key[128], own[128];
    snprintf(key, sizeof key, "link %s", bin);
    snprintf(own, sizeof own, GRADE_OBJECTS "/parts/%s/", plan->folder);
    l->what = what;
    char *words[GRADE_PLAN_WORDS];
    if (!grade_path(l->log, GRADE_PATH, "%s/link-%d.log", plan->work, k) ||
        recipe_words(plan, recipes_len, "cc", l->link.argv, 0, 2) != 1 ||
        recipe_words(plan, recipes_len, key, words, 0, GRADE_PLAN_WORDS - GRADE_SOURCE_FILES - 2) < 0)
        return false;
    int argc = 1;
    bool placed = false;
    for (char **w = words; *w; w++) {
        if (strncmp(*w, own, strlen(own))) l->link.argv[argc++] = *w;
        else if (!placed) {  /* the course's objects of the part: the submission's in their place, once */
            for (int i = 0; i < plan->num_sources; i++) l->link.argv[argc++] = plan->sources[i].obj;
            placed = true;
        }
    }
    l->link.argv[argc] = NULL;
    return placed;
}

/* Where a submission's part is laid out: the compile's folder (the course's headers, the part's own
 * files), the part's tree (the course's pieces, every part's headers, the other parts' objects), and
 * what the inspection reads of the course. */
static bool plan_layout(const grade_run_plan *rp, grade_plan *plan)
{
    static const char *const pieces[] = {"Makefile", "framework", "tests", "tools", "third_party", "scenes", "VERSION",
                                         "build"};
    bool ok = grade_path(plan->header_dirs[0].from, GRADE_PATH, "%s/framework", rp->course) &&
              grade_path(plan->header_dirs[0].to, GRADE_PATH, "%s/framework", plan->scratch_src) &&
              grade_path(plan->scratch_parts, GRADE_PATH, "%s/parts", plan->scratch_src) &&
              grade_path(plan->scratch_part, GRADE_PATH, "%s/%s", plan->scratch_parts, plan->folder) &&
              grade_path(plan->tree_bin, GRADE_PATH, "%s/bin", plan->tree) &&
              grade_path(plan->course_program, GRADE_PATH, "%s/bin/subject-part%d", rp->course, plan->part) &&
              grade_path(plan->course_objects, GRADE_PATH, "%s/" GRADE_OBJECTS "/parts/%s", rp->course, plan->folder);
    plan->num_header_dirs = 1;
    for (size_t k = 0; ok && k < sizeof pieces / sizeof pieces[0]; k++, plan->num_tree_pieces++)
        ok = grade_path(plan->tree_pieces[k].from, GRADE_PATH, "%s/%s", rp->course, pieces[k]);
    for (int n = 1; ok && n <= GRADE_MAX_PART; n++) {
        char other[64];
        if (!grade_plan_part_folder(rp->course, n, other, sizeof other)) continue;  /* not in this course */
        grade_plan_copy *h = &plan->header_dirs[plan->num_header_dirs++], *t = &plan->tree_headers[plan->num_tree_headers++];
        ok = grade_path(h->from, GRADE_PATH, "%s/parts/%s", rp->course, other) &&
             grade_path(h->to, GRADE_PATH, "%s/%s", plan->scratch_parts, other) &&
             grade_path(t->from, GRADE_PATH, "%s", h->from) &&
             grade_path(t->to, GRADE_PATH, "%s/parts/%s", plan->tree, other);
        if (ok && strcmp(other, plan->folder))
            ok = grade_path(plan->other_objects[plan->num_other_objects++], GRADE_PATH, "%s/" GRADE_OBJECTS "/parts/%s",
                            plan->tree, other);
    }
    return ok;
}

/* A submission's build: its scratch folders, each file's compile, the two links. */
static bool plan_build(const grade_env *env, const grade_run_plan *rp, const grade_manifest *m, grade_plan *plan)
{
    bool ok = grade_path(plan->submitted, GRADE_PATH, "%s/parts/%s", env->submission, plan->folder) &&
              grade_path(plan->scratch, GRADE_PATH, "%s/part%d-build", env->sandbox_dir, plan->part) &&
              grade_path(plan->scratch_src, GRADE_PATH, "%s/src", plan->scratch) &&
              grade_path(plan->scratch_out, GRADE_PATH, "%s/out", plan->scratch) &&
              grade_path(plan->objects, GRADE_PATH, "%s/" GRADE_OBJECTS "/parts/%s", plan->tree, plan->folder) &&
              grade_path(plan->tree_sources, GRADE_PATH, "%s/parts/%s", plan->tree, plan->folder) &&
              grade_path(plan->inspect_log, GRADE_PATH, "%s/inspect.log", plan->work) &&
              grade_path(plan->tree_log, GRADE_PATH, "%s/tree.log", plan->work) &&
              grade_path(plan->tmpdir_env, sizeof plan->tmpdir_env, "TMPDIR=%s", plan->scratch_out);
    ok = ok && plan_layout(rp, plan);
    size_t recipes_len = 0;
    if (!ok || !m || !recipes_read(rp->course, plan, &recipes_len)) return false;
    for (int i = 0; i < m->count; i++) {
        size_t n = strlen(m->names[i]);
        if (m->names[i][n - 1] != 'c') continue;  /* headers are laid out, never compiled alone */
        if (!plan_source(plan, recipes_len, m->names[i], &plan->sources[plan->num_sources++])) return false;
    }
    char subject[32];
    snprintf(subject, sizeof subject, "bin/subject-part%d", plan->part);
    return plan_link(plan, recipes_len, "bin/pathtracer", "the renderer", 0) &&
           plan_link(plan, recipes_len, subject, "the suite", 1);
}

/* A student's own tree: its make builds what the grading runs; its suite writes XML into a folder of
 * its own. */
static bool plan_own_tree(const grade_env *env, grade_plan *plan)
{
    static const char *const make[] = {"make", "-C", NULL, "-j2", "--no-print-directory", "WERROR=0", "SAN=0",
                                       "bin/pathtracer", NULL, NULL};
    snprintf(plan->own_target, sizeof plan->own_target, "bin/test-part%d", plan->part);
    for (int i = 0; i < 9; i++) plan->own_build.argv[i] = (char *)make[i];
    plan->own_build.argv[2] = plan->tree;
    plan->own_build.argv[8] = plan->own_target;
    plan->own_build.argv[9] = NULL;
    return grade_path(plan->suite_dir, GRADE_PATH, "%s/part%d-suite", env->sandbox_dir, plan->part) &&
           grade_path(plan->suite_xml_env, sizeof plan->suite_xml_env, "CMOCKA_XML_FILE=%s/%%g.xml", plan->suite_dir) &&
           grade_path(plan->suite_log, GRADE_PATH, "%s/suite.log", plan->work) &&
           grade_path(plan->suite_list_log, GRADE_PATH, "%s/suite.list", plan->work) &&
           grade_path(plan->test_program, GRADE_PATH, "%s/bin/test-part%d", plan->tree, plan->part);
}

/* One image case: its logs and film, its reference, its scene as the render sees it, its baseline's
 * renderer (work_check), its pictures. */
static bool plan_case(const grade_env *env, const grade_run_plan *rp, grade_plan *plan, const grade_case *k,
                      grade_plan_case *c)
{
    static const char *const kinds[3] = {"candidate", "reference", "z"};
    c->spec = k;
    bool hidden_scene = !strncmp(k->scene, "grading/", 8);  /* a hidden case's: a copy in the tree, only while it renders */
    const char *base = strrchr(k->scene, '/') ? strrchr(k->scene, '/') + 1 : k->scene;
    bool ok = grade_path(c->log, GRADE_PATH, "%s/%s.log", plan->work, k->name) &&
              grade_path(c->again_log, GRADE_PATH, "%s/%s.again.log", plan->work, k->name) &&
              grade_path(c->baseline_log, GRADE_PATH, "%s/%s.baseline.log", plan->work, k->name) &&
              grade_path(c->film, GRADE_PATH, "%s/%s.exr", plan->work, k->name) &&
              grade_plan_reference(env->root, k, plan->part, c->reference, GRADE_PATH) &&
              (hidden_scene ? grade_path(c->scene, GRADE_PATH, "%s/%s", plan->tree, base) &&
                                  grade_path(c->scene_source, GRADE_PATH, "%s/%s", env->root, k->scene)
                            : grade_path(c->scene, GRADE_PATH, "%s/%s", plan->tree, k->scene));
    /* The baseline: the course's renderer with its part 2 (a submission), or the tree's own, which
     * the render runs through the linear scan (a student's tree holds no course part 2). */
    ok = ok && grade_path(c->baseline_cwd, GRADE_PATH, "%s", plan->submission ? rp->course : plan->tree) &&
         grade_path(c->baseline, GRADE_PATH, "%s/bin/pathtracer", c->baseline_cwd);
    for (int i = 0; ok && i < 3; i++)
        ok = grade_path(c->images[i], sizeof c->images[i], "part%d_%s_%s.png", plan->part, k->name, kinds[i]) &&
             grade_path(c->image_paths[i], GRADE_PATH, "%s/%s", env->report, c->images[i]);
    return ok;
}

bool grade_plan_part(const grade_env *env, const grade_run_plan *rp, const grade_part_spec *p, const grade_manifest *m,
                     double deadline, grade_plan *plan, char *why, size_t size)
{
    memset(plan, 0, sizeof *plan);
    plan->part = p->part;
    plan->deadline = deadline;
    plan->submission = env->submission != NULL;
    bool ok = grade_plan_part_folder(env->root, p->part, plan->folder, sizeof plan->folder) &&
              grade_path(plan->work, GRADE_PATH, "%s/part%d", env->work, p->part) &&
              (plan->submission ? grade_path(plan->tree, GRADE_PATH, "%s/part%d", env->sandbox_dir, p->part)
                                : grade_path(plan->tree, GRADE_PATH, "%s", env->root)) &&
              grade_path(plan->build_log, GRADE_PATH, "%s/build.log", plan->work) &&
              grade_path(plan->split_dir, GRADE_PATH, "%s/split", plan->work) &&
              grade_path(plan->judge, GRADE_PATH, "%s/bin/judge-part%d", rp->course, p->part) &&
              grade_path(plan->subject, GRADE_PATH, "%s/bin/subject-part%d", plan->tree, p->part) &&
              grade_path(plan->tests_list_log, GRADE_PATH, "%s/tests.list", plan->split_dir) &&
              grade_path(plan->pathtracer, GRADE_PATH, "%s/bin/pathtracer", plan->tree);
    if (ok) ok = plan->submission ? plan_build(env, rp, m, plan) : plan_own_tree(env, plan);
    for (int i = 0; ok && i < p->num_cases; i++) {
        if (env->public_only && p->cases[i].hidden) continue;
        ok = plan_case(env, rp, plan, &p->cases[i], &plan->cases[plan->num_cases++]);
    }
    if (!ok) {
        grade_msg(why, size, "part %d's grading cannot be planned: a path too long for the grader, or the course's "
                  "build recipes missing (%s): the course's problem, please tell the staff", p->part, GRADE_RECIPES);
        grade_plan_free(plan);
    }
    return ok;
}

void grade_plan_free(grade_plan *plan)
{
    if (!plan) return;
    free(plan->text);
    plan->text = NULL;
}

bool grade_plan_split_test(const grade_plan *plan, int k, const char *name, grade_plan_test *out)
{
    bool ok = grade_path(out->subject_log, GRADE_PATH, "%s/subject-%d.log", plan->split_dir, k) &&
              grade_path(out->judge_log, GRADE_PATH, "%s/judge-%d.log", plan->split_dir, k) &&
              grade_path(out->judge_xml, GRADE_PATH, "%s/judge-%d.xml", plan->split_dir, k) &&
              grade_path(out->filter_env, sizeof out->filter_env, "PL_TEST_FILTER=%s", name) &&
              grade_path(out->xml_env, sizeof out->xml_env, "CMOCKA_XML_FILE=%s", out->judge_xml);
    out->subject_env[0] = out->filter_env, out->subject_env[1] = "PL_SEAM_FD=3", out->subject_env[2] = NULL;
    out->judge_env[0] = out->filter_env, out->judge_env[1] = "PL_SEAM_FD=0", out->judge_env[2] = "CMOCKA_MESSAGE_OUTPUT=xml";
    out->judge_env[3] = out->xml_env, out->judge_env[4] = NULL;
    return ok;
}

void grade_plan_case_command(const grade_case *k, const char *bin, const char *scene, const char *out,
                             unsigned long long seed, int threads, bool no_bvh, grade_case_text *text, char **argv)
{
    snprintf(text->width, sizeof text->width, "%d", k->width);
    snprintf(text->height, sizeof text->height, "%d", k->height);
    snprintf(text->samples, sizeof text->samples, "%d", k->samples);
    snprintf(text->seed, sizeof text->seed, "%llu", seed);
    snprintf(text->threads, sizeof text->threads, "%d", threads);
    int n = 0;
    argv[n++] = (char *)bin;
    if (no_bvh) argv[n++] = "--no-bvh";  /* the framework's linear scan: the work_check's baseline */
    for (int f = 0; f < k->num_flags; f++) argv[n++] = k->flags[f];
    /* No output file: the film goes to the grader's pipe (GRADE_FILM_FD), never through a file. */
    char *fixed[] = {"-r", text->width, text->height, "-s", text->samples, "--seed", text->seed, "-t",
                     text->threads, "-q", out ? "-f" : "--film-fd", out ? (char *)out : GRADE_FILM_FD_TEXT,
                     (char *)scene, NULL};
    for (char **f = fixed; *f; f++) argv[n++] = *f;
    argv[n] = NULL;
}
