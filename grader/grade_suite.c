/* Grader machinery: not part of any assignment. A suite's verdicts from its cmocka XML files
 * (grade_suite.h). The files are written by student code: read as hostile (no links, a size cap, no
 * DTD, no network), and anything the suite would not write makes the whole suite unreadable. */
#include "grade_suite.h"
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

/* One test into the suite's facts: its name (the course's, a C identifier: anything else is named by
 * kind) and, for a failure, the message cmocka wrote (the course's test's, with the candidate's
 * numbers in it: the report rounds them, grade_figure_text), less cmocka's "<file>:<line>: error:
 * Failure!" tail, cut on a character boundary; a skipped test is a failed one. */
static void add_test(grade_suite_facts *s, xmlNodePtr t, xmlNodePtr v)
{
    xmlChar *name = xmlGetProp(t, (const xmlChar *)"name");
    xmlChar *msg = v && !is_element(v, "skipped") ? xmlNodeGetContent(v) : NULL;
    const char *text = !v ? "" : msg ? (const char *)msg : "skipped: a skipped test is not a passed one";
    const char *tail = strstr(text, ": error: Failure!");
    size_t cut = tail ? (size_t)(tail - text) : strlen(text);
    if (cut > GRADE_MESSAGE_MAX) {
        cut = GRADE_MESSAGE_MAX;
        while (cut > 0 && ((unsigned char)text[cut] & 0xc0) == 0x80) cut--;  /* never inside a character */
    }
    bool identifier = name && strlen((char *)name) < 128 &&
                      strspn((char *)name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                          strlen((char *)name);
    grade_test_fact *f = grade_suite_note(s, identifier ? (char *)name : "(a test whose name is not a C identifier)",
                                          v == NULL);
    if (f) snprintf(f->message, sizeof f->message, "%.*s", (int)cut, text);
    xmlFree(name);
    xmlFree(msg);
}

grade_test_fact *grade_suite_note(grade_suite_facts *s, const char *name, bool passed)
{
    if (s->num_tests >= GRADE_MAX_TESTS) return NULL;
    grade_test_fact *f = &s->tests[s->num_tests++];
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", name);
    f->passed = passed;
    return f;
}

/* Counts the testcases below n (any depth) into *run and *failed. */
static void count_tests(xmlNodePtr n, grade_suite_facts *s, int *run, int *failed)
{
    for (xmlNodePtr c = n->children; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE) continue;
        if (is_element(c, "testcase")) {
            xmlNodePtr v = verdict_of(c);
            ++*run;
            *failed += v != NULL;
            add_test(s, c, v);
        }
        count_tests(c, s, run, failed);
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
static bool read_suite(xmlDocPtr doc, const char *group, grade_suite_facts *s, char *why, size_t size)
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
    count_tests(suite, s, &run, &failed);
    long tests = count_attribute(suite, "tests"), f = count_attribute(suite, "failures"),
         e = count_attribute(suite, "errors"), k = count_attribute(suite, "skipped");
    if (tests != run || f < 0 || e < 0 || (k < 0 && xmlHasProp(suite, (const xmlChar *)"skipped")) ||
        f + e + (k > 0 ? k : 0) != failed)
        return grade_msg(why, size, "tests=%ld failures=%ld errors=%ld skipped=%ld, but it holds %d tests of which %d did "
                        "not pass", tests, f, e, k, run, failed), false;
    s->run += run;
    s->failed += failed;
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

bool grade_suite_read_file(const char *path, const char *group, grade_suite_facts *s, char *why, size_t size)
{
    xmlDocPtr doc = parse_file(path, why, size);
    bool ok = doc && read_suite(doc, group, s, why, size);
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

bool grade_suite_read(const char *dir, const grade_test_list *order, int part, grade_suite_facts *s, char *why,
                      size_t size)
{
    char prefix[16], reason[256] = "";
    snprintf(prefix, sizeof prefix, "part%d: ", part);
    suite_file *files = calloc(SUITE_FILES_MAX, sizeof *files);
    int count = 0;
    DIR *d = files ? opendir(dir) : NULL;
    bool ok = d != NULL;
    if (!d) grade_msg(why, size, "the suite's results folder cannot be read");
    /* Every file is parsed before any is counted: the groups are then taken in the suite's order (the
     * folder's order is the file system's), so the failed tests are listed as the suite ran them. */
    for (struct dirent *e; ok && (e = readdir(d));) {
        const char *n = e->d_name;
        size_t len = strlen(n);
        if (!strcmp(n, ".") || !strcmp(n, "..")) continue;
        /* What cmocka names a group's file: "part<N>: <group>.xml", no path, no other file. */
        if (len < strlen(prefix) + 5 || len >= sizeof files[0].name || strncmp(n, prefix, strlen(prefix)) ||
            strcmp(n + len - 4, ".xml") || strchr(n, '/'))
            grade_msg(reason, sizeof reason, "the suite writes 'part%d: <group>.xml' files only, not this one", part);
        else if (count == SUITE_FILES_MAX) grade_msg(reason, sizeof reason, "more than %d groups", SUITE_FILES_MAX);
        else {
            grade_path_buf path;
            grade_join(dir, n, path, sizeof path);
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
        if (ok && !read_suite(files[i].doc, group, s, reason, sizeof reason)) {
            grade_msg(why, size, "%.200s: %s", files[i].name, reason);
            ok = false;
        }
        xmlFreeDoc(files[i].doc);
    }
    free(files);
    return ok;
}

void grade_suite_results(const char *dir, const grade_test_list *order, int expected, int status, int part,
                         grade_suite_facts *s)
{
    s->run = s->failed = s->num_tests = 0;
    s->judged = false;
    char why[200] = "";
    bool all_read = grade_suite_read(dir, order, part, s, why, sizeof why);
    /* The XML files are written group by group: a suite that stopped early (an _exit in a test, a
     * crash the suite survived) left fewer tests than it has; one with more was not the suite. */
    grade_why_code code = !all_read ? GRADE_WHY_SUITE_UNREADABLE
                        : s->run == 0 ? GRADE_WHY_SUITE_NO_RESULTS
                        : s->run < expected ? GRADE_WHY_SUITE_STOPPED
                        : s->run > expected ? GRADE_WHY_SUITE_TOO_MANY
                        : (status == 1 && s->failed == 0) || (status != 0 && status != 1) ? GRADE_WHY_SUITE_STATUS
                        : GRADE_WHY_NONE;
    s->why = grade_why_of(code);
    s->why.count = code == GRADE_WHY_SUITE_STATUS ? status : s->run;
    s->why.limit = expected;
    if (code == GRADE_WHY_SUITE_UNREADABLE) snprintf(s->why.detail, sizeof s->why.detail, "%s", why);
    s->judged = code == GRADE_WHY_NONE;
}
