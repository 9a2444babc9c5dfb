/* Grader machinery: not part of any assignment. One part: its tree, its suite, its image cases. */
#include "grade.h"
#include "grade_image.h"
#include "grade_inspect.h"
#include <dirent.h>
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
    grade_run_opts o = {BUILD_SECONDS, NULL, log, LOG_MAX, NULL, false};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* With a submission: a fresh copy of the solution's tree with parts/<folder> taken from the
 * submission. Without: the tree itself (the student's own, graded cumulatively). */
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
                                         "grading", "VERSION"};
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
    char *rm_part[] = {"rm", "-rf", to, NULL}, *cp_part[] = {"cp", "-r", from, to, NULL};
    if (!run_quiet(rm_part, NULL) || !run_quiet(cp_part, log)) return false;
    /* Student code runs as `nobody` when the grader is root: give it this part's folder, only. */
    if (env->sandbox.as_other_user) {
        char owner[64], part_dir[4096];
        snprintf(owner, sizeof owner, "%u:%u", env->sandbox.uid, env->sandbox.gid);
        snprintf(part_dir, sizeof part_dir, "%s/part%d", env->work, n);
        char *chown[] = {"chown", "-R", owner, part_dir, NULL};
        if (!run_quiet(chown, log)) return false;
    }
    return true;
}

static bool build(const grade_env *env, const char *tree, int n, grade_part_result *r)
{
    char target[32];
    snprintf(target, sizeof target, "bin/test-part%d", n);
    snprintf(r->build_log, sizeof r->build_log, "%s/part%d/build.log", env->work, n);
    char *argv[] = {"make", "-C", (char *)tree, "-j2", "--no-print-directory", "bin/pathtracer", target, NULL};
    /* The compiler reads student code too (#include, .incbin): it runs contained like the code. */
    grade_run_opts o = {BUILD_SECONDS, NULL, r->build_log, LOG_MAX, NULL, env->submission != NULL};
    grade_run_result rr = grade_run(argv, &o);
    return rr.exited && rr.status == 0;
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
    xmlDocPtr doc = xmlReadFile(path, NULL, XML_PARSE_NONET | XML_PARSE_NOBLANKS);
    if (!doc) return false;
    xmlNodePtr root = xmlDocGetRootElement(doc);
    bool ok = root && !xmlStrcmp(root->name, (const xmlChar *)"testsuites");
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
                char line[512];
                snprintf(line, sizeof line, "- `%s`: %.300s\n", name ? (char *)name : "?", msg ? (char *)msg : "");
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

static void run_suite(const grade_env *env, const char *tree, const grade_part_spec *p, grade_part_result *r)
{
    char dir[4096], pattern[4200], xml_env[4300], log[4096], bin[4096];
    snprintf(dir, sizeof dir, "%s/part%d/suite", env->work, p->part);
    char *rm[] = {"rm", "-rf", dir, NULL}, *mk[] = {"mkdir", "-p", dir, NULL};
    run_quiet(rm, NULL);
    /* Made by the suite's own user, so the suite can write its results there (and nothing else). */
    grade_run_opts mo = {BUILD_SECONDS, NULL, NULL, 0, NULL, env->submission != NULL};
    grade_run(mk, &mo);
    snprintf(pattern, sizeof pattern, "%s/%%g.xml", dir);
    snprintf(xml_env, sizeof xml_env, "CMOCKA_XML_FILE=%s", pattern);
    snprintf(log, sizeof log, "%s/part%d/suite.log", env->work, p->part);
    snprintf(bin, sizeof bin, "%s/bin/test-part%d", tree, p->part);
    char *envv[] = {"CMOCKA_MESSAGE_OUTPUT=xml", xml_env, NULL};
    char *argv[] = {bin, NULL};
    grade_run_opts o = {SUITE_SECONDS, tree, log, LOG_MAX, envv, env->submission != NULL};
    grade_run_result rr = grade_run(argv, &o);

    /* A suite that crashed, timed out or exited early scores zero, whatever files it left. */
    if (!rr.exited || (rr.status != 0 && rr.status != 1)) {
        grade_run_describe(&rr, r->suite_reason, sizeof r->suite_reason);
        return;
    }
    DIR *d = opendir(dir);
    bool all_read = d != NULL;
    for (struct dirent *e; d && (e = readdir(d));) {
        if (!strstr(e->d_name, ".xml")) continue;
        char path[4400];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        all_read = read_suite_xml(path, r) && all_read;
    }
    if (d) closedir(d);
    if (!all_read || r->tests_run == 0) {
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite wrote no readable test results");
        r->tests_run = r->tests_failed = 0;
        return;
    }
    if (rr.status == 1 && r->tests_failed == 0)
        snprintf(r->suite_reason, sizeof r->suite_reason, "the suite exited with status 1 but reported no failure");
    else
        r->unit_score = p->unit_points * (double)(r->tests_run - r->tests_failed) / r->tests_run;
}

/* ---- one part -------------------------------------------------------------------------------- */

void grade_part(const grade_env *env, const grade_spec *spec, const grade_part_spec *p, grade_part_result *r)
{
    memset(r, 0, sizeof *r);
    r->part = p->part;
    r->unit_max = p->unit_points;
    r->max_score = p->unit_points;
    char tree[4096], dir[4096];
    snprintf(dir, sizeof dir, "%s/part%d", env->work, p->part);
    char *mk[] = {"mkdir", "-p", dir, NULL};
    run_quiet(mk, NULL);
    for (int i = 0; i < p->num_cases; i++) {
        if (env->public_only && p->cases[i].hidden) continue;
        grade_case_result *c = &r->cases[r->num_cases++];
        memset(c, 0, sizeof *c);
        c->spec = &p->cases[i];
        r->max_score += p->cases[i].points;
    }
    r->built = make_tree(env, p->part, tree, sizeof tree, r) && build(env, tree, p->part, r);
    if (!r->built) {
        if (!r->suite_reason[0]) snprintf(r->suite_reason, sizeof r->suite_reason, "the part does not build");
        for (int i = 0; i < r->num_cases; i++) snprintf(r->cases[i].reason, sizeof r->cases[i].reason, "%s", r->suite_reason);
        return;
    }
    /* A submission's part keeps to the allow-list before any of it runs. */
    char folder[256], why[sizeof r->suite_reason];
    if (env->submission && part_folder(env->root, p->part, folder, sizeof folder)) {
        char scratch[4200];
        snprintf(scratch, sizeof scratch, "%s/build", tree);
        if (!grade_inspect_part(tree, folder, scratch, true, why, sizeof why)) {
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
