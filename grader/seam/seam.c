/* Grader machinery: not part of any assignment. What the subject and the judge share (seam.h): the
 * table of part functions and the hash of a call's inputs. */
#include "seam.h"
#include "../../tests/common/test.h"
#include "../../framework/render.h"
#include <string.h>

/* Names and tasks from the seam's one list (framework/seam.h), in seam_fn's order. */
static const struct { const char *name, *task; } functions[SEAM_NUM_FUNCTIONS] = {
#define SEAM_FN_ROW(name, task) {#name, task},
    PL_SEAM_PART_FUNCTIONS(SEAM_FN_ROW)
#undef SEAM_FN_ROW
};

const char *seam_fn_name(int fn) { return fn >= 0 && fn < SEAM_NUM_FUNCTIONS ? functions[fn].name : "?"; }
const char *seam_fn_task(int fn) { return fn >= 0 && fn < SEAM_NUM_FUNCTIONS ? functions[fn].task : "?"; }

int seam_fn_from_todo(const char *text)
{
    /* todo.c writes "Part 3, task 3.4: direct_hemisphere()": the name sits between ": " and "(". */
    const char *name = text ? strstr(text, ": ") : NULL;
    if (!name) return -1;
    name += 2;
    size_t len = strcspn(name, "(");
    for (int fn = 0; fn < SEAM_NUM_FUNCTIONS; fn++)
        if (strlen(functions[fn].name) == len && !strncmp(functions[fn].name, name, len)) return fn;
    return -1;
}

/* FNV-1a over the bytes: the hash only tells the judge that a record answers the call it makes (a
 * subject that lies can send any outputs anyway), so it need not resist a forger. */
uint64_t seam_hash(uint64_t h, const void *data, size_t size)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < size; i++) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

uint64_t seam_hash_int(uint64_t h, int64_t v) { return seam_hash(h, &v, sizeof v); }

/* The structs below are hashed whole only where they have no padding. */
_Static_assert(sizeof(ray) == 9 * 4 && sizeof(hit) == 19 * 4 && sizeof(mat4) == 16 * 4, "padding in ray, hit or mat4");

uint64_t seam_hash_camera(uint64_t h, const camera *c)
{
    if (!c) return seam_hash_int(h, -1);
    float f[] = {c->position.x, c->position.y, c->position.z, c->hfov, c->vfov, c->znear, c->zfar,
                 c->lens_radius, c->focal_distance};
    h = SEAM_HASH(h, c->camera_to_world);
    return seam_hash_int(SEAM_HASH(h, f), c->fov_is_vertical);
}

uint64_t seam_hash_ray(uint64_t h, const ray *r) { return r ? SEAM_HASH(h, *r) : seam_hash_int(h, -1); }
uint64_t seam_hash_hit(uint64_t h, const hit *x) { return x ? SEAM_HASH(h, *x) : seam_hash_int(h, -1); }
uint64_t seam_hash_rng(uint64_t h, const rng *g) { return g ? SEAM_HASH(h, *g) : seam_hash_int(h, -1); }

uint64_t seam_hash_material(uint64_t h, const material *m)
{
    if (!m) return seam_hash_int(h, -1);
    float f[] = {m->albedo.r, m->albedo.g, m->albedo.b, m->Le.r, m->Le.g, m->Le.b, m->reflectance.r,
                 m->reflectance.g, m->reflectance.b, m->transmittance.r, m->transmittance.g, m->transmittance.b,
                 m->ior, m->alpha, m->eta.r, m->eta.g, m->eta.b, m->k.r, m->k.g, m->k.b};
    return SEAM_HASH(seam_hash_int(h, m->kind), f);
}

uint64_t seam_hash_bsdf(const material *m, vec3 wo, vec3 wi)
{
    return SEAM_HASH(SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo), wi);
}

uint64_t seam_hash_bsdf_sample(const material *m, vec3 wo, const vec2 *u, const vec3 *wi, const float *pdf)
{
    uint64_t h = SEAM_HASH(seam_hash_material(SEAM_HASH_START, m), wo);
    if (u) h = SEAM_HASH(h, *u);
    return seam_hash_int(h, (wi != NULL) * 2 + (pdf != NULL));
}

uint64_t seam_hash_scene(uint64_t h, const scene *s)
{
    if (!s) return seam_hash_int(h, -1);
    int64_t n[] = {s->num_triangles, s->num_spheres, s->num_materials, s->num_lights};
    return SEAM_HASH(h, n);
}

uint64_t seam_hash_bvh(uint64_t h, const bvh *b)
{
    if (!b) return seam_hash_int(h, -1);
    int64_t n[] = {b->num_nodes, b->num_prims};
    return SEAM_HASH(h, n);
}

uint64_t seam_hash_ctx(uint64_t h, const struct render_ctx *ctx)
{
    if (!ctx) return seam_hash_int(h, -1);
    const options *o = ctx->opts;
    int64_t n[] = {ctx->width, ctx->height, ctx->sample_begin, ctx->sample_end,
                   o ? o->max_depth : -1, o ? o->light_samples : -1, o ? o->accumulate : -1,
                   o ? o->hemisphere : -1, o ? o->no_roulette : -1, o ? (int64_t)o->seed : -1};
    return seam_hash_scene(SEAM_HASH(h, n), ctx->scene);
}

/* Both split binaries run their tests single-threaded (check.h). */
__attribute__((constructor)) static void seam_split_mode(void) { pl_test_split = true; }
