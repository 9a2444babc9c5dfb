/* Grader machinery: not part of any assignment. Part 8's functions across the split (seam.h; see
 * seam_part1.c for the pattern). A call depends on the whole map (and tables): both are hashed in
 * full, texel by texel. env_build_distribution's record carries the tables it filled, which the
 * judge copies into the caller's (the framework allocated them, at the map's size). */
#include "seam.h"
#include "../../parts/part8_envlight/part8.h"
#include <string.h>


static uint64_t map_hash(const envmap *e)
{
    if (!e) return seam_hash_int(SEAM_HASH_START, -1);
    uint64_t h = seam_hash_int(seam_hash_int(SEAM_HASH_START, e->width), e->height);
    return e->texels ? seam_hash(h, e->texels, (size_t)e->width * e->height * sizeof *e->texels) : h;
}

/* The tables' sizes, from the map they belong to (NULL: none). */
static size_t marginal_size(const envmap *e) { return e ? ((size_t)e->height + 1) * sizeof(float) : 0; }
static size_t conditional_size(const envmap *e) { return e ? (size_t)e->height * ((size_t)e->width + 1) * sizeof(float) : 0; }

static uint64_t tables_hash(uint64_t h, const envmap *e, const env_distribution *d)
{
    if (!d || !e || !d->marginal_cdf || !d->conditional_cdf) return seam_hash_int(h, -1);
    h = seam_hash(h, d->marginal_cdf, marginal_size(e));
    return seam_hash(h, d->conditional_cdf, conditional_size(e));
}

static uint64_t sample_inputs(const envmap *e, const env_distribution *d, vec2 u, const vec3 *wi, const float *pdf)
{
    uint64_t h = SEAM_HASH(tables_hash(map_hash(e), e, d), u);
    return seam_hash_int(h, (wi != NULL) * 2 + (pdf != NULL));
}

static uint64_t pdf_inputs(const envmap *e, const env_distribution *d, vec3 wi)
{
    return SEAM_HASH(tables_hash(map_hash(e), e, d), wi);
}

/* The density answers with its value (see SEAM_FIXED in seam.h). */
SEAM_FIXED(float, float, env_pdf, (const envmap *e, const env_distribution *d, vec3 wi), (e, d, wi), pdf_inputs(e, d, wi), NULL)

/* The two samplers also fill *wi and *pdf: the answer is the three together (SEAM_SAMPLER). */
SEAM_SAMPLER(env_sample_uniform, (const envmap *e, vec2 u, vec3 *wi, float *pdf), (e, u, wi, pdf),
             sample_inputs(e, NULL, u, wi, pdf))
SEAM_SAMPLER(env_sample_importance, (const envmap *e, const env_distribution *d, vec2 u, vec3 *wi, float *pdf),
             (e, d, u, wi, pdf), sample_inputs(e, d, u, wi, pdf))

#ifdef PL_SEAM_SUBJECT
void __real_env_build_distribution(const envmap *e, env_distribution *d);
void __wrap_env_build_distribution(const envmap *e, env_distribution *d);

/* The tables go back whole: the two arrays, at the sizes the map gives them. */
void __wrap_env_build_distribution(const envmap *e, env_distribution *d)
{
    seam_call call;
    uint64_t in = map_hash(e);
    if (!seam_begin(&call)) {
        __real_env_build_distribution(e, d);
        return;
    }
    __real_env_build_distribution(e, d);
    bool sent = e && d && d->marginal_cdf && d->conditional_cdf;
    int32_t head = sent;
    const void *arrays[] = {sent ? d->marginal_cdf : NULL, sent ? d->conditional_cdf : NULL};
    size_t sizes[] = {sent ? marginal_size(e) : 0, sent ? conditional_size(e) : 0};
    seam_end(&call, SEAM_env_build_distribution, in, NULL, &head, sizeof head, arrays, sizes, 2);
}
#endif

#ifdef PL_SEAM_JUDGE
/* The tables, of exactly the sizes the map gives them (the record is sized before it is read). */
void env_build_distribution(const envmap *e, env_distribution *d)
{
    size_t m = marginal_size(e), c = conditional_size(e), size;
    int32_t head;
    const unsigned char *p = seam_replay(SEAM_env_build_distribution, map_hash(e), NULL, sizeof head + m + c, &size);
    if (size < sizeof head) seam_fail(SEAM_env_build_distribution, "its answer is shorter than its header");
    memcpy(&head, p, sizeof head);
    if (!head) return;
    if (size != sizeof head + m + c || !d || !d->marginal_cdf || !d->conditional_cdf)
        seam_fail(SEAM_env_build_distribution, "it sent tables of another size than the map's");
    memcpy(d->marginal_cdf, p + sizeof head, m);
    memcpy(d->conditional_cdf, p + sizeof head + m, c);
}
#endif
