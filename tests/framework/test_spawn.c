/* Test machinery: not part of any assignment.
 * Leaving a surface (framework/spawn.c): a ray spawned from a hit never hits its own primitive
 * again, for a million random hits on spheres and triangles from 1e-3 to 1e3 in size, placed up
 * to 1e4 from the origin, leaving at random angles down to 89.9 degrees from the normal; a shadow
 * ray towards an area light sample stops short of the emissive quad at the light but not of an
 * occluder before it, and one towards a point or spot light inside a quad through it stops short
 * of that quad (at angles above SPAWN_GRAZING_SIN to it) but not of an occluder. Both are exact counts (no statistics); the seed is fixed and printed
 * (PL_TEST_SEED changes it). Each test also counts what rays from the raw hit point do on the
 * same hits, so a test that could not fail would show. Parts 1's intersection routines answer
 * (through scene_prim_intersect): in a tree where part 1 is a stub, the tests skip. */
#include <stdio.h>
#include <string.h>
#include "../common/test.h"
#include "../common/mc_assert.h"
#include "../../framework/spawn.h"
#include "../../framework/frame.h"
#include "../../framework/sampler.h"
#include "../../framework/todo.h"
#include "../../framework/light.h"

#define SEED mc_seed(0x5eed5a11ull)
#define HITS_PER_KIND 500000          /* spheres and triangles: a million hits in all */
#define COS_MIN 1.7453283e-3f         /* cos(89.9 degrees) */

/* 10^(lo + (hi - lo) u): sizes and distances spread evenly over their decades. */
static float log_uniform(rng *g, float lo, float hi) { return powf(10.0f, lo + (hi - lo) * rng_uniform(g)); }

/* A place up to 1e4 from the origin: a random direction at a distance from 1e-2 to 1e4. */
static vec3 random_place(rng *g) { return vec3_scale(sample_uniform_sphere(rng_uniform2(g)), log_uniform(g, -2.0f, 4.0f)); }

/* A unit direction at angle theta from n, cos(theta) in [COS_MIN, 1]: half uniform in cos, half
 * crowded towards grazing (cos log-uniform from COS_MIN to 0.1), where self-hits happen. */
static vec3 leaving_direction(rng *g, vec3 n)
{
    float c = rng_uniform(g) < 0.5f ? COS_MIN + (1.0f - COS_MIN) * rng_uniform(g) : log_uniform(g, log10f(COS_MIN), -1.0f);
    float phi = 2.0f * PL_PI * rng_uniform(g), s = sqrtf(fmaxf(0.0f, 1.0f - c * c));
    frame f = frame_from_normal(n);
    return vec3_normalize(frame_to_world(&f, vec3_make(s * cosf(phi), s * sinf(phi), c)));
}

/* A hit on one primitive as render_intersect returns it: part 1's test, then the framework's
 * point and error bound. */
static bool hit_prim(const scene *s, int prim, ray *r, hit *h)
{
    if (!scene_prim_intersect(s, prim, r, h)) return false;
    scene_hit_finish(s, NULL, r, h);
    return true;
}

typedef struct {
    long hits, spawned_self, raw_self;  /* hits made; spawned and raw rays that hit their own prim */
    char first[256];                    /* the first spawned self-hit, for the message */
} spawn_tally;

/* Leaves the hit h of r on prim along w twice: through spawn_ray, and from the raw hit point with
 * min_t = EPS_F as CS184 did. Tallies which of them hit the primitive they leave. */
static void leave_and_tally(const scene *s, int prim, const ray *r, const hit *h, vec3 w, spawn_tally *t)
{
    t->hits++;
    ray spawned = spawn_ray(r, h, w), raw = ray_make(h->p, w, EPS_F, INFINITY);
    hit again;
    if (scene_prim_intersect(s, prim, &raw, &again)) t->raw_self++;
    if (!scene_prim_intersect(s, prim, &spawned, &again)) return;
    if (t->spawned_self++ == 0)
        snprintf(t->first, sizeof t->first, "prim %d: p (%g, %g, %g), err (%g, %g, %g), leaving along (%g, %g, %g) "
                 "(cos %g to ng) hit itself at t = %g", prim, h->p.x, h->p.y, h->p.z, h->p_err.x, h->p_err.y, h->p_err.z,
                 w.x, w.y, w.z, vec3_dot(w, h->ng), again.t);
}

/* A hit on a random sphere, seen from outside, left outwards (inwards it meets its far side). */
static bool sphere_trial(scene *s, rng *g, spawn_tally *t)
{
    sphere *sp = &s->spheres[0];
    sp->center = random_place(g);
    sp->radius = log_uniform(g, -3.0f, 3.0f);
    vec3 u = sample_uniform_sphere(rng_uniform2(g));
    vec3 at = vec3_add(sp->center, vec3_scale(u, sp->radius));
    vec3 v = leaving_direction(g, u);  /* where the viewer is */
    ray r = ray_make(vec3_add(at, vec3_scale(v, sp->radius * (1.0f + 9.0f * rng_uniform(g)))), vec3_neg(v), 0.0f, INFINITY);
    hit h;
    int prim = s->num_triangles;
    if (!hit_prim(s, prim, &r, &h)) return false;  /* grazed past */
    leave_and_tally(s, prim, &r, &h, leaving_direction(g, h.ng), t);
    return true;
}

/* A hit on a random triangle from either side, left towards either side. */
static bool triangle_trial(scene *s, rng *g, spawn_tally *t)
{
    vec3 c = random_place(g);
    float size = log_uniform(g, -3.0f, 3.0f);
    vec3 p[3];
    for (int i = 0; i < 3; i++) p[i] = vec3_add(c, vec3_scale(sample_uniform_sphere(rng_uniform2(g)), size));
    vec3 n = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
    if (vec3_length(n) < 0.05f * size * size) return false;  /* too thin to aim at reliably */
    s->triangles[0] = triangle_make(p[0], p[1], p[2], 0);
    vec2 b = sample_uniform_triangle(rng_uniform2(g));
    vec3 at = vec3_add(vec3_add(vec3_scale(p[0], 1.0f - b.x - b.y), vec3_scale(p[1], b.x)), vec3_scale(p[2], b.y));
    n = vec3_normalize(n);
    vec3 v = leaving_direction(g, rng_uniform(g) < 0.5f ? n : vec3_neg(n));
    ray r = ray_make(vec3_add(at, vec3_scale(v, size * (1.0f + 9.0f * rng_uniform(g)))), vec3_neg(v), 0.0f, INFINITY);
    hit h;
    if (!hit_prim(s, 0, &r, &h)) return false;  /* missed at an edge */
    leave_and_tally(s, 0, &r, &h, leaving_direction(g, rng_uniform(g) < 0.5f ? h.ng : vec3_neg(h.ng)), t);
    return true;
}

/* A scene of one triangle and one sphere, rewritten by each trial. False where part 1 is a stub. */
static bool one_of_each(scene *s)
{
    memset(s, 0, sizeof *s);
    scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    scene_add_triangle(s, triangle_make(vec3_make(0, 0, 0), vec3_make(1, 0, 0), vec3_make(0, 1, 0), 0));
    sphere sp = {vec3_make(0, 0, 0), 1.0f, 0};
    scene_add_sphere(s, sp);
    ray r = ray_make(vec3_make(0, 0, 5), vec3_make(0, 0, -1), 0.0f, INFINITY);
    hit h;
    scene_prim_intersect(s, 1, &r, &h);
    return pl_todo_count() == 0;
}

static void check_never_self(bool (*trial)(scene *, rng *, spawn_tally *), const char *what, uint64_t seed)
{
    scene s;
    if (!one_of_each(&s)) {
        scene_free(&s);
        skip();  /* the student tree before part 1: its own tests report the stubs */
    }
    mc_print_seed(what, seed);
    rng g = rng_seeded(seed, 0);
    spawn_tally t = {0};
    while (t.hits < HITS_PER_KIND) trial(&s, &g, &t);
    scene_free(&s);
    printf("  %s: %ld hits; rays from the raw hit point (min_t = EPS_F) hit their own surface %ld times, "
           "spawned rays %ld times\n", what, t.hits, t.raw_self, t.spawned_self);
    if (t.spawned_self > 0) {
        print_error("%s: %ld of %ld spawned rays hit the primitive they leave; the first: %s\n", what, t.spawned_self,
                    t.hits, t.first);
        fail();
    }
    assert_true(t.raw_self > 0);  /* the trials reach the cases that need the offset */
}
#define check_never_self(...) PL_AT(check_never_self(__VA_ARGS__))

static void test_spawn_ray__never_hits_its_own_sphere(void **state)
{
    check_never_self(sphere_trial, "spheres", SEED);
}

static void test_spawn_ray__never_hits_its_own_triangle(void **state)
{
    check_never_self(triangle_trial, "triangles", SEED + 1);
}

/* ---- towards a light: the far end ---------------------------------------------------------- */

typedef struct {
    long samples, reached_light, raw_reached, missed_occluder;
    char first[256];
} light_tally;

/* A random area light and its coincident emissive quad (prims 0, 1), a floor facing it (prim 2),
 * and a hit on that floor from the light's side, anywhere from straight below to far off to the
 * side (grazing at both ends). False when the floor was missed. */
static bool light_and_floor(scene *s, rng *g, light *l, ray *r, hit *h)
{
    float size = log_uniform(g, -3.0f, 3.0f);
    frame f = frame_from_normal(sample_uniform_sphere(rng_uniform2(g)));
    vec3 place = random_place(g), eu = vec3_scale(f.s, size * (0.2f + rng_uniform(g)));
    *l = light_make_area(place, eu, vec3_scale(f.t, size * (0.2f + rng_uniform(g))), vec3_neg(f.n), rgb_gray(1.0f));
    vec3 hu = vec3_scale(l->edge_u, 0.5f), hv = vec3_scale(l->edge_v, 0.5f), c = l->position;
    vec3 c00 = vec3_sub(vec3_sub(c, hu), hv), c10 = vec3_sub(vec3_add(c, hu), hv);
    vec3 c11 = vec3_add(vec3_add(c, hu), hv), c01 = vec3_add(vec3_sub(c, hu), hv);
    s->triangles[0] = triangle_make(c00, c10, c11, 0), s->triangles[1] = triangle_make(c00, c11, c01, 0);
    vec3 below = vec3_sub(c, vec3_scale(f.n, size * log_uniform(g, -2.0f, 1.0f)));
    vec3 side = vec3_scale(frame_to_world(&f, vec3_make(rng_uniform(g) - 0.5f, rng_uniform(g) - 0.5f, 0)), size * log_uniform(g, -1.0f, 2.0f));
    vec3 at = vec3_add(below, side), fs = vec3_scale(f.s, 300.0f * size), ft = vec3_scale(f.t, 300.0f * size);
    s->triangles[2] = triangle_make(vec3_sub(at, fs), vec3_add(at, ft), vec3_add(at, vec3_sub(fs, ft)), 0);
    *r = ray_make(vec3_add(at, vec3_scale(f.n, size)), vec3_neg(f.n), 0.0f, INFINITY);
    return hit_prim(s, 2, r, h);
}

/* Whether the shadow ray still stops at an occluder put across its middle (triangle 3 of s, as wide
 * as the segment is long): stopping short of the light must not stop short of what lies between. */
static bool occluder_stops(scene *s, const ray *shadow, const light_sample *ls)
{
    frame across = frame_from_normal(ls->wi);
    vec3 mid = vec3_add(shadow->o, vec3_scale(shadow->d, 0.5f * shadow->max_t));
    vec3 a = vec3_scale(across.s, ls->dist), b = vec3_scale(across.t, ls->dist);
    s->triangles[3] = triangle_make(vec3_sub(mid, a), vec3_add(mid, b), vec3_add(mid, vec3_sub(a, b)), 0);
    ray r = *shadow;  /* the test narrows the ray's max_t */
    hit any;
    return scene_prim_intersect(s, 3, &r, &any);
}

/* One shadow ray from a floor hit to a light sample: it must reach neither the light's quad nor
 * the floor, and must stop at an occluder (prim 3) put across its middle. */
static void light_trial(scene *s, rng *g, light_tally *t)
{
    light l;
    ray r;
    hit h;
    light_sample ls;
    if (!light_and_floor(s, g, &l, &r, &h) || !light_sample_L(&l, h.p, rng_uniform2(g), &ls) || !(ls.pdf > 0.0f)) return;
    /* Floats resolve a distance d at a place x from the origin only to d / (x u): keep to where
     * the light and its distance span at least 1e-3 of x (some 16,000 steps of float). */
    float place = fmaxf(fabsf(h.p.x), fmaxf(fabsf(h.p.y), fabsf(h.p.z)));
    if (ls.dist < 1e-3f * place || vec3_length(l.edge_u) < 1e-3f * place || vec3_length(l.edge_v) < 1e-3f * place) return;
    t->samples++;
    ray shadow = spawn_ray_to_light(&r, &h, &l, &ls), raw = ray_make(h.p, ls.wi, EPS_F, ls.dist - EPS_F);
    hit any;
    for (int prim = 0; prim < 3; prim++) {
        ray probe = shadow, raw_probe = raw;
        if (scene_prim_intersect(s, prim, &raw_probe, &any)) t->raw_reached++;
        if (scene_prim_intersect(s, prim, &probe, &any) && t->reached_light++ == 0)
            snprintf(t->first, sizeof t->first, "prim %d at t = %g of max_t %g; light at (%g, %g, %g), size %g, dist %g",
                     prim, any.t, shadow.max_t, l.position.x, l.position.y, l.position.z, vec3_length(l.edge_u), ls.dist);
    }
    t->missed_occluder += !occluder_stops(s, &shadow, &ls);
}

/* one_of_each's scene with three more triangles, the room the light and occluder checks build in
 * (triangles 1..3); the test is skipped where part 1 is not solved yet. */
static void scene_with_room(scene *s)
{
    bool solved = one_of_each(s);
    for (int i = 0; i < 3; i++) scene_add_triangle(s, s->triangles[0]);
    if (!solved) {
        scene_free(s);
        skip();
    }
}

static void test_spawn_ray_to_light__stops_short_of_the_light_not_of_an_occluder(void **state)
{
    scene s;
    scene_with_room(&s);
    uint64_t seed = SEED + 2;
    mc_print_seed("area light samples", seed);
    rng g = rng_seeded(seed, 0);
    light_tally t = {0};
    while (t.samples < 200000) light_trial(&s, &g, &t);
    scene_free(&s);
    printf("  %ld samples: rays from the raw hit point to dist - EPS_F reached the light or the floor %ld times, "
           "spawned rays %ld times; spawned rays missed the occluder %ld times\n", t.samples, t.raw_reached,
           t.reached_light, t.missed_occluder);
    if (t.reached_light > 0) {
        print_error("%ld of %ld shadow rays reached the light's quad or their own floor; the first: %s\n", t.reached_light,
                    t.samples, t.first);
        fail();
    }
    assert_int_equal(0, t.missed_occluder);
    assert_true(t.raw_reached > 0);  /* the trials reach the cases that need the offsets */
}

/* ---- towards a point or spot light inside a surface ----------------------------------------- */

typedef struct {
    long samples, reached_quad, raw_reached, missed_occluder;
    long reached_by_sin[4];  /* reached_quad by sin of the ray to the quad: < 1e-3, < 1e-2, < 1e-1, above */
    char first[256];
} point_tally;

/* A random point or spot light inside a non-emissive quad (prims 0, 1) whose plane passes through
 * it, as CS184's CBempty.dae puts its point light, a floor facing it (prim 2) and a hit on that
 * floor from the light's side, from straight below to far off to the side. The spot points at the
 * floor with a cone of 90 degrees. False when the floor was missed. */
static bool point_light_in_quad(scene *s, rng *g, light_kind kind, light *l, vec3 *quad_n, ray *r, hit *h)
{
    float size = log_uniform(g, -3.0f, 3.0f);
    frame f = frame_from_normal(sample_uniform_sphere(rng_uniform2(g)));
    vec3 c = random_place(g);
    vec3 eu = vec3_scale(f.s, size * (0.2f + rng_uniform(g))), ev = vec3_scale(f.t, size * (0.2f + rng_uniform(g)));
    vec3 hu = vec3_scale(eu, 0.5f), hv = vec3_scale(ev, 0.5f);
    vec3 c00 = vec3_sub(vec3_sub(c, hu), hv), c10 = vec3_sub(vec3_add(c, hu), hv);
    vec3 c11 = vec3_add(vec3_add(c, hu), hv), c01 = vec3_add(vec3_sub(c, hu), hv);
    s->triangles[0] = triangle_make(c00, c10, c11, 0), s->triangles[1] = triangle_make(c00, c11, c01, 0);
    memset(l, 0, sizeof *l);
    l->kind = kind;
    l->radiance = rgb_gray(1.0f);
    l->position = vec3_add(c, vec3_add(vec3_scale(eu, 0.9f * (rng_uniform(g) - 0.5f)), vec3_scale(ev, 0.9f * (rng_uniform(g) - 0.5f))));
    l->direction = vec3_neg(f.n);
    l->attenuation[0] = 1.0f;
    l->falloff_deg = 90.0f;
    *quad_n = f.n;
    vec3 below = vec3_sub(l->position, vec3_scale(f.n, size * log_uniform(g, -2.0f, 1.0f)));
    vec3 side = vec3_scale(frame_to_world(&f, vec3_make(rng_uniform(g) - 0.5f, rng_uniform(g) - 0.5f, 0)), size * log_uniform(g, -1.0f, 2.0f));
    vec3 at = vec3_add(below, side), fs = vec3_scale(f.s, 300.0f * size), ft = vec3_scale(f.t, 300.0f * size);
    s->triangles[2] = triangle_make(vec3_sub(at, fs), vec3_add(at, ft), vec3_add(at, vec3_sub(fs, ft)), 0);
    *r = ray_make(vec3_add(at, vec3_scale(f.n, size)), vec3_neg(f.n), 0.0f, INFINITY);
    return hit_prim(s, 2, r, h);
}

static void point_trial(scene *s, rng *g, light_kind kind, point_tally *t)
{
    light l;
    vec3 quad_n;
    ray r;
    hit h;
    light_sample ls;
    if (!point_light_in_quad(s, g, kind, &l, &quad_n, &r, &h) || !light_sample_L(&l, h.p, rng_uniform2(g), &ls)) return;
    float place = fmaxf(fabsf(h.p.x), fmaxf(fabsf(h.p.y), fabsf(h.p.z)));
    if (ls.dist < 1e-3f * place) return;  /* as for area lights: where floats resolve the segment */
    t->samples++;
    ray shadow = spawn_ray_to_light(&r, &h, &l, &ls), raw = ray_make(h.p, ls.wi, EPS_F, ls.dist - EPS_F);
    hit any;
    float sin_quad = fabsf(vec3_dot(ls.wi, quad_n));
    for (int prim = 0; prim < 3; prim++) {
        ray probe = shadow, raw_probe = raw;
        if (scene_prim_intersect(s, prim, &raw_probe, &any)) t->raw_reached++;
        if (!scene_prim_intersect(s, prim, &probe, &any)) continue;
        t->reached_by_sin[sin_quad < 1e-3f ? 0 : sin_quad < 1e-2f ? 1 : sin_quad < 1e-1f ? 2 : 3]++;
        if (sin_quad < SPAWN_GRAZING_SIN) continue;  /* shallower than the contract: counted, not failed */
        if (t->reached_quad++ == 0)
            snprintf(t->first, sizeof t->first, "prim %d at t = %g of max_t %g; light at (%g, %g, %g), dist %g, sin %g",
                     prim, any.t, shadow.max_t, l.position.x, l.position.y, l.position.z, ls.dist, sin_quad);
    }
    t->missed_occluder += !occluder_stops(s, &shadow, &ls);
}

static void check_point_light_in_quad(light_kind kind, const char *what, uint64_t seed)
{
    scene s;
    scene_with_room(&s);
    mc_print_seed(what, seed);
    rng g = rng_seeded(seed, 0);
    point_tally t = {0};
    while (t.samples < 200000) point_trial(&s, &g, kind, &t);
    scene_free(&s);
    printf("  %s: %ld samples: rays from the raw hit point to dist - EPS_F reached the quad or the floor %ld times, "
           "spawned rays %ld times at sin >= SPAWN_GRAZING_SIN to the quad (at any angle, by sin: <1e-3 %ld, <1e-2 %ld, "
           "<1e-1 %ld, above %ld); spawned rays missed the occluder %ld times\n",
           what, t.samples, t.raw_reached, t.reached_quad, t.reached_by_sin[0], t.reached_by_sin[1], t.reached_by_sin[2],
           t.reached_by_sin[3], t.missed_occluder);
    if (t.reached_quad > 0) {
        print_error("%s: %ld of %ld shadow rays reached the quad around the light or their own floor; the first: %s\n",
                    what, t.reached_quad, t.samples, t.first);
        fail();
    }
    assert_int_equal(0, t.missed_occluder);
    assert_true(t.raw_reached > 0);
}
#define check_point_light_in_quad(...) PL_AT(check_point_light_in_quad(__VA_ARGS__))

static void test_spawn_ray_to_light__stops_short_of_a_quad_around_a_point_light(void **state)
{
    check_point_light_in_quad(LIGHT_POINT, "point light in a quad", SEED + 3);
}

static void test_spawn_ray_to_light__stops_short_of_a_quad_around_a_spot_light(void **state)
{
    check_point_light_in_quad(LIGHT_SPOT, "spot light in a quad", SEED + 4);
}

int spawn_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_spawn_ray__never_hits_its_own_sphere, test_setup),
        cmocka_unit_test_setup(test_spawn_ray__never_hits_its_own_triangle, test_setup),
        cmocka_unit_test_setup(test_spawn_ray_to_light__stops_short_of_the_light_not_of_an_occluder, test_setup),
        cmocka_unit_test_setup(test_spawn_ray_to_light__stops_short_of_a_quad_around_a_point_light, test_setup),
        cmocka_unit_test_setup(test_spawn_ray_to_light__stops_short_of_a_quad_around_a_spot_light, test_setup),
    };
    return cmocka_run_group_tests_name("framework: leaving a surface (spawn.c)", tests, NULL, NULL);
}
