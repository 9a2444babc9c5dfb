/* Grader machinery: not part of any assignment. One part: its tree, its suite, its image cases. */
#include "grade.h"
#include "grade_image.h"
#include "grade_guard.h"
#include "grade_inspect.h"
#include "../framework/file.h"
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define BUILD_SECONDS 300
#define SUITE_SECONDS 300
#define RENDER_SECONDS 120
#define LOG_MAX (256 * 1024)
#define XML_MAX (4L << 20)        /* a suite's results file: far more than 100 tests need */
#define BUILD_TAIL_LINES 40       /* of a failed build's output, shown in the report */

/* ---- the tree: the submission's part N among the solution's other parts ----------------------- */

/* The folder name of part n in root, e.g. "part2_bvh". */
static bool part_folder(const char *root, int n, char *out, size_t size)
{
    char parts[4096], prefix[16];
    snprintf(parts, sizeof parts, "%s/parts", root);
    snprintf(prefix, sizeof prefix, "part%d_", n);
    DIR *d = opendir(parts);
    if (!d) return false;
    bool found = false;
    for (struct dirent *e; !found && (e = readdir(d));)
        if (!strncmp(e->d_name, prefix, strlen(prefix))) found = snprintf(out, size, "%s", e->d_name) < (int)size;
    closedir(d);
    return found;
}

static bool run_quiet(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = BUILD_SECONDS, .log_path = log, .log_max = LOG_MAX};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
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
        snprintf(r->suite_reason, sizeof r->suite_reason, "cannot read the submission's parts/%s", folder);
        return false;
    }
    bool ok = mkdir(to, 0755) == 0;
    if (!ok) snprintf(r->suite_reason, sizeof r->suite_reason, "cannot create %s", to);
    for (struct dirent *e; ok && (e = readdir(d));) {
        if (e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2]))) continue;
        char src[4400], dst[4400];
        struct stat st;
        snprintf(src, sizeof src, "%s/%s", from, e->d_name);
        snprintf(dst, sizeof dst, "%s/%s", to, e->d_name);
        if (lstat(src, &st) != 0 || S_ISDIR(st.st_mode)) continue;
        if (!S_ISREG(st.st_mode)) {
            snprintf(r->suite_reason, sizeof r->suite_reason,
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
        if (!ok) snprintf(r->suite_reason, sizeof r->suite_reason, "%.250s", diag.error);
        free(data);
    }
    closedir(d);
    return ok;
}

/* With a submission: a fresh copy of the solution's tree with parts/<folder> taken from the
 * submission. Without: the tree itself (the student's own, graded cumulatively). The copy holds
 * what a build and its tests need, never grading/ or reference_images/; and the part's headers stay
 * the course's, since framework files include them (a header could otherwise put code into a
 * framework object, which the allow-list does not inspect). */
static bool make_tree(const grade_env *env, int n, char *tree, size_t size, grade_part_result *r)
{
    if (!env->submission) {
        snprintf(tree, size, "%s", env->root);
        return true;
    }
    char folder[256], from[4096], to[4096], log[4096];
    snprintf(tree, size, "%s/part%d/tree", env->work, n);
    snprintf(log, sizeof log, "%s/part%d/copy.log", env->work, n);
    if (!part_folder(env->root, n, folder, sizeof folder)) {
        snprintf(r->suite_reason, sizeof r->suite_reason, "no folder for part %d under parts/", n);
        return false;
    }
    char *rm[] = {"rm", "-rf", tree, NULL}, *mk[] = {"mkdir", "-p", tree, NULL};
    run_quiet(rm, NULL);
    if (!run_quiet(mk, NULL)) return false;
    static const char *const copied[] = {"Makefile", "framework", "parts", "tests", "tools", "third_party", "scenes",
                                         "VERSION"};
    for (size_t k = 0; k < sizeof copied / sizeof copied[0]; k++) {
        struct stat st;
        snprintf(from, sizeof from, "%s/%s", env->root, copied[k]);
        if (stat(from, &st) != 0) continue;
        char *cp[] = {"cp", "-a", from, tree, NULL};
        if (!run_quiet(cp, log)) return false;
    }
    snprintf(to, sizeof to, "%s/parts/%s", tree, folder);
    snprintf(from, sizeof from, "%s/parts/%s", env->submission, folder);
    struct stat st;
    if (stat(from, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(r->suite_reason, sizeof r->suite_reason, "the submission has no parts/%s folder", folder);
        return false;
    }
    char course_folder[4200];
    snprintf(course_folder, sizeof course_folder, "%s/parts/%s", env->root, folder);
    char *rm_part[] = {"rm", "-rf", to, NULL};
    if (!run_quiet(rm_part, NULL) || !copy_submitted_part(from, to, folder, r)) return false;
    char cmd[12800];
    snprintf(cmd, sizeof cmd, "for h in '%s'/*.h; do [ ! -e \"$h\" ] || cp -f \"$h\" '%s'/; done", course_folder, to);
    char *keep_headers[] = {"sh", "-c", cmd, NULL};
    if (!run_quiet(keep_headers, log)) return false;
    /* Student code runs as `nobody` when the grader is root: give it the tree, only. */
    if (env->sandbox.as_other_user) {
        char owner[64];
        snprintf(owner, sizeof owner, "%u:%u", env->sandbox.uid, env->sandbox.gid);
        char *chown[] = {"chown", "-R", owner, tree, NULL};
        if (!run_quiet(chown, log)) return false;
    }
    return true;
}

static bool build(const grade_env *env, const char *tree, int n, grade_part_result *r)
{
    char target[32];
    snprintf(target, sizeof target, "bin/test-part%d", n);
    snprintf(r->build_log, sizeof r->build_log, "%s/part%d/build.log", env->work, n);
    /* LTO=0: the objects then hold machine code, and the allow-list reads the very files linked.
     * WERROR=0 SAN=0: the course's build whatever the grader's caller exported (CI exports
     * WERROR=1, which made a student's unused variable a part that does not build). */
    char *argv[] = {"make", "-C", (char *)tree, "-j2", "--no-print-directory", "LTO=0", "WERROR=0", "SAN=0",
                    "bin/pathtracer", target, NULL};
    /* The compiler reads student code too (#include, .incbin): it runs contained like the code. */
    grade_run_opts o = {.wall_seconds = GRADE_BUILD_SECONDS, .log_path = r->build_log, .log_max = LOG_MAX,
                        .untrusted = env->submission != NULL, .compiler = true};
    grade_run_result rr = grade_run(argv, &o);
    bool ok = rr.exited && rr.status == 0;
    if (!ok) grade_log_tail(r->build_log, BUILD_TAIL_LINES, r->build_output, sizeof r->build_output);
    /* What was built and inspected is what runs: the child's user may no longer change it. */
    if (ok && env->submission && env->sandbox.as_other_user) {
        char bin[4200], objs[4200];
        snprintf(bin, sizeof bin, "%s/bin", tree);
        snprintf(objs, sizeof objs, "%s/build", tree);
        char *chown[] = {"chown", "-R", "0:0", bin, objs, NULL};
        ok = run_quiet(chown, NULL);
    }
    return ok;
}

/* make's quiet progress lines ("  CC     framework/rng.c"): no help in finding the error. */
static bool progress_line(const char *line)
{
    return !strncmp(line, "  CC ", 5) || !strncmp(line, "  LD ", 5);
}

void grade_log_tail(const char *path, int lines, char *out, size_t size)
{
    out[0] = '\0';
    int fd = path ? open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC) : -1;
    char window[65536];  /* the end of the log, where the error is */
    off_t end = fd >= 0 ? lseek(fd, 0, SEEK_END) : 0, start = end > (off_t)sizeof window - 1 ? end - (off_t)sizeof window + 1 : 0;
    ssize_t n = fd >= 0 && size > 1 ? pread(fd, window, (size_t)(end - start), start) : -1;
    if (fd >= 0) close(fd);
    if (n <= 0) return;
    window[n] = '\0';
    /* Walk back over whole lines (less a first line the window cut) until `lines` are kept or the
     * next would not fit; then copy them out in order. */
    char *first = start > 0 && strchr(window, '\n') ? strchr(window, '\n') + 1 : window;
    char *kept[256];
    int count = 0;
    size_t used = 0;
    for (char *p = window + n; p > first && count < lines && count < 256;) {
        while (p > first && p[-1] == '\n') *--p = '\0';
        char *line = p;
        while (line > first && line[-1] != '\n') line--;
        if (line == p) break;
        if (!progress_line(line)) {
            if (used + strlen(line) + 1 >= size) break;
            used += strlen(line) + 1;
            kept[count++] = line;
        }
        p = line;
    }
    for (int i = count - 1; i >= 0; i--) {
        strcat(out, kept[i]);
        if (i > 0) strcat(out, "\n");
    }
}

/* ---- the suite: verdicts from cmocka's XML files, one per test group ------------------------- */

static void append(char *buf, size_t size, const char *text)
{
    size_t len = strlen(buf);
    if (len + 1 < size) snprintf(buf + len, size - len, "%s", text);
}

/* Adds the tests of one cmocka XML file to r; false when the file is not cmocka's XML. */
static bool read_suite_xml(const char *path, grade_part_result *r)
{
    int fd = grade_guard_open_child_file(path, XML_MAX);  /* the suite's user wrote it: no links */
    xmlDocPtr doc = fd >= 0 ? xmlReadFd(fd, path, NULL, XML_PARSE_NONET | XML_PARSE_NOBLANKS | XML_PARSE_NOERROR | XML_PARSE_NOWARNING) : NULL;
    if (fd >= 0) close(fd);
    if (!doc) return false;
    xmlNodePtr root = xmlDocGetRootElement(doc);
    /* cmocka writes no DTD: one here could only declare entities to expand (amplification). */
    bool ok = root && !doc->intSubset && !xmlStrcmp(root->name, (const xmlChar *)"testsuites");
    for (xmlNodePtr s = ok ? root->children : NULL; s; s = s->next) {
        if (s->type != XML_ELEMENT_NODE || xmlStrcmp(s->name, (const xmlChar *)"testsuite")) continue;
        for (xmlNodePtr t = s->children; t; t = t->next) {
            if (t->type != XML_ELEMENT_NODE || xmlStrcmp(t->name, (const xmlChar *)"testcase")) continue;
            r->tests_run++;
            for (xmlNodePtr f = t->children; f; f = f->next) {
                if (f->type != XML_ELEMENT_NODE ||
                    (xmlStrcmp(f->name, (const xmlChar *)"failure") && xmlStrcmp(f->name, (const xmlChar *)"error")))
                    continue;
                r->tests_failed++;
                xmlChar *name = xmlGetProp(t, (const xmlChar *)"name");
                xmlChar *msg = xmlNodeGetContent(f);
                /* cmocka ends every failure with "<file>:<line>: error: Failure!": keep the place. */
                char *tail = msg ? strstr((char *)msg, ": error: Failure!") : NULL;
                if (tail) *tail = '\0';
                char line[1024];
                snprintf(line, sizeof line, "- `%s`: %.700s\n", name ? (char *)name : "?", msg ? (char *)msg : "");
                append(r->failures, sizeof r->failures, line);
                xmlFree(name);
                xmlFree(msg);
                break;
            }
        }
    }
    xmlFreeDoc(doc);
    return ok;
}

void grade_suite_score(const char *dir, int expected, double points, int status, grade_part_result *r)
{
    r->tests_run = r->tests_failed = 0;
    r->failures[0] = '\0';
    DIR *d = opendir(dir);
    bool all_read = d != NULL;
    for (struct dirent *e; d && (e = readdir(d));) {
        if (!strstr(e->d_name, ".xml")) continue;
        char path[4400];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        all_read = read_suite_xml(path, r) && all_read;
    }
    if (d) closedir(d);
    /* The XML files are written group by group: a suite that stopped early (an _exit in a test, a
     * crash the suite survived) left fewer tests than it has; one with more was not the suite. */
    if (!all_read || r->tests_run == 0)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite wrote no readable test results");
    else if (r->tests_run < expected)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite stopped after %d of %d tests", r->tests_run,
                 expected);
    else if (r->tests_run > expected)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite reported %d tests, but it has %d: its results "
                 "are not the suite's own", r->tests_run, expected);
    else if (status == 1 && r->tests_failed == 0)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite exited with status 1 but reported no failure");
    else if (status != 0 && status != 1)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite exited with status %d", status);
    if (r->suite_reason[0]) {
        r->tests_run = r->tests_failed = 0;
        r->failures[0] = '\0';
        r->unit_score = 0;
    }
    else
        r->unit_score = points * (double)(r->tests_run - r->tests_failed) / r->tests_run;
}

static void run_suite(const grade_env *env, const char *tree, const grade_part_spec *p, grade_part_result *r)
{
    char dir[4096], pattern[4200], xml_env[4300], log[4096], bin[4096];
    bool contained = env->submission != NULL;
    snprintf(dir, sizeof dir, "%s/part%d/suite", env->work, p->part);
    /* The suite's own folder: it may write its results there, and nothing else beside them. */
    if (!grade_guard_child_dir(dir, &env->sandbox, contained)) {
        snprintf(r->suite_reason, sizeof r->suite_reason, "cannot create %s", dir);
        return;
    }
    snprintf(pattern, sizeof pattern, "%s/%%g.xml", dir);
    snprintf(xml_env, sizeof xml_env, "CMOCKA_XML_FILE=%s", pattern);
    snprintf(log, sizeof log, "%s/part%d/suite.log", env->work, p->part);
    snprintf(bin, sizeof bin, "%s/bin/test-part%d", tree, p->part);
    char *envv[] = {"CMOCKA_MESSAGE_OUTPUT=xml", xml_env, NULL};
    char *argv[] = {bin, NULL};
    grade_run_opts o = {.wall_seconds = SUITE_SECONDS, .cwd = tree, .log_path = log, .log_max = LOG_MAX, .env = envv,
                        .untrusted = contained, .writes_files = true};
    grade_run_result rr = grade_run(argv, &o);

    /* A suite that crashed or timed out scores zero, whatever files it left. */
    if (!rr.exited) {
        grade_run_describe(&rr, r->suite_reason, sizeof r->suite_reason);
        return;
    }
    grade_suite_score(dir, p->unit_tests, p->unit_points, rr.status, r);
}

/* ---- one part -------------------------------------------------------------------------------- */

bool grade_part_dirs(const grade_env *env, int part)
{
    /* The part's folder is the grader's (its logs live there); the children get folders below it. */
    char dir[4096], renders[4200];
    snprintf(dir, sizeof dir, "%s/part%d", env->work, part);
    snprintf(renders, sizeof renders, "%s/renders", dir);
    return grade_guard_child_dir(dir, &env->sandbox, false) &&
           grade_guard_child_dir(renders, &env->sandbox, env->submission != NULL);
}

void grade_part(const grade_env *env, const grade_spec *spec, const grade_part_spec *p, grade_part_result *r)
{
    memset(r, 0, sizeof *r);
    r->part = p->part;
    r->unit_max = p->unit_points;
    r->max_score = p->unit_points;
    char tree[4096], dir[4096];
    snprintf(dir, sizeof dir, "%s/part%d", env->work, p->part);
    if (!grade_part_dirs(env, p->part)) snprintf(r->suite_reason, sizeof r->suite_reason, "cannot create %s", dir);
    for (int i = 0; i < p->num_cases; i++) {
        if (env->public_only && p->cases[i].hidden) continue;
        grade_case_result *c = &r->cases[r->num_cases++];
        memset(c, 0, sizeof *c);
        c->spec = &p->cases[i];
        r->max_score += p->cases[i].points;
    }
    r->built = !r->suite_reason[0] && make_tree(env, p->part, tree, sizeof tree, r) && build(env, tree, p->part, r);
    if (!r->built) {
        if (!r->suite_reason[0]) snprintf(r->suite_reason, sizeof r->suite_reason, "the part does not build");
        for (int i = 0; i < r->num_cases; i++) snprintf(r->cases[i].reason, sizeof r->cases[i].reason, "%s", r->suite_reason);
        return;
    }
    /* A submission's part keeps to the allow-list before any of it runs. */
    char folder[256], why[sizeof r->suite_reason];
    if (env->submission && part_folder(env->root, p->part, folder, sizeof folder)) {
        if (!grade_inspect_part(tree, folder, dir, true, why, sizeof why)) {
            snprintf(r->suite_reason, sizeof r->suite_reason, "%s", why);
            for (int i = 0; i < r->num_cases; i++) snprintf(r->cases[i].reason, sizeof r->cases[i].reason, "%s", why);
            return;
        }
    }
    run_suite(env, tree, p, r);
    for (int i = 0; i < r->num_cases; i++) grade_image_case(env, spec, tree, p->part, &r->cases[i]);
    r->score = r->unit_score;
    for (int i = 0; i < r->num_cases; i++) r->score += r->cases[i].score;
}
