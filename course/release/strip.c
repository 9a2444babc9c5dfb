/* Instructor tooling: not part of any assignment. The release stripper's core (see strip.h). */
#include "strip.h"
#include "../../framework/buf.h"
#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Split literals: a whole marker in this file would make the release strip the stripper. */
#define MARK_BEGIN "/* BEGIN " "SOLUTION */"
#define MARK_END "/* END " "SOLUTION */"
#define MARK_STUB "/* STUB" ":"
#define MARK_BANNER "/* === PART"

/* One line of the input: text without its line ending, and the ending itself ("", "\n", "\r\n"). */
typedef struct {
    const char *text;
    size_t len;
    const char *eol;
    size_t eol_len;
    int number;  /* 1-based */
} line;

typedef enum { LINE_PLAIN, LINE_BEGIN, LINE_END, LINE_STUB, LINE_BANNER } line_kind;

/* Everything one pass over a file produces; out and tasks are optional. */
typedef struct {
    const char *name;
    pl_diag *diag;
    char *out;           /* NULL: validate only */
    size_t out_len;
    bool banners;        /* check banners and collect tasks (strip_tasks) */
    strip_task *tasks;   /* the banners seen so far */
    int num_tasks, cap_tasks;
    strip_task current;  /* the latest banner; line 0 before the first */
} pass;

static bool has(const char *s, size_t len, const char *needle)
{
    size_t n = strlen(needle);
    for (size_t i = 0; i + n <= len; i++)
        if (memcmp(s + i, needle, n) == 0) return true;
    return false;
}

static bool starts(const char *s, size_t len, const char *prefix)
{
    size_t n = strlen(prefix);
    return len >= n && memcmp(s, prefix, n) == 0;
}

static size_t indent_of(const line *l)
{
    size_t i = 0;
    while (i < l->len && (l->text[i] == ' ' || l->text[i] == '\t')) i++;
    return i;
}

/* The line without leading and trailing blanks. */
static void trimmed(const line *l, const char **s, size_t *len)
{
    size_t a = indent_of(l), b = l->len;
    while (b > a && isspace((unsigned char)l->text[b - 1])) b--;
    *s = l->text + a;
    *len = b - a;
}

/* Reads the line starting at in[*pos] and advances *pos past its ending. */
static line next_line(const char *in, size_t len, size_t *pos, int number)
{
    line l = {in + *pos, 0, "", 0, number};
    size_t i = *pos;
    while (i < len && in[i] != '\n') i++;
    l.len = i - *pos;
    if (i < len) {  /* a '\n' ends it; a '\r' before it belongs to the ending */
        bool crlf = l.len > 0 && l.text[l.len - 1] == '\r';
        if (crlf) l.len--;
        l.eol = crlf ? "\r\n" : "\n";
        l.eol_len = crlf ? 2 : 1;
        i++;
    }
    *pos = i;
    return l;
}

static pl_status fail(const pass *p, const line *l, const char *what)
{
    return pl_fail(p->diag, PL_ERR_PARSE, "%s:%d: %s", p->name, l->number, what);
}

/* Whether s[0..len) starts, ignoring case, with word and a character that cannot continue it. */
static bool starts_word(const char *s, size_t len, const char *word)
{
    size_t n = strlen(word);
    if (len < n || strncasecmp(s, word, n) != 0) return false;
    return len == n || !isalnum((unsigned char)s[n]);
}

/* Whether the ASCII word w[0..n) is one of the (lowercase) words in set, in any letter case. */
static bool word_in(const char *w, size_t n, const char *const *set)
{
    for (; *set; set++)
        if (strlen(*set) == n && strncasecmp(w, *set, n) == 0) return true;
    return false;
}

static const char *const EDGE_WORDS[] = {"begin", "end", NULL};
static const char *const SOLUTION_WORDS[] = {"solution", "solutions", NULL};

/* Whether w[0..n) is an edge word and a solution word glued together, in either order. */
static bool glued(const char *w, size_t n)
{
    for (size_t k = 1; k < n; k++)
        if ((word_in(w, k, EDGE_WORDS) && word_in(w + k, n - k, SOLUTION_WORDS)) ||
            (word_in(w, k, SOLUTION_WORDS) && word_in(w + k, n - k, EDGE_WORDS)))
            return true;
    return false;
}

/* In comment text c[0..end): the first place where BEGIN or END and SOLUTION(S) stand side by side,
 * in either order, in any case, with only blanks, '_' or '-' between (or glued into one word).
 * Its start and length go to *at, *len. */
static bool marker_words(const char *c, const char *end, const char **at, size_t *len)
{
    const char *prev = NULL;
    size_t prev_len = 0;
    bool prev_adjacent = false;  /* only blanks, '_' or '-' since the previous word */
    for (const char *s = c; s < end;) {
        if (!isalnum((unsigned char)*s)) {
            if (!isblank((unsigned char)*s) && *s != '_' && *s != '-') prev_adjacent = false;
            s++;
            continue;
        }
        const char *w = s;
        while (s < end && isalnum((unsigned char)*s)) s++;
        size_t n = (size_t)(s - w);
        bool pair = prev && prev_adjacent &&
                    ((word_in(prev, prev_len, EDGE_WORDS) && word_in(w, n, SOLUTION_WORDS)) ||
                     (word_in(prev, prev_len, SOLUTION_WORDS) && word_in(w, n, EDGE_WORDS)));
        if (pair || glued(w, n)) {
            *at = pair ? prev : w;
            *len = (size_t)(s - *at);
            return true;
        }
        prev = w;
        prev_len = n;
        prev_adjacent = true;
    }
    return false;
}

/* A comment that a reader (or a careless edit) would take for a marker but the stripper would not:
 * a line comment instead of a block comment, a missing or doubled blank, another letter case, the
 * words swapped or plural, '_' or '-' between them. Such a line would pass through a release with
 * the solution under it, so it is an error, never plain text. Looked for in every comment on the
 * line (after each opener, and the whole line when it starts inside a block comment): BEGIN or END
 * beside SOLUTION(S) (marker_words), or a comment whose first word is STUB followed by a colon or
 * nothing ("Stub bookkeeping" in prose is fine; so is "the end of the solution"). On a hit, the
 * words go to *at, *len. */
static bool near_miss(const line *l, bool in_comment, const char **at, size_t *len)
{
    const char *end = l->text + l->len;
    if (in_comment && marker_words(l->text, end, at, len)) return true;
    for (size_t i = 0; i + 1 < l->len; i++) {
        if (l->text[i] != '/' || (l->text[i + 1] != '*' && l->text[i + 1] != '/')) continue;
        const char *c = l->text + i + 2;
        while (c < end && (*c == '*' || *c == '/' || isspace((unsigned char)*c))) c++;
        if (starts_word(c, (size_t)(end - c), "stub")) {
            const char *d = c + 4;
            while (d < end && isspace((unsigned char)*d)) d++;
            if (d == end || *d == ':' || (*d == '*' && d + 1 < end && d[1] == '/')) {
                *at = c;
                *len = (size_t)(d - c);
                return true;
            }
        }
        if (marker_words(c, end, at, len)) return true;
    }
    return false;
}

/* What a line is; a marker that shares its line with anything else is an error. in_comment: the
 * line starts inside a block comment. */
static pl_status classify(const pass *p, const line *l, bool in_comment, line_kind *kind)
{
    const char *s;
    size_t n;
    trimmed(l, &s, &n);
    bool begin = has(l->text, l->len, MARK_BEGIN), end = has(l->text, l->len, MARK_END);
    if (begin && end) return fail(p, l, "expected BEGIN and END SOLUTION markers on separate lines");
    if (begin || end) {
        const char *mark = begin ? MARK_BEGIN : MARK_END;
        if (n != strlen(mark))
            return fail(p, l, begin ? "expected the BEGIN SOLUTION marker alone on its line"
                                    : "expected the END SOLUTION marker alone on its line");
        *kind = begin ? LINE_BEGIN : LINE_END;
        return PL_OK;
    }
    if (has(l->text, l->len, MARK_STUB)) {
        if (!starts(s, n, MARK_STUB) || n < strlen(MARK_STUB) + 2 || memcmp(s + n - 2, "*/", 2) != 0)
            return fail(p, l, "expected a STUB line to hold `" MARK_STUB " <code> */` and nothing else");
        *kind = LINE_STUB;
        return PL_OK;
    }
    const char *at;
    size_t at_len;
    if (near_miss(l, in_comment, &at, &at_len)) {
        char msg[512];
        snprintf(msg, sizeof msg, "`%.*s` looks like a solution marker but is not spelt exactly `" MARK_BEGIN
                 "`, `" MARK_END "` or `" MARK_STUB " <code> */`; expected the exact marker (the release would "
                 "copy this line and the solution after it)", (int)(at_len > 60 ? 60 : at_len), at);
        return fail(p, l, msg);
    }
    *kind = starts(s, n, MARK_BANNER) ? LINE_BANNER : LINE_PLAIN;
    return PL_OK;
}

static void emit(pass *p, const char *s, size_t n)
{
    if (!p->out) return;
    memcpy(p->out + p->out_len, s, n);
    p->out_len += n;
}

/* A STUB line's code: what lies between the marker and the closing comment, trimmed. */
static void stub_code(const line *l, const char **code, size_t *len)
{
    const char *s;
    size_t n;
    trimmed(l, &s, &n);
    size_t a = strlen(MARK_STUB), b = n - 2;
    while (a < b && isspace((unsigned char)s[a])) a++;
    while (b > a && isspace((unsigned char)s[b - 1])) b--;
    *code = s + a;
    *len = b - a;
}

/* ---- banners (checked only by strip_tasks) ------------------------------------------------ */

static const char *skip_blanks(const char *s, const char *end)
{
    while (s < end && (*s == ' ' || *s == '\t')) s++;
    return s;
}

static const char *expect_word(const char *s, const char *end, const char *word)
{
    s = skip_blanks(s, end);
    size_t n = strlen(word);
    if ((size_t)(end - s) < n || memcmp(s, word, n) != 0) return NULL;
    return s + n;
}

static bool is_ident(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* Parses a banner line, `=== PART N | TASK N.M | function ===...` after the comment opener, into t. */
static bool parse_banner(const line *l, strip_task *t)
{
    const char *s, *end, *w;
    size_t n;
    trimmed(l, &s, &n);
    end = s + n;
    s += strlen(MARK_BANNER);
    char *num_end;
    if (s >= end || !isblank((unsigned char)*s)) return false;
    long part = strtol(s, &num_end, 10);
    if (num_end == s || num_end > end || part < 1 || part > 99) return false;
    s = expect_word(num_end, end, "|");
    if (s) s = expect_word(s, end, "TASK");
    if (!s) return false;
    s = skip_blanks(s, end);
    w = s;
    while (s < end && (isdigit((unsigned char)*s) || *s == '.')) s++;
    size_t id_len = (size_t)(s - w);
    if (id_len == 0 || id_len >= sizeof t->id) return false;
    memcpy(t->id, w, id_len);
    t->id[id_len] = '\0';
    int major, minor;
    char tail;
    if (sscanf(t->id, "%d.%d%c", &major, &minor, &tail) != 2) return false;
    s = expect_word(s, end, "|");
    if (!s) return false;
    s = skip_blanks(s, end);
    w = s;
    while (s < end && is_ident(*s)) s++;
    size_t fn_len = (size_t)(s - w);
    if (fn_len == 0 || fn_len >= sizeof t->function || isdigit((unsigned char)*w)) return false;
    memcpy(t->function, w, fn_len);
    t->function[fn_len] = '\0';
    if (!expect_word(s, end, "===")) return false;
    t->part = (int)part;
    t->line = l->number;
    return true;
}

/* Whether the code calls a PL_TODO macro as PL_TODO*("id", "function"). */
static bool stub_names(const char *code, size_t len, const strip_task *t)
{
    const char *end = code + len;
    for (const char *s = code; s < end; s++) {
        if (!starts(s, (size_t)(end - s), "PL_TODO")) continue;
        const char *c = s + strlen("PL_TODO");
        while (c < end && (isupper((unsigned char)*c) || isdigit((unsigned char)*c) || *c == '_')) c++;  /* PL_TODO_VEC2 */
        char want_id[32], want_fn[80];
        snprintf(want_id, sizeof want_id, "\"%s\"", t->id);
        snprintf(want_fn, sizeof want_fn, "\"%s\"", t->function);
        c = expect_word(c, end, "(");
        if (c) c = expect_word(c, end, want_id);
        if (c) c = expect_word(c, end, ",");
        if (c) c = expect_word(c, end, want_fn);
        if (c) c = expect_word(c, end, ")");
        if (c) return true;
    }
    return false;
}

/* Where the latest banner stands: header, definition, solution, stub. */
typedef enum { TASK_NONE, TASK_IN_BANNER, TASK_WANT_FUNCTION, TASK_WANT_REGION, TASK_WANT_STUB, TASK_DONE } task_state;

static pl_status add_task(pass *p, const strip_task *t)
{
    for (int i = 0; i < p->num_tasks; i++)
        if (strcmp(p->tasks[i].id, t->id) == 0 && strcmp(p->tasks[i].function, t->function) == 0) {
            char msg[256];
            snprintf(msg, sizeof msg, "task %s %s() already has a banner at line %d; expected one banner a "
                     "function", t->id, t->function, p->tasks[i].line);
            line l = {0};
            l.number = t->line;
            return fail(p, &l, msg);
        }
    if (buf_append(&p->tasks, &p->num_tasks, &p->cap_tasks, sizeof *t, t) < 0)
        return pl_fail(p->diag, PL_ERR_NOMEM, "%s: out of memory", p->name);
    return PL_OK;
}

/* Whether the line defines or declares `function(`. */
static bool names_function(const line *l, const char *function)
{
    size_t n = strlen(function);
    for (size_t i = 0; i + n < l->len; i++)
        if (memcmp(l->text + i, function, n) == 0 && (i == 0 || !is_ident(l->text[i - 1])) &&
            (l->text[i + n] == '(' || l->text[i + n] == ' '))
            return true;
    return false;
}

/* Advances the banner checks by one line. */
static pl_status track_task(pass *p, task_state *st, const line *l, line_kind kind, bool after_end)
{
    const strip_task *t = &p->current;
    char msg[256];
    bool own = false;  /* this line is the STUB right after the task's solution */
    if (kind == LINE_BANNER) {
        if (*st != TASK_NONE && *st != TASK_DONE) {
            snprintf(msg, sizeof msg, "banner of task %s (line %d) has no solution region and STUB yet; "
                     "expected them before the next banner", t->id, t->line);
            return fail(p, l, msg);
        }
        strip_task next = {0};
        if (!parse_banner(l, &next))
            return fail(p, l, "expected a banner `/* === PART N | TASK N.M | function ===...`");
        char part_prefix[16];
        snprintf(part_prefix, sizeof part_prefix, "%d.", next.part);
        if (!starts(next.id, strlen(next.id), part_prefix)) {
            snprintf(msg, sizeof msg, "banner says PART %d but TASK %s; expected task %s<M>", next.part,
                     next.id, part_prefix);
            return fail(p, l, msg);
        }
        p->current = next;
        pl_status s = add_task(p, &next);
        if (s != PL_OK) return s;
        *st = has(l->text, l->len, "*/") ? TASK_WANT_FUNCTION : TASK_IN_BANNER;
        return PL_OK;
    }
    switch (*st) {
    case TASK_IN_BANNER:
        if (has(l->text, l->len, "*/")) *st = TASK_WANT_FUNCTION;
        break;
    case TASK_WANT_FUNCTION:
        if (names_function(l, t->function)) {
            *st = TASK_WANT_REGION;
        } else if (kind == LINE_BEGIN || indent_of(l) < l->len) {
            snprintf(msg, sizeof msg, "expected the definition of %s() right after the banner of task %s (line %d)",
                     t->function, t->id, t->line);
            return fail(p, l, msg);
        }
        break;
    case TASK_WANT_REGION:
        if (kind == LINE_END) *st = TASK_WANT_STUB;
        break;
    case TASK_WANT_STUB:
        if (kind != LINE_STUB || !after_end) {
            snprintf(msg, sizeof msg, "expected a STUB line after the solution of task %s (banner at line %d)",
                     t->id, t->line);
            return fail(p, l, msg);
        }
        *st = TASK_DONE;
        own = true;
        break;
    case TASK_NONE:
    case TASK_DONE:
        break;
    }
    if (kind != LINE_STUB) return PL_OK;
    /* The task's own STUB, and any other that reports a missing task, must name the banner's task,
     * so the student reads the same id and function in the banner, the handout and the message. */
    const char *code;
    size_t n;
    stub_code(l, &code, &n);
    bool reports = has(code, n, "PL_TODO");
    if (t->line == 0 && reports)
        return fail(p, l, "this STUB calls PL_TODO but no task banner precedes it; expected "
                          "a banner `=== PART N | TASK N.M | function ===` above the function");
    if ((reports || own) && !stub_names(code, n, t)) {
        snprintf(msg, sizeof msg, "expected this STUB to call PL_TODO*(\"%s\", \"%s\") as the banner at line %d says",
                 t->id, t->function, t->line);
        return fail(p, l, msg);
    }
    return PL_OK;
}

/* ---- the pass ----------------------------------------------------------------------------- */

/* Adds the line's braces to *depth, skipping comments (*in_comment carries a block comment to the
 * next line), string and character literals. Depth 0 is file scope: a region there may be a whole
 * helper removed without a stub; deeper, it sits in a function body and needs its STUB. */
static void count_braces(const line *l, bool *in_comment, int *depth)
{
    for (size_t i = 0; i < l->len; i++) {
        char c = l->text[i], next = i + 1 < l->len ? l->text[i + 1] : '\0';
        if (*in_comment) {
            if (c == '*' && next == '/') *in_comment = false, i++;
        } else if (c == '/' && next == '*') {
            *in_comment = true;
            i++;
        } else if (c == '/' && next == '/') {
            return;
        } else if (c == '"' || c == '\'') {
            for (i++; i < l->len && l->text[i] != c; i++)
                if (l->text[i] == '\\') i++;
        } else if (c == '{') {
            (*depth)++;
        } else if (c == '}') {
            (*depth)--;
        }
    }
}

/* A region inside a function body removed without a STUB would silently delete code from a
 * function the student is given: an error at the region's BEGIN. */
static pl_status stubless_in_body(const pass *p, const line *begin)
{
    return fail(p, begin, "solution region inside a function body has no STUB line; expected `" MARK_STUB
                          " <code> */` right after its END SOLUTION marker (only a region at file scope "
                          "may be removed whole)");
}

static pl_status run(pass *p, const char *in, size_t len)
{
    if (memchr(in, '\0', len)) {
        line l = {0};
        l.number = 1;
        for (size_t i = 0; in[i] != '\0'; i++) l.number += in[i] == '\n';
        return fail(p, &l, "unexpected NUL byte; expected a text file");
    }
    bool in_region = false, after_end = false;
    bool last_blank = true;  /* the last line written was blank (the start of the file counts) */
    bool in_comment = false;
    int depth = 0, begin_depth = 0;  /* brace depth now, and at the latest BEGIN */
    line begin_line = {0};
    task_state st = TASK_NONE;
    size_t pos = 0;
    for (int number = 1; pos < len; number++) {
        line l = next_line(in, len, &pos, number);
        line_kind kind = LINE_PLAIN;
        pl_status s = classify(p, &l, in_comment, &kind);
        if (s == PL_OK && p->banners) s = track_task(p, &st, &l, kind, after_end);
        if (s != PL_OK) return s;
        if (after_end && kind != LINE_STUB && begin_depth > 0) return stubless_in_body(p, &begin_line);
        if (kind == LINE_BEGIN) begin_depth = depth;
        count_braces(&l, &in_comment, &depth);
        if (in_region) {
            if (kind == LINE_BEGIN) {
                char msg[160];
                snprintf(msg, sizeof msg, "nested BEGIN SOLUTION: expected END SOLUTION first for the region "
                         "opened at line %d", begin_line.number);
                return fail(p, &l, msg);
            }
            if (kind == LINE_STUB) return fail(p, &l, "STUB inside a solution region; expected it right after "
                                                      "the END SOLUTION marker");
            in_region = kind != LINE_END;
            after_end = kind == LINE_END;
            continue;
        }
        if (kind == LINE_END) return fail(p, &l, "END SOLUTION without a BEGIN SOLUTION before it");
        if (kind == LINE_STUB) {
            if (!after_end) return fail(p, &l, "STUB not directly after an END SOLUTION marker; expected it on "
                                               "the line right after the region it replaces");
            const char *code;
            size_t n;
            stub_code(&l, &code, &n);
            if (n == 0) return fail(p, &l, "empty STUB; expected `" MARK_STUB " <code> */`");
            emit(p, l.text, indent_of(&l));
            emit(p, code, n);
        } else if (kind == LINE_BEGIN) {
            in_region = true;
            begin_line = l;
        } else if (after_end && last_blank && indent_of(&l) == l.len) {
            /* A region removed whole (no STUB) leaves one blank line between its neighbours, not two. */
            after_end = false;
            continue;
        } else {
            emit(p, l.text, l.len);
        }
        if (kind != LINE_BEGIN) {
            emit(p, l.eol, l.eol_len);
            last_blank = kind != LINE_STUB && indent_of(&l) == l.len;
        }
        after_end = false;
    }
    if (in_region) return fail(p, &begin_line, "BEGIN SOLUTION never closed; expected END SOLUTION before the "
                                              "end of the file");
    if (after_end && begin_depth > 0) return stubless_in_body(p, &begin_line);
    if (p->banners && st != TASK_NONE && st != TASK_DONE) {
        line l = {0};
        l.number = p->current.line;
        return fail(p, &l, "banner without a solution region and STUB; expected both in the function's body");
    }
    return PL_OK;
}

pl_status strip_text(const char *in, size_t len, const char *name, char **out, pl_diag *diag)
{
    pass p = {name, diag, NULL, 0, false, NULL, 0, 0, {0}};
    if (out) {
        /* A stub is shorter than its line and markers vanish: the result never outgrows the input. */
        p.out = malloc(len + 1);
        if (!p.out) return pl_fail(diag, PL_ERR_NOMEM, "%s: out of memory", name);
    }
    pl_status s = run(&p, in, len);
    if (s != PL_OK) {
        free(p.out);
        return s;
    }
    if (out) {
        p.out[p.out_len] = '\0';
        *out = p.out;
    }
    return PL_OK;
}

pl_status strip_tasks(const char *in, size_t len, const char *name, strip_task **tasks, int *num_tasks,
                      pl_diag *diag)
{
    pass p = {name, diag, NULL, 0, true, NULL, 0, 0, {0}};
    pl_status s = run(&p, in, len);
    if (s != PL_OK) {
        free(p.tasks);
        return s;
    }
    *tasks = p.tasks;
    *num_tasks = p.num_tasks;
    return PL_OK;
}
