/* Test machinery: not part of any assignment.
 * Direct light at grazing angles, in closed form: where shadow acne darkened the reference
 * (issue 22: the lower half of the Cornell box's left sphere, lit by the ceiling light at grazing
 * angles). The sphere of cornell_spheres.dae (radius 0.35 at (-0.45, 0.35, -0.35)) under its
 * 0.6 x 0.8 ceiling light (radiance 10), nothing else. A point on a sphere sees exactly the part of
 * the light above its tangent plane (the sphere lies below it), so its irradiance is the cosine law
 * integrated over that part: Lambert's formula for a polygon, E = L/2 sum_i theta_i (n . g_i), over
 * the light clipped by the tangent plane (theta_i the angle each edge subtends at p, g_i the unit
 * normal of the plane through p and that edge). The reflected radiance is rho / pi * E.
 * Points: normals 90 to 110 degrees from straight up, where the light straddles their horizon.
 * Each point is one t test of direct_importance (-l 1, 20,000 samples) at PART3_CHECK_ALPHA
 * (part3_alpha.h: the Sidak share of the suite's 1e-3). Seed fixed and printed. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../common/tiny_scenes.h"
#include "../../parts/part3_direct/part3.h"
#include "part3_alpha.h"

#define SEED mc_seed(0x5eed3305ull)
#define RHO 0.8
#define LE 10.0
#define RADIUS 0.35
#define MAX_CORNERS 8

typedef struct { double x, y, z; } dvec;
static dvec dv(double x, double y, double z) { dvec v = {x, y, z}; return v; }
static dvec dsub(dvec a, dvec b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dcross(dvec a, dvec b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static dvec dlerp(dvec a, dvec b, double t) { return dv(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t); }

/* The ceiling light's corners, as tiny_add_emitter builds it below. */
static const dvec light_corners[4] = {{-0.3, 1.49, -0.4}, {0.3, 1.49, -0.4}, {0.3, 1.49, 0.4}, {-0.3, 1.49, 0.4}};

/* The polygon's part on the positive side of the plane through p with normal n (one
 * Sutherland-Hodgman step), as vectors from p. Returns its number of corners. */
static int clip_above(const dvec *poly, int count, dvec p, dvec n, dvec *out)
{
    int k = 0;
    for (int i = 0; i < count; i++) {
        dvec a = dsub(poly[i], p), b = dsub(poly[(i + 1) % count], p);
        double da = ddot(a, n), db = ddot(b, n);
        if (da >= 0) out[k++] = a;
        if ((da >= 0) != (db >= 0)) out[k++] = dlerp(a, b, da / (da - db));
    }
    return k;
}

/* Lambert's formula: the irradiance at p (normal n) from a uniform polygon of radiance L. */
static double polygon_irradiance(dvec p, dvec n, double L)
{
    dvec v[MAX_CORNERS];
    int k = clip_above(light_corners, 4, p, n, v);
    double sum = 0;
    for (int i = 0; i < k; i++) {
        dvec a = v[i], b = v[(i + 1) % k], g = dcross(a, b);
        double lg = sqrt(ddot(g, g)), la = sqrt(ddot(a, a)), lb = sqrt(ddot(b, b));
        if (lg == 0 || la == 0 || lb == 0) continue;
        double theta = atan2(lg, ddot(a, b));
        sum += theta * ddot(n, dv(g.x / lg, g.y / lg, g.z / lg));
    }
    return 0.5 * L * fabs(sum);
}

static void grazing_world(tiny_world *w)
{
    tiny_world_begin(w);
    int mat = scene_add_material(&w->s, material_make(rgb_gray((float)RHO), rgb_gray(0.0f)));
    sphere sp = {vec3_make(-0.45f, 0.35f, -0.35f), (float)RADIUS, mat};
    assert_true(mat >= 0 && scene_add_sphere(&w->s, sp) >= 0);
    assert_true(tiny_add_emitter(&w->s, vec3_make(0, 1.49f, 0), vec3_make(0.6f, 0, 0), vec3_make(0, 0, 0.8f),
                                 vec3_make(0, -1, 0), rgb_gray((float)LE)));
    w->o.light_samples = 1;
    assert_int_equal(PL_OK, tiny_world_finish(w));
}

/* The sphere point whose normal is `polar` degrees from straight up, turned `azimuth` degrees
 * around the vertical from the direction towards the light's centre; seen from 3 m along it. */
static void check_point(tiny_world *w, double polar, double azimuth, uint64_t seed)
{
    dvec c = dv(-0.45, 0.35, -0.35), to_light = dv(0.45, 0, 0.35);
    double base = atan2(to_light.z, to_light.x) + azimuth * PL_PI / 180, th = polar * PL_PI / 180;
    dvec n = dv(sin(th) * cos(base), cos(th), sin(th) * sin(base));
    dvec p = dv(c.x + RADIUS * n.x, c.y + RADIUS * n.y, c.z + RADIUS * n.z);
    vec3 pf = vec3_make((float)p.x, (float)p.y, (float)p.z), nf = vec3_make((float)n.x, (float)n.y, (float)n.z);
    ray r = ray_make(vec3_add(pf, vec3_scale(nf, 3.0f)), vec3_neg(nf), 0.0f, INFINITY);
    hit h;
    assert_hit(render_intersect(&w->ctx, &r, &h));
    double expected = RHO / PL_PI * polygon_irradiance(p, n, LE);
    char what[160];
    snprintf(what, sizeof what, "direct_importance on the sphere, normal %g deg from up, azimuth %g: rho/pi E", polar, azimuth);
    mc_print_seed(what, seed);
    stats_acc acc[3];
    mc_run_at(&w->ctx, direct_importance, what, &r, &h, seed, 20000, acc, __FILE__, __LINE__);
    assert_true(expected > 0);
    assert_mean_matches(&acc[0], expected, PART3_CHECK_ALPHA, what);
}
#define check_point(...) PL_AT(check_point(__VA_ARGS__))

static void test_direct_importance__grazing_light_on_a_sphere_follows_the_cosine_law(void **state)
{
    tiny_world w;
    grazing_world(&w);
    /* The light's centre from 80 to 99 degrees off these normals: it straddles their horizon. */
    const double polar[] = {90, 95, 100, 100, 105, 105, 110}, azimuth[] = {0, 20, 0, 30, 0, 30, 0};
    for (int i = 0; i < 7; i++) check_point(&w, polar[i], azimuth[i], SEED + (uint64_t)i);
    tiny_world_free(&w);
}

int grazing_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_direct_importance__grazing_light_on_a_sphere_follows_the_cosine_law, test_setup),
    };
    return cmocka_run_group_tests_name("part3: direct light at grazing angles, in closed form", tests, NULL, NULL);
}
