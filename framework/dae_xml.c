/* COLLADA loader, part 1 of 5: element helpers, the id index, numbers, located messages.
 * Numbers are read straight from the text nodes libxml2 built, in one pass, so a large mesh costs
 * time linear in its size. */
#include "dae_internal.h"
#include "buf.h"

#include <errno.h>
#include <math.h>
#include <limits.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- elements ---------------------------------------------------------------------------- */

bool dae_is(const xmlNode *n, const char *name)
{
    return n && n->type == XML_ELEMENT_NODE && strcmp((const char *)n->name, name) == 0;
}

const char *dae_name(const xmlNode *n) { return n ? (const char *)n->name : "?"; }

static xmlNode *element_from(xmlNode *n)
{
    while (n && n->type != XML_ELEMENT_NODE) n = n->next;
    return n;
}

xmlNode *dae_first(const xmlNode *parent) { return parent ? element_from(parent->children) : NULL; }
xmlNode *dae_next(const xmlNode *n) { return n ? element_from(n->next) : NULL; }

xmlNode *dae_child(const xmlNode *parent, const char *name)
{
    for (xmlNode *c = dae_first(parent); c; c = dae_next(c))
        if (dae_is(c, name)) return c;
    return NULL;
}

const char *dae_attr(const xmlNode *n, const char *name)
{
    if (!n || n->type != XML_ELEMENT_NODE) return NULL;
    for (const xmlAttr *a = n->properties; a; a = a->next) {
        if (strcmp((const char *)a->name, name) != 0) continue;
        /* Without entity substitution a value is a single text child (or none when empty). */
        const xmlNode *t = a->children;
        return (t && t->type == XML_TEXT_NODE && t->content) ? (const char *)t->content : "";
    }
    return NULL;
}

long dae_line(const xmlNode *n)
{
    if (!n) return 0;
    /* dae.c stores every element's exact line here while parsing (libxml2's saturates at 65535) */
    if (n->type == XML_ELEMENT_NODE && n->_private) return (long)(intptr_t)n->_private;
    return xmlGetLineNo(n);
}

xmlNode *dae_cgl_technique(const xmlNode *parent)
{
    for (xmlNode *e = dae_first(parent); e; e = dae_next(e)) {
        if (!dae_is(e, "extra")) continue;
        for (xmlNode *t = dae_first(e); t; t = dae_next(t)) {
            const char *profile = dae_attr(t, "profile");
            if (dae_is(t, "technique") && profile && strcmp(profile, "CGL") == 0) return t;
        }
    }
    return NULL;
}

/* ---- messages ---------------------------------------------------------------------------- */

static void locate(char *buf, size_t size, dae_ctx *c, const xmlNode *at, const char *fmt, va_list ap)
{
    int n = snprintf(buf, size, "%s:%ld: <%s>: ", c->name, dae_line(at), dae_name(at));
    if (n >= 0 && (size_t)n < size) vsnprintf(buf + n, size - (size_t)n, fmt, ap);
}

pl_status dae_error(dae_ctx *c, const xmlNode *at, pl_status status, const char *fmt, ...)
{
    char msg[PL_DIAG_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    locate(msg, sizeof msg, c, at, fmt, ap);
    va_end(ap);
    return pl_fail(c->diag, status, "%s", msg);
}

void dae_warn_once(dae_ctx *c, const xmlNode *at, const char *kind, const char *fmt, ...)
{
    for (int i = 0; i < c->num_warned; i++)
        if (strcmp(c->warned[i], kind) == 0) return;
    if (c->num_warned < DAE_MAX_WARN_KINDS) c->warned[c->num_warned++] = kind;
    char msg[PL_DIAG_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    locate(msg, sizeof msg, c, at, fmt, ap);
    va_end(ap);
    pl_warn(c->diag, "%s", msg);
}

/* ---- ids --------------------------------------------------------------------------------- */

static size_t hash_id(const char *s)
{
    size_t h = 1469598103934665603u;  /* FNV-1a */
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211u;
    return h;
}

/* The slot holding (id, element), or the empty slot where it would go. */
static dae_entry *probe(const dae_index *ix, const char *id, const char *element)
{
    size_t mask = ix->capacity - 1;
    for (size_t i = hash_id(id) & mask;; i = (i + 1) & mask) {
        dae_entry *e = &ix->slots[i];
        if (!e->node || (strcmp(e->id, id) == 0 && dae_is(e->node, element))) return e;
    }
}

static size_t count_ids(const xmlNode *n)
{
    size_t count = 0;
    for (const xmlNode *c = n; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE) continue;
        if (dae_attr(c, "id")) count++;
        count += count_ids(c->children);  /* depth is bounded by libxml2's nesting limit */
    }
    return count;
}

static pl_status insert_ids(dae_ctx *c, xmlNode *n)
{
    for (xmlNode *e = n; e; e = e->next) {
        if (e->type != XML_ELEMENT_NODE) continue;
        const char *id = dae_attr(e, "id");
        if (id) {
            dae_entry *slot = probe(&c->index, id, dae_name(e));
            if (slot->node)
                return dae_error(c, e, PL_ERR_PARSE, "duplicate id '%s' (first used at line %ld)", id,
                                 dae_line(slot->node));
            slot->id = id;
            slot->node = e;
            slot->material = -1;
        }
        pl_status st = insert_ids(c, e->children);
        if (st) return st;
    }
    return PL_OK;
}

pl_status dae_index_build(dae_ctx *c)
{
    xmlNode *root = xmlDocGetRootElement(c->doc);
    size_t capacity = 16;
    while (capacity < 2 * count_ids(root) + 1) capacity *= 2;
    c->index.slots = calloc(capacity, sizeof *c->index.slots);
    if (!c->index.slots) return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    c->index.capacity = capacity;
    return insert_ids(c, root);
}

void dae_index_free(dae_index *ix)
{
    for (size_t i = 0; i < ix->capacity; i++) free(ix->slots[i].floats);
    free(ix->slots);
    ix->slots = NULL;
    ix->capacity = 0;
}

dae_entry *dae_index_find(const dae_index *ix, const char *id, const char *element)
{
    if (!ix->slots) return NULL;
    dae_entry *e = probe(ix, id, element);
    return e->node ? e : NULL;
}

pl_status dae_resolve(dae_ctx *c, const xmlNode *at, const char *attr, const char *element,
                      dae_entry **out)
{
    const char *url = dae_attr(at, attr);
    *out = NULL;
    if (!url) return dae_error(c, at, PL_ERR_PARSE, "expected a %s attribute naming a <%s>", attr, element);
    if (url[0] != '#')
        return dae_error(c, at, PL_ERR_PARSE, "%s '%.200s': expected a reference within the file ('#id')",
                         attr, url);
    *out = dae_index_find(&c->index, url + 1, element);
    if (!*out) return dae_error(c, at, PL_ERR_PARSE, "%s '%.200s' names no <%s>", attr, url, element);
    return PL_OK;
}

/* ---- numbers ----------------------------------------------------------------------------- */

static bool is_space(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; }

/* The element's text. Usually a single text node read in place; otherwise a copy in *copy. */
static const char *text_of(const xmlNode *n, xmlChar **copy)
{
    *copy = NULL;
    const xmlNode *t = n->children;
    if (!t) return "";
    if (!t->next && t->type == XML_TEXT_NODE) return t->content ? (const char *)t->content : "";
    *copy = xmlNodeGetContent(n);
    return *copy ? (const char *)*copy : "";
}

/* Calls take(user, token, end) for each whitespace-separated token of n's text, stopping at the
 * first non-OK status. The tokenizer is shared by every number reader. */
typedef pl_status (*token_fn)(dae_ctx *c, const xmlNode *n, void *user, const char *tok, const char *end);

static pl_status for_each_token(dae_ctx *c, const xmlNode *n, token_fn take, void *user)
{
    xmlChar *copy;
    const char *s = text_of(n, &copy);
    pl_status st = PL_OK;
    while (st == PL_OK) {
        while (is_space(*s)) s++;
        if (!*s) break;
        const char *end = s;
        while (*end && !is_space(*end)) end++;
        st = take(c, n, user, s, end);
        s = end;
    }
    xmlFree(copy);
    return st;
}

static pl_status bad_token(dae_ctx *c, const xmlNode *n, const char *what, const char *tok, const char *end)
{
    int len = (int)(end - tok);
    return dae_error(c, n, PL_ERR_PARSE, "expected %s, found '%.*s%s'", what, len > 32 ? 32 : len, tok,
                     len > 32 ? "..." : "");
}

/* Clinger's fast path: a decimal of at most 7 digits' worth (m < 2^24) with at most 10 digits after
 * the point is m / 10^k with m and 10^k both exact floats, and IEEE division rounds that quotient
 * correctly: the same float strtof returns, at a fraction of its cost. Exported meshes are almost
 * all such numbers ("0.0187232"); anything else (exponents, long mantissas) goes to strtof. */
static bool parse_float_fast(const char *tok, const char *end, float *out)
{
    static const float pow10[11] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
    const char *q = tok;
    bool negative = q < end && *q == '-';
    if (q < end && (*q == '-' || *q == '+')) q++;
    uint32_t m = 0;
    int decimals = 0, digits = 0;
    bool point = false;
    for (; q < end; q++) {
        if (*q == '.' && !point) {
            point = true;
            continue;
        }
        if (*q < '0' || *q > '9') return false;
        m = m * 10 + (uint32_t)(*q - '0');
        if (m >= (1u << 24)) return false;
        decimals += point;
        digits++;
    }
    if (digits == 0 || decimals > 10) return false;
    float v = (float)m / pow10[decimals];
    *out = negative ? -v : v;
    return true;
}

static pl_status parse_float(dae_ctx *c, const xmlNode *n, const char *tok, const char *end, float *out)
{
    if (parse_float_fast(tok, end, out)) return PL_OK;
    char *stop;
    errno = 0;
    float v = strtof(tok, &stop);
    /* ERANGE on underflow still yields a usable (tiny) value; only overflow is rejected below. */
    if (stop != end || !isfinite(v)) return bad_token(c, n, "a finite number", tok, end);
    *out = v;
    return PL_OK;
}

/* Where numbers go: a caller's fixed array (want or want_alt numbers) or a growing one. */
typedef struct { float *v; int count, cap; bool grow; int want, want_alt; } float_sink;

static pl_status too_many(dae_ctx *c, const xmlNode *n, const float_sink *s)
{
    if (s->want_alt > 0)
        return dae_error(c, n, PL_ERR_PARSE, "expected %d or %d numbers, found more", s->want, s->want_alt);
    return dae_error(c, n, PL_ERR_PARSE, "expected %d number%s, found more", s->want, s->want == 1 ? "" : "s");
}

static pl_status take_float(dae_ctx *c, const xmlNode *n, void *user, const char *tok, const char *end)
{
    float_sink *s = user;
    float v = 0.0f;
    pl_status st = parse_float(c, n, tok, end, &v);
    if (st) return st;
    /* A fixed array is full: one number more is already an error, so reading stops here and
     * nothing is ever written past the caller's array. Otherwise the number goes into the fixed
     * array's room, or the growing list grows (buf.h). */
    if (!s->grow && s->count >= s->cap) return too_many(c, n, s);
    if (buf_append(&s->v, &s->count, &s->cap, sizeof v, &v) < 0)
        return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return PL_OK;
}

pl_status dae_floats(dae_ctx *c, const xmlNode *n, float *out, int want, int want_alt, int *found)
{
    float_sink s = {out, 0, want > want_alt ? want : want_alt, false, want, want_alt};
    pl_status st = for_each_token(c, n, take_float, &s);
    if (found) *found = s.count;
    if (st) return st;
    if (s.count == want || (want_alt > 0 && s.count == want_alt)) return PL_OK;
    if (want_alt > 0)
        return dae_error(c, n, PL_ERR_PARSE, "expected %d or %d numbers, found %d", want, want_alt, s.count);
    return dae_error(c, n, PL_ERR_PARSE, "expected %d number%s, found %d", want, want == 1 ? "" : "s", s.count);
}

pl_status dae_float_list(dae_ctx *c, const xmlNode *n, float **out, int *count)
{
    float_sink s = {NULL, 0, 0, true, 0, 0};
    pl_status st = for_each_token(c, n, take_float, &s);
    if (st) { free(s.v); s.v = NULL; s.count = 0; }
    *out = s.v;
    *count = s.count;
    return st;
}

typedef struct { int *v; int count, cap; } int_sink;

static pl_status take_int(dae_ctx *c, const xmlNode *n, void *user, const char *tok, const char *end)
{
    int_sink *s = user;
    /* Indices are plain digit strings: read them without strtol's locale and sign machinery. */
    long v = 0;
    for (const char *q = tok; q < end; q++) {
        if (*q < '0' || *q > '9' || v > INT_MAX / 10) return bad_token(c, n, "a non-negative integer", tok, end);
        v = v * 10 + (*q - '0');
    }
    if (v > INT_MAX) return bad_token(c, n, "a non-negative integer", tok, end);
    int index = (int)v;
    if (buf_append(&s->v, &s->count, &s->cap, sizeof index, &index) < 0)
        return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    return PL_OK;
}

pl_status dae_int_list(dae_ctx *c, const xmlNode *n, int **out, int *count)
{
    int_sink s = {NULL, 0, 0};
    pl_status st = for_each_token(c, n, take_int, &s);
    if (st) { free(s.v); s.v = NULL; s.count = 0; }
    *out = s.v;
    *count = s.count;
    return st;
}

pl_status dae_child_float(dae_ctx *c, const xmlNode *parent, const char *name, float def, float *out)
{
    const xmlNode *n = dae_child(parent, name);
    *out = def;
    return n ? dae_floats(c, n, out, 1, 0, NULL) : PL_OK;
}

pl_status dae_attr_int(dae_ctx *c, const xmlNode *n, const char *name, bool required, int def,
                       int min, int *out)
{
    const char *s = dae_attr(n, name);
    *out = def;
    if (!s) {
        if (required) return dae_error(c, n, PL_ERR_PARSE, "expected an attribute '%s'", name);
        return PL_OK;
    }
    char *stop;
    errno = 0;
    long v = strtol(s, &stop, 10);
    while (is_space(*stop)) stop++;
    if (stop == s || *stop || errno == ERANGE || v < min || v > INT_MAX)
        return dae_error(c, n, PL_ERR_PARSE, "expected %s to be an integer >= %d, found '%.32s'", name,
                         min, s);
    *out = (int)v;
    return PL_OK;
}

pl_status dae_color(dae_ctx *c, const xmlNode *n, rgb *out)
{
    float v[4];
    pl_status st = dae_floats(c, n, v, 3, 4, NULL);
    if (st) return st;
    if (v[0] < 0 || v[1] < 0 || v[2] < 0)
        return dae_error(c, n, PL_ERR_INVALID, "expected non-negative colour components, found %g %g %g",
                         v[0], v[1], v[2]);
    *out = rgb_make(v[0], v[1], v[2]);
    return PL_OK;
}

pl_status dae_child_color(dae_ctx *c, const xmlNode *parent, const char *name, bool required, rgb *out)
{
    const xmlNode *n = dae_child(parent, name);
    if (!n) {
        if (required) return dae_error(c, parent, PL_ERR_PARSE, "expected a <%s> child", name);
        return PL_OK;
    }
    /* profile_COMMON wraps colours (<diffuse><color>); CGL writes them inline (<radiance>1 1 1). */
    const xmlNode *inner = dae_child(n, "color");
    return dae_color(c, inner ? inner : n, out);
}

/* ---- limits ------------------------------------------------------------------------------ */

pl_status dae_check_coord(dae_ctx *c, const xmlNode *at, const char *what, vec3 p)
{
    bool ok = fabsf(p.x) <= DAE_MAX_COORD && fabsf(p.y) <= DAE_MAX_COORD && fabsf(p.z) <= DAE_MAX_COORD;
    if (ok) return PL_OK;  /* NaN fails every comparison, so it lands below too */
    return dae_error(c, at, PL_ERR_INVALID,
                     "%s is (%g, %g, %g) in world space: expected finite coordinates within +-%g "
                     "(check the node transforms above it)", what, p.x, p.y, p.z, DAE_MAX_COORD);
}

pl_status dae_check_room(dae_ctx *c, const xmlNode *at, long more)
{
    long have = (long)c->out->num_triangles + c->out->num_spheres;
    if (more <= c->limits.max_primitives - have) return PL_OK;
    return dae_error(c, at, PL_ERR_INVALID,
                     "the scene would hold more than %ld primitives (%ld so far, %ld more here): "
                     "the limit guards memory; --max-primitives N raises it", c->limits.max_primitives, have, more);
}
