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

/* Element walking that skips text, comments and processing instructions, and takes NULL anywhere:
 * dae_child(dae_child(a, "b"), "c") is NULL when any step is missing, so callers test once. */
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

/* CS184's extensions: <extra><technique profile="CGL"> under the element they extend. */
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

/* "scene.dae:212: <polylist>: " and then the message: every loader message names file, line and
 * element. */
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

/* One warning per kind per file: a mesh of a million unsupported lines warns once, at the first. */
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
/* An open-addressing hash table of every element with an id, keyed by (id, element name), built
 * once per file: each url="#id" reference resolves in constant time, however large the file. */

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

/* Sized to at most half full (a power of two, so the probe masks), then filled; a duplicate id is
 * refused with both lines. */
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

/* Only references inside the file ("#id"): a scene never names another file or a URL. */
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

/* The offending token, cut at 32 characters so a megabyte of junk makes a one-line message. */
static pl_status bad_token(dae_ctx *c, const xmlNode *n, const char *what, const char *tok, const char *end)
{
    int len = (int)(end - tok);
    return dae_error(c, n, PL_ERR_PARSE, "expected %s, found '%.*s%s'", what, len > 32 ? 32 : len, tok,
                     len > 32 ? "..." : "");
}

/* Clinger's fast path: a decimal of at most 7 digits' worth (m < 2^24) with at most 10 digits after
 * the point is m / 10^k with m and 10^k both exact floats, and IEEE division rounds that quotient
 * correctly: the same float strtof returns, at a fraction of its cost. Exported meshes are almost
 * all such numbers ("0.0187232"). scan_float parses one at s while scanning it and returns where it
 * ends (at a blank or the text's end), or NULL for anything else (exponents, long mantissas, junk),
 * which parse_float then reads with strtof or refuses. */
static const char *scan_float(const char *s, float *out)
{
    static const float pow10[11] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
    bool negative = *s == '-';
    if (*s == '-' || *s == '+') s++;
    uint32_t m = 0;
    int digits = 0, decimals = 0;
    for (; *s >= '0' && *s <= '9'; s++, digits++)
        if ((m = m * 10 + (uint32_t)(*s - '0')) >= (1u << 24)) return NULL;
    if (*s == '.')
        for (s++; *s >= '0' && *s <= '9'; s++, digits++, decimals++)
            if ((m = m * 10 + (uint32_t)(*s - '0')) >= (1u << 24)) return NULL;
    if (digits == 0 || decimals > 10 || (*s && !is_space(*s))) return NULL;
    float v = (float)m / pow10[decimals];
    *out = negative ? -v : v;
    return s;
}

/* An index: a plain digit string up to INT_MAX, parsed while scanned (no strtol locale or sign
 * machinery); NULL for anything else, which the caller refuses naming the token. */
static const char *scan_index(const char *s, int *out)
{
    long x = 0;
    const char *start = s;
    for (; *s >= '0' && *s <= '9'; s++)
        if ((x = x * 10 + (*s - '0')) > INT_MAX) return NULL;
    if (s == start || (*s && !is_space(*s))) return NULL;
    *out = (int)x;
    return s;
}

static pl_status parse_float(dae_ctx *c, const xmlNode *n, const char *tok, const char *end, float *out)
{
    char *stop;
    errno = 0;
    float v = strtof(tok, &stop);
    /* ERANGE on underflow still yields a usable (tiny) value; only overflow is rejected below. */
    if (stop != end || !isfinite(v)) return bad_token(c, n, "a finite number", tok, end);
    *out = v;
    return PL_OK;
}

/* ---- number lists ---------------------------------------------------------------------------
 * Every list of numbers in a scene (vertex arrays, index lists, matrices, colours) is read by one
 * loop, read_numbers. It walks the element's text once, parses each token in place, and reads at
 * most one number past `max`, the count the file declares or the caller's array holds: a list that
 * lies about its length is refused after one extra number, never read to its end. The output is
 * sized once, from what the text can hold (a number and its separator take two characters) and
 * from max, so a 3 MB mesh is one allocation rather than twenty reallocations and copies. */

/* Reads the numbers of n's text, floats or (ints) non-negative indices, into `into` (room for max)
 * or, when into is NULL, a new array in *grown (free with free()). *count is how many were read;
 * max + 1 means "more than max" (that one is not stored). max < 0: no limit but the text's length. */
static pl_status read_numbers(dae_ctx *c, const xmlNode *n, bool ints, int max, void *into, void **grown,
                              int *count)
{
    xmlChar *copy;
    const char *s = text_of(n, &copy);
    size_t room = strlen(s) / 2 + 1;
    if (room > INT_MAX) room = INT_MAX;
    if (max >= 0 && (size_t)max < room) room = (size_t)max;
    void *v = into;
    if (!v && !(v = malloc((room ? room : 1) * sizeof(float)))) {  /* float and int: 4 bytes each */
        xmlFree(copy);
        return pl_fail(c->diag, PL_ERR_NOMEM, "%s: out of memory", c->name);
    }
    float *fv = v;
    int *iv = v;
    size_t k = 0;
    pl_status st = PL_OK;
    for (;;) {
        while (is_space(*s)) s++;
        if (!*s) break;
        if (k == room) {  /* one number more than the list may hold: stop reading here */
            k++;
            break;
        }
        /* The common token is parsed while it is scanned; anything else is found whole and read
         * (or refused) by the careful path. */
        const char *tok = s, *fast = ints ? scan_index(s, &iv[k]) : scan_float(s, &fv[k]);
        if (fast) {
            s = fast;
            k++;
            continue;
        }
        while (*s && !is_space(*s)) s++;
        if (ints) st = bad_token(c, n, "a non-negative integer", tok, s);
        else st = parse_float(c, n, tok, s, &fv[k]);
        if (st) break;
        k++;
    }
    xmlFree(copy);
    if (!into) {
        if (st) {
            free(v);
            v = NULL;
        }
        *grown = v;
    }
    *count = st ? 0 : (int)k;
    return st;
}

/* ---- the readers the modules call ---------------------------------------------------------------- */

/* Exactly `want` numbers (or `want_alt`: an rgb or rgba colour) into a fixed array. */
pl_status dae_floats(dae_ctx *c, const xmlNode *n, float *out, int want, int want_alt, int *found)
{
    int k, cap = want > want_alt ? want : want_alt;
    pl_status st = read_numbers(c, n, false, cap, out, NULL, &k);
    if (found) *found = k;
    if (st) return st;
    if (k == want || (want_alt > 0 && k == want_alt)) return PL_OK;
    char got[32];
    if (k > cap) snprintf(got, sizeof got, "more");
    else snprintf(got, sizeof got, "%d", k);
    if (want_alt > 0)
        return dae_error(c, n, PL_ERR_PARSE, "expected %d or %d numbers, found %s", want, want_alt, got);
    return dae_error(c, n, PL_ERR_PARSE, "expected %d number%s, found %s", want, want == 1 ? "" : "s", got);
}

pl_status dae_doubles(dae_ctx *c, const xmlNode *n, double *out, int want)
{
    xmlChar *copy;
    const char *s = text_of(n, &copy);
    int k = 0;
    pl_status st = PL_OK;
    for (;;) {
        while (is_space(*s)) s++;
        if (!*s || k > want) break;
        const char *tok = s;
        while (*s && !is_space(*s)) s++;
        char *stop;
        double v = strtod(tok, &stop);
        if (stop != s || !isfinite(v)) {
            st = bad_token(c, n, "a finite number", tok, s);
            break;
        }
        if (k < want) out[k] = v;
        k++;
    }
    xmlFree(copy);
    if (st) return st;
    if (k == want) return PL_OK;
    return dae_error(c, n, PL_ERR_PARSE, "expected %d number%s, found %s%d", want, want == 1 ? "" : "s",
                     k > want ? "more than " : "", k > want ? want : k);
}

pl_status dae_float_list(dae_ctx *c, const xmlNode *n, int max, float **out, int *count)
{
    void *v;
    pl_status st = read_numbers(c, n, false, max, NULL, &v, count);
    *out = v;
    return st;
}

pl_status dae_int_list(dae_ctx *c, const xmlNode *n, int max, int **out, int *count)
{
    void *v;
    pl_status st = read_numbers(c, n, true, max, NULL, &v, count);
    *out = v;
    return st;
}

pl_status dae_child_float(dae_ctx *c, const xmlNode *parent, const char *name, float def, float *out)
{
    const xmlNode *n = dae_child(parent, name);
    *out = def;
    return n ? dae_floats(c, n, out, 1, 0, NULL) : PL_OK;
}

/* An integer attribute (count, stride, offset): whole text, no overflow, at least min. */
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

/* A colour is radiance or reflectance: rgb, with an alpha that is read and ignored; never negative. */
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

/* Asked before a list's primitives are made, so the cap refuses the memory before it is spent. */
pl_status dae_check_room(dae_ctx *c, const xmlNode *at, long more)
{
    long have = (long)c->out->num_triangles + c->out->num_spheres;
    if (more <= c->limits.max_primitives - have) return PL_OK;
    return dae_error(c, at, PL_ERR_INVALID,
                     "the scene would hold more than %ld primitives (%ld so far, %ld more here): "
                     "the limit guards memory; --max-primitives N raises it", c->limits.max_primitives, have, more);
}
