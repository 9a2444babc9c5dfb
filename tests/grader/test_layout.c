/* Test machinery: not part of any assignment.
 * The grader's layout rules (grader/README.md, "The rules, and how a maintainer checks them"),
 * checked on its sources as text: the README's layout block gives each module its stage, and each
 * rule is a test here. The sources are read with comments and string contents blanked where a rule
 * is about code (a comment that mentions grade_path is not a call). */
#include "../common/test.h"
#include "../common/c_text.h"
#include "../../framework/file.h"
#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define GRADER "grader"
#define MAX_MODULES 64

/* ---- the README's layout block ------------------------------------------------------------------ */

static const char *const stages[] = {"shared", "spec", "plan", "build", "run", "verdicts", "score", "report", "driver"};
enum { SHARED = 0, DRIVER = 8 };

typedef struct {
    char name[48];
    int stage;
    char header[56];   /* its header: <name>.h, another's (sandbox.h), or "" for a program */
} module;

static module modules[MAX_MODULES];
static int num_modules;

static int stage_of(const char *word)
{
    for (int s = 0; s < (int)(sizeof stages / sizeof stages[0]); s++)
        if (!strcmp(word, stages[s])) return s;
    return -1;
}

/* Reads the ```layout block of grader/README.md into modules[]; fails the test when it is missing
 * or names an unknown stage. */
static void read_layout(void)
{
    char *text = NULL;
    size_t len = 0;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all(GRADER "/README.md", "the grader's README", 1 << 20, &text, &len, &d));
    const char *at = strstr(text, "```layout\n");
    if (!at) fail_msg("grader/README.md has no ```layout block");
    num_modules = 0;
    for (at = strchr(at, '\n') + 1; *at && strncmp(at, "```", 3); at = strchr(at, '\n') + 1) {
        char name[48] = "", stage[16] = "", header[48] = "", line[160];
        snprintf(line, sizeof line, "%.*s", (int)strcspn(at, "\n"), at);
        int n = sscanf(line, "%47s %15s %47s", name, stage, header);
        if (n < 2) fail_msg("grader/README.md, layout block: expected 'module stage [header]', got '%.40s'", at);
        module *m = &modules[num_modules++];
        snprintf(m->name, sizeof m->name, "%s", name);
        if ((m->stage = stage_of(stage)) < 0) fail_msg("grader/README.md, layout block: %s: no stage '%s'", name, stage);
        if (n == 3 && !strcmp(header, "-")) m->header[0] = '\0';
        else snprintf(m->header, sizeof m->header, "%s", n == 3 ? header : "");
        if (n < 3) snprintf(m->header, sizeof m->header, "%s.h", name);
        if (!strchr(at, '\n') || num_modules == MAX_MODULES) break;
    }
    free(text);
}

/* The module a file of grader/ belongs to (its stem, or the module whose header it is); NULL when
 * the layout block does not name it. */
static const module *module_of(const char *file)
{
    size_t stem = strcspn(file, ".");
    for (int i = 0; i < num_modules; i++)
        if (strlen(modules[i].name) == stem && !strncmp(modules[i].name, file, stem)) return &modules[i];
    return NULL;
}

/* ---- the sources, read as text ---------------------------------------------------------------- */

typedef struct {
    char name[64];
    char *text;    /* as written */
    char *code;    /* comments and the contents of strings and characters blanked */
} source;

static source sources[2 * MAX_MODULES];
static int num_sources;

/* Quiet while the planted breaks are checked (the last test): only the counts matter there. */
static bool quiet;
#define BROKEN(...) (quiet ? (void)0 : (void)print_error(__VA_ARGS__))

/* text with comments, strings and character constants blanked (their quotes kept), the same length. */
static char *code_of(const char *text)
{
    char *c = c_text_code(text, false);
    assert_non_null(c);
    return c;
}

static int by_name(const void *a, const void *b) { return strcmp(((const source *)a)->name, ((const source *)b)->name); }

/* Every .c and .h of grader/ (not seam/: its own rules), read and blanked. */
static int load_sources(void **state)
{
    (void)state;
    read_layout();
    DIR *d = opendir(GRADER);
    assert_non_null(d);
    num_sources = 0;
    for (struct dirent *e; (e = readdir(d)) && num_sources < (int)(sizeof sources / sizeof sources[0]);) {
        size_t n = strlen(e->d_name);
        if (n < 3 || (strcmp(e->d_name + n - 2, ".c") && strcmp(e->d_name + n - 2, ".h"))) continue;
        source *s = &sources[num_sources++];
        char path[300];
        size_t len = 0;
        pl_diag diag = pl_diag_default();
        if (n >= sizeof s->name) fail_msg("grader/%s: a name longer than this test keeps", e->d_name);
        memcpy(s->name, e->d_name, n + 1);
        snprintf(path, sizeof path, GRADER "/%s", e->d_name);
        assert_int_equal(PL_OK, file_read_all(path, "a grader source", 1 << 22, &s->text, &len, &diag));
        s->code = code_of(s->text);
    }
    closedir(d);
    qsort(sources, (size_t)num_sources, sizeof *sources, by_name);
    return 0;
}

static int free_sources(void **state)
{
    (void)state;
    for (int i = 0; i < num_sources; i++) free(sources[i].text), free(sources[i].code);
    return 0;
}

static bool is_c(const source *s) { return s->name[strlen(s->name) - 1] == 'c'; }

/* The 1-based line of position at in s's text. */
static int line_of(const source *s, const char *at, const char *base)
{
    int line = 1;
    for (const char *p = base; p < at; p++) line += *p == '\n';
    (void)s;
    return line;
}

/* Whether word occurs in code at p as a whole identifier. */
static bool word_at(const char *code, const char *p, const char *word)
{
    size_t n = strlen(word);
    return strncmp(p, word, n) == 0 && (p == code || !(isalnum((unsigned char)p[-1]) || p[-1] == '_')) &&
           !(isalnum((unsigned char)p[n]) || p[n] == '_');
}

/* ---- rule 0: every file is a module of the layout ----------------------------------------------- */

static void test_layout__every_file_has_a_stage(void **state)
{
    (void)state;
    for (int i = 0; i < num_sources; i++)
        if (!module_of(sources[i].name) && strcmp(sources[i].name, "sandbox.h"))
            fail_msg("grader/%s: its module is not in grader/README.md's layout block (give it a stage)", sources[i].name);
}

/* ---- rule 1: includes follow the pipeline ------------------------------------------------------- */

static int check_a_module_never_includes_a_later_stage(void)
{
    int broken = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        const module *m = module_of(s->name);
        if (!is_c(s) || !m) continue;
        for (const char *p = s->text; (p = strstr(p, "#include \"")); p++) {
            char header[64];
            if (sscanf(p, "#include \"%63[^\"]\"", header) != 1 || strchr(header, '/')) continue;
            const module *h = module_of(header);
            if (!h && !strcmp(header, "sandbox.h")) h = module_of("sandbox");
            if (!h) continue;
            bool ok = m->stage == DRIVER || h->stage == SHARED || (m->stage != SHARED && h->stage <= m->stage);
            if (!ok) {
                BROKEN("grader/%s:%d: a %s module includes %s, of the %s stage\n", s->name,
                            line_of(s, p, s->text), stages[m->stage], header, stages[h->stage]);
                broken++;
            }
        }
    }
    return broken;
}

/* ---- rule 2: only the plan formats a path ----------------------------------------------------- */

static int check_only_the_plan_formats_a_path(void)
{
    int broken = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        /* The plan, grade_fmt.c's grade_join, and the sandbox's self-test (no grading's path). */
        if (!is_c(s) || !strcmp(s->name, "grade_plan.c") || !strcmp(s->name, "grade_fmt.c") ||
            !strcmp(s->name, "probe_main.c"))
            continue;
        for (const char *p = s->code; (p = strstr(p, "grade_path")); p++)
            if (word_at(s->code, p, "grade_path")) {
                BROKEN("grader/%s:%d: calls grade_path\n", s->name, line_of(s, p, s->code));
                broken++;
            }
        /* A format that starts with a folder and a slash joins a path (in the text: strings are blank in code). */
        static const char *const joins[] = {"\"%s/", "\"%.*s/"};
        for (int j = 0; j < 2; j++)
            for (const char *p = s->text; (p = strstr(p, joins[j])); p++) {
                BROKEN("grader/%s:%d: a format that joins a path\n", s->name, line_of(s, p, s->text));
                broken++;
            }
    }
    return broken;
}

/* ---- rules 3 and 4: points in the score, pictures in the report ------------------------------- */

/* Every `word` written (assigned: word =, word +=, word -=) in code outside the file `allowed`. */
static int assignments_outside(const char *word, const char *allowed)
{
    int found = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        if (!is_c(s) || !strcmp(s->name, allowed)) continue;
        for (const char *p = s->code; (p = strstr(p, word)); p++) {
            if (!word_at(s->code, p, word) || (p > s->code && p[-1] != '.' && p[-1] != '>')) continue;
            const char *q = p + strlen(word);
            while (*q == ' ') q++;
            if ((q[0] == '=' && q[1] != '=') || ((q[0] == '+' || q[0] == '-') && q[1] == '=')) {
                BROKEN("grader/%s:%d: assigns %s\n", s->name, line_of(s, p, s->code), word);
                found++;
            }
        }
    }
    return found;
}

static int check_only_the_score_computes_points(void)
{
    int broken = assignments_outside("score", "grade_score.c") + assignments_outside("unit_score", "grade_score.c") +
                 assignments_outside("task_score", "grade_score.c") + assignments_outside("max_score", "grade_score.c");
    return broken;
}

/* Every call of function `word` (a whole identifier followed by '(') outside the file `allowed`. */
static int calls_outside(const char *word, const char *allowed)
{
    int found = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        if (!is_c(s) || !strcmp(s->name, allowed)) continue;
        for (const char *p = s->code; (p = strstr(p, word)); p++)
            if (word_at(s->code, p, word) && p[strlen(word)] == '(') {
                BROKEN("grader/%s:%d: calls %s\n", s->name, line_of(s, p, s->code), word);
                found++;
            }
    }
    return found;
}

static int check_only_the_report_writes_pictures(void)
{
    int broken = calls_outside("image_write_png", "grade_report.c") + calls_outside("image_write_png_rgb8", "grade_report.c");
    return broken;
}

/* ---- rule 5: a result is allocated -------------------------------------------------------------- */

static int check_a_result_is_never_a_value(void)
{
    static const char *const types[] = {"grade_result", "grade_part_result"};
    int broken = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        if (!is_c(s)) continue;
        for (size_t t = 0; t < 2; t++)
            for (const char *p = s->code; (p = strstr(p, types[t])); p++) {
                if (!word_at(s->code, p, types[t])) continue;
                const char *q = p + strlen(types[t]);
                while (*q == ' ') q++;
                if (isalpha((unsigned char)*q) || *q == '_') {  /* a declarator, not a pointer */
                    BROKEN("grader/%s:%d: a %s value\n", s->name, line_of(s, p, s->code), types[t]);
                    broken++;
                }
            }
    }
    return broken;
}

/* ---- rules 6 and 7: one header per module; no mutable state ------------------------------------- */

/* Walks code at brace depth 0, statement by statement (up to a ';' or a function's body), calling
 * fn with each statement's text (its braces' contents blanked) and whether it opened a body. */
static void each_statement(const char *code, void (*fn)(const char *stmt, bool body, void *arg), void *arg)
{
    size_t n = strlen(code);
    char *stmt = malloc(n + 1);
    assert_non_null(stmt);
    size_t len = 0;
    for (size_t i = 0; i < n; i++) {
        char c = code[i];
        if (c == '#' && (i == 0 || code[i - 1] == '\n')) {  /* a directive, with its continued lines */
            while (i < n && !(code[i] == '\n' && code[i - 1] != '\\')) i++;
            continue;
        }
        if (c == '{') {
            /* A function's body: the statement so far ends with a parameter list. */
            size_t k = len;
            while (k > 0 && isspace((unsigned char)stmt[k - 1])) k--;
            bool body = k > 0 && stmt[k - 1] == ')';
            int depth = 1;
            for (i++; i < n && depth; i++) depth += (code[i] == '{') - (code[i] == '}');
            i--;
            if (body) {
                stmt[len] = '\0';
                fn(stmt, true, arg);
                len = 0;
            }
            else stmt[len++] = ' ';
            continue;
        }
        if (c == ';') {
            stmt[len] = '\0';
            fn(stmt, false, arg);
            len = 0;
            continue;
        }
        stmt[len++] = c;
    }
    free(stmt);
}

/* The identifier before the first '(' of stmt, into out. */
static void function_name(const char *stmt, char *out, size_t size)
{
    const char *paren = strchr(stmt, '(');
    out[0] = '\0';
    if (!paren) return;
    const char *end = paren;
    while (end > stmt && isspace((unsigned char)end[-1])) end--;
    const char *start = end;
    while (start > stmt && (isalnum((unsigned char)start[-1]) || start[-1] == '_')) start--;
    snprintf(out, size, "%.*s", (int)(end - start), start);
}

typedef struct {
    const source *src, *header;
    int broken;
} exports_check;

static bool starts_with_word(const char *stmt, const char *word)
{
    while (isspace((unsigned char)*stmt)) stmt++;
    return word_at(stmt, stmt, word);
}

static void check_export(const char *stmt, bool body, void *arg)
{
    exports_check *x = arg;
    if (!body || starts_with_word(stmt, "static")) return;
    char name[128];
    function_name(stmt, name, sizeof name);
    if (!name[0] || !strcmp(name, "main")) return;
    bool declared = false;
    for (const char *p = x->header ? x->header->code : ""; !declared && (p = strstr(p, name)); p++)
        declared = word_at(x->header->code, p, name);
    if (!declared) {
        BROKEN("grader/%s: %s is exported but not declared in %s\n", x->src->name, name,
                    x->header ? x->header->name : "a header of its own");
        x->broken++;
    }
}

static const source *source_named(const char *name)
{
    for (int i = 0; i < num_sources; i++)
        if (!strcmp(sources[i].name, name)) return &sources[i];
    return NULL;
}

static int check_one_header_per_module(void)
{
    int broken = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        const module *m = module_of(s->name);
        if (!m || !is_c(s)) continue;
        if (!m->header[0]) continue;  /* a program */
        exports_check x = {s, source_named(m->header), 0};
        if (!x.header) {
            BROKEN("grader/%s: no header %s\n", s->name, m->header);
            broken++;
            continue;
        }
        each_statement(s->code, check_export, &x);
        broken += x.broken;
    }
    /* A header without a .c holds types and limits only: no function declared in it. */
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        char c_file[64];
        snprintf(c_file, sizeof c_file, "%.*s.c", (int)(strlen(s->name) - 2), s->name);
        if (is_c(s) || source_named(c_file) || !strcmp(s->name, "sandbox.h")) continue;
        for (const char *p = s->code; (p = strchr(p, '(')); p++) {
            const char *line = p;
            while (line > s->code && line[-1] != '\n') line--;
            if (!strncmp(line, "static inline", 13) || line[0] == '#' || line[0] == ' ') continue;
            BROKEN("grader/%s:%d: a header with no .c declares a function\n", s->name, line_of(s, p, s->code));
            broken++;
            break;
        }
    }
    return broken;
}

typedef struct {
    const source *src;
    int broken;
} state_check;

/* A declaration is immutable when its last '*' (if any) is followed by const, or it has no '*' and
 * is const: "static const char *const x[]", "static const int n". */
static bool immutable(const char *stmt)
{
    const char *star = strrchr(stmt, '*');
    const char *c = star ? strstr(star, "const") : strstr(stmt, "const");
    return c != NULL;
}

static bool allowed_state(const char *file, const char *stmt)
{
    return !strcmp(file, "probe_main.c") || (!strcmp(file, "grade_main.c") && strstr(stmt, "janitor_child"));
}

static void check_state(const char *stmt, bool body, void *arg)
{
    state_check *x = arg;
    if (body) return;
    const char *t = stmt;
    while (isspace((unsigned char)*t)) t++;
    if (!*t || starts_with_word(t, "typedef") || starts_with_word(t, "extern") || strchr(t, '(')) return;
    if ((starts_with_word(t, "struct") || starts_with_word(t, "enum") || starts_with_word(t, "union")) &&
        !strpbrk(t, "=")) {
        /* "struct x { ... }" alone declares a type; with a declarator after the braces, a variable. */
        const char *close = strrchr(t, ' ');
        if (!close || !strchr(t, '{')) return;
    }
    if (immutable(t) || allowed_state(x->src->name, t)) return;
    BROKEN("grader/%s: file-scope state: %.80s\n", x->src->name, t);
    x->broken++;
}

static int check_no_mutable_state_outside_a_frame(void)
{
    int broken = 0;
    for (int i = 0; i < num_sources; i++) {
        const source *s = &sources[i];
        if (!is_c(s)) continue;
        state_check x = {s, 0};
        each_statement(s->code, check_state, &x);
        broken += x.broken;
        /* A function's own static variables: state too. */
        for (const char *p = s->code; (p = strstr(p, "static")); p++) {
            if (!word_at(s->code, p, "static")) continue;
            const char *line = p;
            while (line > s->code && line[-1] != '\n') line--;
            if (line == p) continue;  /* file scope: checked above */
            /* The declaration up to its initializer, its braces or its end. */
            char stmt[256];
            snprintf(stmt, sizeof stmt, "%.*s", (int)strcspn(p, ";{="), p);
            if (immutable(stmt) || allowed_state(s->name, stmt)) continue;
            BROKEN("grader/%s:%d: a function's static state: %.80s\n", s->name, line_of(s, p, s->code), stmt);
            broken++;
        }
    }
    return broken;
}

static void test_layout__a_module_never_includes_a_later_stage(void **state)
{
    (void)state;
    int broken = check_a_module_never_includes_a_later_stage();
    if (broken) fail_msg("%d includes against the pipeline (grader/README.md, rule 1)", broken);
}

static void test_layout__only_the_plan_formats_a_path(void **state)
{
    (void)state;
    int broken = check_only_the_plan_formats_a_path();
    if (broken) fail_msg("%d paths formatted outside grade_plan.c (grader/README.md, rule 2)", broken);
}

static void test_layout__only_the_score_computes_points(void **state)
{
    (void)state;
    int broken = check_only_the_score_computes_points();
    if (broken) fail_msg("%d points computed outside grade_score.c (grader/README.md, rule 3)", broken);
}

static void test_layout__only_the_report_writes_pictures(void **state)
{
    (void)state;
    int broken = check_only_the_report_writes_pictures();
    if (broken) fail_msg("%d pictures written outside grade_report.c (grader/README.md, rule 4)", broken);
}

static void test_layout__a_result_is_never_a_value(void **state)
{
    (void)state;
    int broken = check_a_result_is_never_a_value();
    if (broken) fail_msg("%d results declared as values (grader/README.md, rule 5)", broken);
}

static void test_layout__one_header_per_module(void **state)
{
    (void)state;
    int broken = check_one_header_per_module();
    if (broken) fail_msg("%d exports without their module's header (grader/README.md, rule 6)", broken);
}

static void test_layout__no_mutable_state_outside_a_frame(void **state)
{
    (void)state;
    int broken = check_no_mutable_state_outside_a_frame();
    if (broken) fail_msg("%d mutable variables outside a function's frame (grader/README.md, rule 7)", broken);
}

/* ---- the checks can fail ---------------------------------------------------------------------------- */

/* Each check, on a source planted with what it refuses, refuses it: a checker that reads nothing
 * would pass every tree. */
static void test_layout__each_check_refuses_a_planted_break(void **state)
{
    (void)state;
    source planted = {.name = "grade_image.c"};
    planted.text = strdup("#include \"grade_words.h\"\nstatic int counter;\nint grade_image_extra(void) { return "
                          "grade_path(x, 1, \"%s/y\", z); }\nvoid f(grade_part_result r) { r.score = 1; "
                          "image_write_png(0, 0, 0); }\n");
    planted.code = code_of(planted.text);
    sources[num_sources++] = planted;
    quiet = true;
    int found[7] = {check_a_module_never_includes_a_later_stage(), check_only_the_plan_formats_a_path(),
                    check_only_the_score_computes_points(), check_only_the_report_writes_pictures(),
                    check_a_result_is_never_a_value(), check_one_header_per_module(),
                    check_no_mutable_state_outside_a_frame()};
    quiet = false;
    num_sources--;
    free(planted.text);
    free(planted.code);
    for (int rule = 0; rule < 7; rule++)
        if (found[rule] == 0) fail_msg("rule %d's check passed a source planted with what it refuses", rule + 1);
}

/* ---- the repository's layout (README.md) -------------------------------------------------------- */

/* The root README's Layout section comes right after its two commands, and its block lists exactly the
 * top-level folders of this tree (a release's too: course/ has a paragraph of its own, which a
 * release drops with the folder; what make builds is nobody's to list). */
static void test_layout__the_readme_lists_every_top_level_folder(void **state)
{
    (void)state;
    char *text = NULL;
    size_t len = 0;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all("README.md", "the README", 1 << 20, &text, &len, &d));
    const char *first = strstr(text, "\n## ");
    if (!first || strncmp(first, "\n## Layout\n", 11))
        fail_msg("README.md: its first section after the two commands must be '## Layout'");
    const char *block = strstr(first, "\n```\n");
    const char *end = block ? strstr(block + 5, "\n```") : NULL;
    if (!block || !end) fail_msg("README.md: the Layout section has no ``` block");
    char listed[32][48];
    int n = 0;
    for (const char *line = block + 5; line < end && n < 32; line = strchr(line, '\n') + 1) {
        /* "name/  ...", or "bench/ fuzz/  ...": the names before the description, each ending in '/'. */
        for (const char *w = line; *w != ' ' && *w != '\n' && n < 32;) {
            size_t k = strcspn(w, " \n");
            if (k > 1 && w[k - 1] == '/') snprintf(listed[n++], sizeof listed[0], "%.*s", (int)(k - 1), w);
            w += k;
            if (*w == ' ' && w[1] != ' ') w++;
        }
    }
    static const char *const made[] = {"bin", "build", "out", "release", "course"};
    DIR *dir = opendir(".");
    assert_non_null(dir);
    int missing = 0;
    for (struct dirent *e; (e = readdir(dir));) {
        char path[300];
        snprintf(path, sizeof path, "%s/.", e->d_name);
        if (e->d_name[0] == '.' || access(path, F_OK) != 0) continue;
        bool skip = false, found = false;
        for (size_t k = 0; k < sizeof made / sizeof made[0]; k++) skip = skip || !strcmp(e->d_name, made[k]);
        for (int k = 0; k < n; k++) found = found || !strcmp(e->d_name, listed[k]);
        if (!skip && !found) print_error("README.md's Layout does not list %s/\n", e->d_name), missing++;
    }
    closedir(dir);
    for (int k = 0; k < n; k++) {
        char path[300];
        snprintf(path, sizeof path, "%s/.", listed[k]);
        if (access(path, F_OK) != 0) print_error("README.md's Layout lists %s/, which this tree lacks\n", listed[k]), missing++;
    }
    free(text);
    if (missing) fail_msg("%d folders differ between README.md's Layout and the tree", missing);
}

int layout_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layout__every_file_has_a_stage),
        cmocka_unit_test(test_layout__a_module_never_includes_a_later_stage),
        cmocka_unit_test(test_layout__only_the_plan_formats_a_path),
        cmocka_unit_test(test_layout__only_the_score_computes_points),
        cmocka_unit_test(test_layout__only_the_report_writes_pictures),
        cmocka_unit_test(test_layout__a_result_is_never_a_value),
        cmocka_unit_test(test_layout__one_header_per_module),
        cmocka_unit_test(test_layout__no_mutable_state_outside_a_frame),
        cmocka_unit_test(test_layout__each_check_refuses_a_planted_break),
        cmocka_unit_test(test_layout__the_readme_lists_every_top_level_folder),
    };
    return cmocka_run_group_tests_name("grader layout (grader/README.md's rules)", tests, load_sources, free_sources);
}
