/* Grader machinery: not part of any assignment. A suite's verdicts from its cmocka XML files
 * (grade_suite.h). The files are written by student code: read as hostile (no links, a size cap, no
 * DTD, no network), and anything the suite would not write makes the whole suite unreadable. */
#include "grade_suite.h"
#include "grade_figure.h"
#include "grade_guard.h"
#include <dirent.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>


static bool is_element(xmlNodePtr n, const char *name)
{
    return n->type == XML_ELEMENT_NODE && !xmlStrcmp(n->name, (const xmlChar *)name);
}

/* The verdict element of testcase t (<failure>, <error> or <skipped>) anywhere below it, outside any
 * testcase nested in it; NULL when it passed. */
static xmlNodePtr verdict_of(xmlNodePtr t)
{
    for (xmlNodePtr c = t->children; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE || is_element(c, "testcase")) continue;
        if (is_element(c, "failure") || is_element(c, "error") || is_element(c, "skipped")) return c;
        xmlNodePtr deeper = verdict_of(c);
        if (deeper) return deeper;
    }
    return NULL;
}

/* One failed test as a Markdown line: its name and message, the message cut at a character boundary
 * and escaped for Markdown. */
static void add_failure(grade_part_result *r, xmlNodePtr t, xmlNodePtr v)
{
    xmlChar *name = xmlGetProp(t, (const xmlChar *)"name");
    xmlChar *msg = is_element(v, "skipped") ? NULL : xmlNodeGetContent(v);
    char rounded[GRADE_MESSAGE_MAX + 64];
    /* The message is the course's test's, but its numbers are the candidate's answers: rounded. */
    grade_figure_text(msg ? (char *)msg : "", rounded, sizeof rounded);
    char *text = msg ? rounded : (char *)"skipped: a skipped test is not a passed one";
    /* cmocka ends every failure with "<file>:<line>: error: Failure!": keep the place. */
    char *tail = strstr(text, ": error: Failure!");
    if (tail) *tail = '\0';
    size_t cut = strlen(text);
    if (cut > GRADE_MESSAGE_MAX) {
        cut = GRADE_MESSAGE_MAX;
        while (cut > 0 && ((unsigned char)text[cut] & 0xc0) == 0x80) cut--;  /* never inside a character */
    }
    /* Markdown: the message escaped (it holds the candidate's numbers, and whatever a suite of a
     * student's own tree printed), the name only when it is a C identifier, as the course's are. */
    char escaped[2 * GRADE_MESSAGE_MAX + 2];
    grade_md_escape(text, cut, escaped, sizeof escaped);
    const char *shown = name && strlen((char *)name) < 200 &&
                                strspn((char *)name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                                    strlen((char *)name)
                            ? (char *)name : "(a test whose name is not a C identifier)";
    size_t len = strlen(r->failures);
    if (len + 1 < sizeof r->failures) snprintf(r->failures + len, sizeof r->failures - len, "- `%s`: %s\n", shown, escaped);
    xmlFree(name);
    xmlFree(msg);
}

/* Counts the testcases below n (any depth) into *run and *failed. */
static void count_tests(xmlNodePtr n, grade_part_result *r, int *run, int *failed)
{
    for (xmlNodePtr c = n->children; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE) continue;
        if (is_element(c, "testcase")) {
            ++*run;
            xmlNodePtr v = verdict_of(c);
            if (v) {
                ++*failed;
                add_failure(r, c, v);
            }
            xmlChar *name = xmlGetProp(c, (const xmlChar *)"name");
            grade_score_note_test(r, name ? (const char *)name : "?", v == NULL);
            xmlFree(name);
        }
        count_tests(c, r, run, failed);
    }
}

/* A whole-number attribute of n, or -1 when absent or not a number. */
static long count_attribute(xmlNodePtr n, const char *name)
{
    xmlChar *v = xmlGetProp(n, (const xmlChar *)name);
    char *end = NULL;
    long x = v && v[0] >= '0' && v[0] <= '9' ? strtol((const char *)v, &end, 10) : -1;
    if (end && *end) x = -1;
    xmlFree(v);
    return x;
}

/* The file's one <testsuite>, named `group`, with its counts agreeing with its testcases. */
static bool read_suite(xmlDocPtr doc, const char *group, grade_part_result *r, char *why, size_t size)
{
    xmlNodePtr root = xmlDocGetRootElement(doc), suite = NULL;
    /* cmocka writes no DTD: one here could only declare entities to expand (amplification). */
    if (!root || doc->intSubset || !is_element(root, "testsuites"))
        return grade_msg(why, size, "expected <testsuites> and no DTD"), false;
    for (xmlNodePtr c = root->children; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE) {
            if (suite || !is_element(c, "testsuite")) return grade_msg(why, size, "expected one <testsuite>"), false;
            suite = c;
        }
    xmlChar *name = suite ? xmlGetProp(suite, (const xmlChar *)"name") : NULL;
    bool named = name && (!group || !strcmp((const char *)name, group));
    xmlFree(name);
    if (!named) return grade_msg(why, size, "expected one <testsuite name=\"<the file's group>\">"), false;
    int run = 0, failed = 0;
    count_tests(suite, r, &run, &failed);
    long tests = count_attribute(suite, "tests"), f = count_attribute(suite, "failures"),
         e = count_attribute(suite, "errors"), s = count_attribute(suite, "skipped");
    if (tests != run || f < 0 || e < 0 || (s < 0 && xmlHasProp(suite, (const xmlChar *)"skipped")) ||
        f + e + (s > 0 ? s : 0) != failed)
        return grade_msg(why, size, "tests=%ld failures=%ld errors=%ld skipped=%ld, but it holds %d tests of which %d did "
                        "not pass", tests, f, e, s, run, failed), false;
    r->tests_run += run;
    r->tests_failed += failed;
    return true;
}

/* Parses the file at path, opened without following a link; NULL, with the reason in why, otherwise. */
static xmlDocPtr parse_file(const char *path, char *why, size_t size)
{
    int fd = grade_guard_open_child_file(path, GRADE_SUITE_XML_MAX);
    xmlDocPtr doc = fd >= 0 ? xmlReadFd(fd, path, NULL, XML_PARSE_NONET | XML_PARSE_NOBLANKS | XML_PARSE_NOERROR |
                                                           XML_PARSE_NOWARNING) : NULL;
    if (fd >= 0) close(fd);
    if (!doc) grade_msg(why, size, "not a regular file under %ld MiB of XML", GRADE_SUITE_XML_MAX >> 20);
    return doc;
}

bool grade_suite_read_file(const char *path, const char *group, grade_part_result *r, char *why, size_t size)
{
    xmlDocPtr doc = parse_file(path, why, size);
    bool ok = doc && read_suite(doc, group, r, why, size);
    xmlFreeDoc(doc);
    return ok;
}

/* ---- a whole suite's folder, its groups in the order the suite runs them ---------------------- */

#define SUITE_FILES_MAX 64  /* groups in one suite: the course's largest has 8 */

typedef struct {
    char name[208];  /* "part<N>: <group>.xml" */
    xmlDocPtr doc;
    int rank;        /* the place of its first test in the suite's list */
} suite_file;

/* The smallest place in order of a testcase below n (any depth), into *best. */
static void rank_tests(xmlNodePtr n, const grade_test_list *order, int *best)
{
    for (xmlNodePtr c = n->children; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE) continue;
        xmlChar *name = is_element(c, "testcase") ? xmlGetProp(c, (const xmlChar *)"name") : NULL;
        for (int i = 0; name && order && i < order->count && i < *best; i++)
            if (!strcmp((const char *)name, order->names[i])) *best = i;
        xmlFree(name);
        rank_tests(c, order, best);
    }
}

static int compare_files(const void *a, const void *b)
{
    const suite_file *x = a, *y = b;
    return x->rank != y->rank ? (x->rank < y->rank ? -1 : 1) : strcmp(x->name, y->name);
}

bool grade_suite_read(const char *dir, const grade_test_list *order, grade_part_result *r, char *why, size_t size)
{
    char prefix[16], reason[256] = "";
    snprintf(prefix, sizeof prefix, "part%d: ", r->part);
    static suite_file files[SUITE_FILES_MAX];
    int count = 0;
    DIR *d = opendir(dir);
    bool ok = d != NULL;
    if (!d) grade_msg(why, size, "%s: cannot read the folder", dir);
    /* Every file is parsed before any is counted: the groups are then taken in the suite's order (the
     * folder's order is the file system's), so the failed tests are listed as the suite ran them. */
    for (struct dirent *e; ok && (e = readdir(d));) {
        const char *n = e->d_name;
        size_t len = strlen(n);
        if (!strcmp(n, ".") || !strcmp(n, "..")) continue;
        /* What cmocka names a group's file: "part<N>: <group>.xml", no path, no other file. */
        if (len < strlen(prefix) + 5 || len >= sizeof files[0].name || strncmp(n, prefix, strlen(prefix)) ||
            strcmp(n + len - 4, ".xml") || strchr(n, '/'))
            grade_msg(reason, sizeof reason, "the suite writes 'part%d: <group>.xml' files only, not this one", r->part);
        else if (count == SUITE_FILES_MAX) grade_msg(reason, sizeof reason, "more than %d groups", SUITE_FILES_MAX);
        else {
            char path[4400];
            grade_path(path, sizeof path, "%s/%s", dir, n);
            suite_file *f = &files[count];
            memcpy(f->name, n, len + 1);  /* len < sizeof f->name, checked above */
            if ((f->doc = parse_file(path, reason, sizeof reason))) {
                f->rank = GRADE_MAX_TESTS;
                rank_tests(xmlDocGetRootElement(f->doc), order, &f->rank);
                count++;
                continue;
            }
        }
        grade_msg(why, size, "%.200s: %s", n, reason);
        ok = false;
    }
    if (d) closedir(d);
    qsort(files, (size_t)count, sizeof *files, compare_files);
    for (int i = 0; i < count; i++) {
        char group[256];
        snprintf(group, sizeof group, "%.*s", (int)(strlen(files[i].name) - 4), files[i].name);
        if (ok && !read_suite(files[i].doc, group, r, reason, sizeof reason)) {
            grade_msg(why, size, "%.200s: %s", files[i].name, reason);
            ok = false;
        }
        xmlFreeDoc(files[i].doc);
    }
    return ok;
}

bool grade_suite_list(const char *program, const grade_run_opts *o, grade_test_list *list)
{
    char *envv[] = {"PL_TEST_LIST=1", NULL}, *argv[] = {(char *)program, NULL};
    grade_run_opts listing = *o;
    listing.env = envv;
    grade_run_result rr = grade_run(argv, &listing);
    FILE *f = rr.exited && rr.status == 0 && o->log_path ? fopen(o->log_path, "r") : NULL;
    list->count = 0;
    char line[512];
    while (f && fgets(line, sizeof line, f)) {
        size_t len = strcspn(line, "\n");
        line[len] = '\0';
        if (strncmp(line, "  ", 2) || len - 2 >= sizeof list->names[0] ||
            strspn(line + 2, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != len - 2)
            continue;
        if (list->count < GRADE_MAX_TESTS) memcpy(list->names[list->count++], line + 2, len - 1);  /* and its NUL */
    }
    if (f) fclose(f);
    return list->count > 0;
}
