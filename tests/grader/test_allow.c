/* Test machinery: not part of any assignment.
 * One allow-list, said three times and kept equal: the PL_PART_API marks in the framework's headers
 * (framework/part_api.h), the grader's list (grader/grade_allow.c) and the handout's "What your part
 * may call" (handout/README.md); and each header's own word on what a part may not call. Run from
 * the repository's top, as make test-grader does. */
#include "../common/test.h"
#include "../common/c_text.h"
#include "../../grader/grade_allow.h"
#include <ctype.h>
#include <dirent.h>
#include <fnmatch.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NAMES 256
#define NAME_MAX_LEN 64

typedef struct {
    char name[MAX_NAMES][NAME_MAX_LEN];
    int count;
} name_list;

static bool listed(const name_list *l, const char *s)
{
    for (int i = 0; i < l->count; i++)
        if (!strcmp(l->name[i], s)) return true;
    return false;
}

static void add_name(name_list *l, const char *s, size_t len)
{
    if (l->count >= MAX_NAMES || len == 0 || len >= NAME_MAX_LEN) fail_msg("too many or too long names (%zu)", len);
    snprintf(l->name[l->count++], NAME_MAX_LEN, "%.*s", (int)len, s);
}

/* Reads a whole text file (at most 256 KiB) into a NUL-terminated buffer, or fails the test. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) fail_msg("cannot open %s (run from the repository's top)", path);
    char *text = calloc(1, 256 * 1024 + 1);
    size_t n = text ? fread(text, 1, 256 * 1024, f) : 0;
    fclose(f);
    if (!text || n == 0 || n == 256 * 1024) fail_msg("%s: empty, unreadable or too long", path);
    return text;
}

/* ---- what the three places say ------------------------------------------------------------- */

/* The name of each declaration marked PL_PART_API in text: the identifier before the first '(' on
 * the marked line (the mark starts its line). */
static void marked_names(const char *text, name_list *marked)
{
    for (const char *p = strstr(text, "\nPL_PART_API "); p; p = strstr(p + 1, "\nPL_PART_API ")) {
        const char *paren = strchr(p, '('), *eol = strchr(p + 1, '\n');
        if (!paren || (eol && paren > eol)) fail_msg("a PL_PART_API line without a '(': %.60s", p + 1);
        const char *end = paren;
        while (end > p && isspace((unsigned char)end[-1])) end--;
        const char *start = end;
        while (start > p && (isalnum((unsigned char)start[-1]) || start[-1] == '_')) start--;
        add_name(marked, start, (size_t)(end - start));
    }
}

/* Every framework header's text, concatenated (for "is this name declared anywhere?"). */
static char *framework_headers(name_list *marked)
{
    DIR *d = opendir("framework");
    if (!d) fail_msg("cannot open framework/ (run from the repository's top)");
    size_t cap = 1 << 20, len = 0;
    char *all = calloc(1, cap);
    struct dirent *e;
    while (all && (e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 3 || strcmp(e->d_name + n - 2, ".h")) continue;
        char path[300];
        snprintf(path, sizeof path, "framework/%s", e->d_name);
        char *text = slurp(path);
        marked_names(text, marked);
        size_t tn = strlen(text);
        if (len + tn + 2 > cap) fail_msg("the framework headers exceed %zu bytes", cap);
        memcpy(all + len, text, tn);
        len += tn;
        all[len++] = '\n';
        free(text);
    }
    closedir(d);
    if (!all) fail_msg("out of memory");
    return all;
}

/* The section of handout/README.md from its "## What your part may call" heading to the next. */
static char *handout_section(void)
{
    char *text = slurp("handout/README.md");
    char *start = strstr(text, "\n## What your part may call");
    if (!start) fail_msg("handout/README.md has no \"## What your part may call\" section");
    char *end = start ? strstr(start + 1, "\n## ") : NULL;  /* (fail_msg does not return) */
    if (end) *end = '\0';
    if (start) memmove(text, start, strlen(start) + 1);
    return text;
}

/* The `quoted` tokens of text that are identifiers or patterns of one (`mat4_*`, `*_pdf`). */
static void quoted_names(const char *text, name_list *out)
{
    for (const char *p = strchr(text, '`'); p; p = strchr(p + 1, '`')) {
        const char *q = strchr(p + 1, '`');
        if (!q) break;
        size_t n = (size_t)(q - p - 1);
        bool ident = n > 0;
        for (size_t i = 0; i < n; i++)
            ident = ident && (isalnum((unsigned char)p[1 + i]) || p[1 + i] == '_' || p[1 + i] == '*');
        if (ident) add_name(out, p + 1, n);
        p = q;
    }
}

/* A whole-word occurrence of name in text. */
static bool mentions(const char *text, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = strstr(text, name); p; p = strstr(p + 1, name)) {
        bool before = p == text || !(isalnum((unsigned char)p[-1]) || p[-1] == '_');
        bool after = !(isalnum((unsigned char)p[n]) || p[n] == '_');
        if (before && after) return true;
    }
    return false;
}

/* ---- what each header says a part may not call --------------------------------------------- */

/* The functions with external linkage a header declares, split by their PL_PART_API mark, and
 * whether it has a static inline one. A top-level statement (ended by ';' or by a body's closing
 * brace; what is inside braces skipped) that is no typedef and holds a '(' declares the identifier
 * before its first '('. */
static void header_functions(const char *text, name_list *marked, name_list *unmarked, bool *has_inline)
{
    char *t = c_text_code(text, true);
    if (!t) fail_msg("out of memory");
    *has_inline = false;
    int depth = 0;
    char *start = t;
    for (char *p = t; *p; p++) {
        if (*p == '{') depth++;
        if (*p == '}') depth--;
        bool ends = depth == 0 && (*p == ';' || *p == '}');
        if (!ends) continue;
        char *open = memchr(start, '(', (size_t)(p - start));
        while (start < p && isspace((unsigned char)*start)) start++;
        char *brace = memchr(start, '{', (size_t)(p - start));
        if (brace && (!open || brace < open)) open = NULL;  /* a struct's or an enum's body */
        if (open && strncmp(start, "typedef", 7)) {
            char *end = open;
            while (end > start && isspace((unsigned char)end[-1])) end--;
            char *name = end;
            while (name > start && (isalnum((unsigned char)name[-1]) || name[-1] == '_')) name--;
            bool is_static = false, is_marked = false;
            for (char *w = start; w < name; w++) {
                if (!strncmp(w, "static", 6)) is_static = true;
                if (!strncmp(w, "PL_PART_API", 11)) is_marked = true;
            }
            if (name == end || name == start || !strncmp(name, "__attribute__", 13)) {
                /* not a declaration of a named function */
            } else if (is_static) *has_inline = true;
            else add_name(is_marked ? marked : unmarked, name, (size_t)(end - name));
        }
        start = p + 1;
    }
    free(t);
}

/* The names listed after "Parts may not call: " up to the parenthesis that ends them, with the
 * comment's line breaks and stars taken out; or the whole phrase when it is not a list. */
static void said_not_callable(const char *path, const char *text, char *phrase, size_t size, name_list *listed_names)
{
    const char *at = strstr(text, "Parts may not call: ");
    const char *code = strstr(text, "*/");
    if (!at || (code && at > code))
        fail_msg("%s: its opening comment never says \"Parts may not call: ...\" (tests/grader/test_allow.c says how)", path);
    at += strlen("Parts may not call: ");
    size_t n = 0;
    for (; *at && *at != '(' && n + 1 < size; at++) {
        if (*at == '\n') {
            while (at[1] == ' ' || at[1] == '*') at++;
            phrase[n++] = ' ';
        } else phrase[n++] = *at;
    }
    while (n > 0 && phrase[n - 1] == ' ') n--;
    phrase[n] = '\0';
    for (const char *p = phrase; *p;) {
        size_t len = strcspn(p, ",");
        add_name(listed_names, p, len);
        p += len;
        while (*p == ',' || *p == ' ') p++;
    }
}

/* Every framework header says in its opening comment which of its functions a part may not call,
 * and says it truly: "none of these" where every function is marked or static inline, "any function
 * declared here" where none is marked, else the unmarked ones by name, each of them. So a student
 * reading envmap.h learns that envmap_texel_coords is the framework's, before the grader says so. */
static void test_allowlist__every_header_says_what_parts_may_not_call(void **state)
{
    DIR *d = opendir("framework");
    if (!d) fail_msg("cannot open framework/ (run from the repository's top)");
    int headers = 0;
    for (struct dirent *e; (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 3 || strcmp(e->d_name + n - 2, ".h")) continue;
        char path[300];
        snprintf(path, sizeof path, "framework/%s", e->d_name);
        char *text = slurp(path);
        name_list marked = {0}, unmarked = {0}, said = {0};
        bool has_inline;
        header_functions(text, &marked, &unmarked, &has_inline);
        char phrase[2048];
        said_not_callable(path, text, phrase, sizeof phrase, &said);
        free(text);
        if (unmarked.count == 0) {
            if (strcmp(phrase, "none of these"))
                fail_msg("%s: every function it declares is marked PL_PART_API or static inline, so it should say "
                         "\"Parts may not call: none of these\", not \"%s\"", path, phrase);
        } else if (marked.count == 0) {
            if (strncmp(phrase, "any function declared here", strlen("any function declared here")))
                fail_msg("%s: no function it declares is marked PL_PART_API (%s is one), so it should say \"Parts may "
                         "not call: any function declared here\", not \"%s\"", path, unmarked.name[0], phrase);
            if (!has_inline && strcmp(phrase, "any function declared here"))
                fail_msg("%s: it has no static inline function, yet says \"%s\"", path, phrase);
        } else {
            for (int i = 0; i < unmarked.count; i++)
                if (!listed(&said, unmarked.name[i]))
                    fail_msg("%s declares %s without PL_PART_API, but its \"Parts may not call:\" list leaves it out",
                             path, unmarked.name[i]);
            for (int i = 0; i < said.count; i++)
                if (!listed(&unmarked, said.name[i]))
                    fail_msg("%s: its \"Parts may not call:\" list names %s, which it does not declare unmarked", path,
                             said.name[i]);
        }
        headers++;
    }
    closedir(d);
    if (headers < 20) fail_msg("only %d headers found in framework/", headers);
}

/* ---- the tests ------------------------------------------------------------------------------ */

/* The grader's framework list is exactly the marked declarations: a mark without an entry would
 * cost a correct part its points, an entry without a mark would let a part reach framework code
 * nobody promised. */
static void test_allowlist__equals_the_part_api_marks(void **state)
{
    name_list marked = {0}, granted = {0};
    free(framework_headers(&marked));
    if (marked.count < 10) fail_msg("only %d PL_PART_API marks found in framework/", marked.count);
    for (const char *const *s = grade_allow_framework(); *s; s++) add_name(&granted, *s, strlen(*s));
    for (int i = 0; i < marked.count; i++)
        if (!listed(&granted, marked.name[i]))
            fail_msg("%s is marked PL_PART_API but grader/grade_allow.c does not allow it", marked.name[i]);
    for (int i = 0; i < granted.count; i++)
        if (!listed(&marked, granted.name[i]))
            fail_msg("grader/grade_allow.c allows %s, which no framework header marks PL_PART_API", granted.name[i]);
}

/* The handout names every marked function (by name or by a pattern such as `sample_*`), and every
 * framework-looking name it quotes (one with an underscore) exists in a framework header: a
 * function renamed or removed cannot linger in the students' list. */
static void test_allowlist__the_handout_names_what_exists(void **state)
{
    name_list marked = {0}, quoted = {0};
    char *headers = framework_headers(&marked);
    char *section = handout_section();
    quoted_names(section, &quoted);
    char missing[1024] = "", stale[1024] = "";
    for (int i = 0; i < marked.count; i++) {
        bool named = false;
        for (int k = 0; k < quoted.count && !named; k++) named = fnmatch(quoted.name[k], marked.name[i], 0) == 0;
        if (!named) snprintf(missing + strlen(missing), sizeof missing - strlen(missing), " %s", marked.name[i]);
    }
    for (int k = 0; k < quoted.count; k++) {
        const char *q = quoted.name[k];
        if (!strchr(q, '_') || strchr(q, '*') || q[0] == '_') continue;
        if (!mentions(headers, q)) snprintf(stale + strlen(stale), sizeof stale - strlen(stale), " %s", q);
    }
    free(headers);
    free(section);
    if (missing[0]) fail_msg("handout/README.md's \"What your part may call\" never names:%s", missing);
    if (stale[0]) fail_msg("handout/README.md's \"What your part may call\" names what no framework header has:%s", stale);
}

/* The reader of declarations above, on a header made to hold each shape it must tell apart: had it
 * missed a declaration, the test above would pass a header that hides one. */
static void test_allowlist__the_declaration_reader_sees_each_shape(void **state)
{
    const char *text = "/* x */\n#define M(a) f(a)\ntypedef struct { int (*cb)(void); } s;\n"
                       "PL_PART_API bool marked_one(int a);\nPL_PART_API\nfloat marked_two(void);\n"
                       "void plain(const s *x,\n           int y) __attribute__((nonnull));\n"
                       "static inline int helper(int a) { return g(a); }\nenum { A, B };\nextern int counter;\n"
                       "/* void commented(void); */\nint *pointer_back(void);\n";
    name_list marked = {0}, unmarked = {0};
    bool has_inline = false;
    header_functions(text, &marked, &unmarked, &has_inline);
    assert_int_equal(2, marked.count);
    assert_string_equal("marked_one", marked.name[0]);
    assert_string_equal("marked_two", marked.name[1]);
    assert_int_equal(2, unmarked.count);
    assert_string_equal("plain", unmarked.name[0]);
    assert_string_equal("pointer_back", unmarked.name[1]);
    assert_true(has_inline);
}

int allow_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_allowlist__equals_the_part_api_marks),
        cmocka_unit_test(test_allowlist__the_handout_names_what_exists),
        cmocka_unit_test(test_allowlist__every_header_says_what_parts_may_not_call),
        cmocka_unit_test(test_allowlist__the_declaration_reader_sees_each_shape),
    };
    return cmocka_run_group_tests_name("grader: one allow-list (PL_PART_API, grade_allow.c, the handout)", tests,
                                       NULL, NULL);
}
