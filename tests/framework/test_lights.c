/* Test machinery: not part of any assignment.
 * The framework's lights (framework/light.c): area light samples have the solid-angle density they
 * claim (the mean of 1 / pdf is the solid angle the light subtends), point and spot lights follow
 * the inverse square law and COLLADA attenuation, one-sided lights are dark from behind.
 * alpha: statistical checks run at FRAMEWORK_CHECK_ALPHA (framework_alpha.h). Fixed seeds. */
#include <stdio.h>
#include "../common/test.h"
#include "../../framework/stats.h"
#include "../common/mc_assert.h"
#include "../../framework/light.h"
#include "framework_alpha.h"
#include <string.h>

#define SEED mc_seed(0x5eed3002ull)

static light area_light(float half_x, float half_z, float height)
{
    return light_make_area(vec3_make(0, height, 0), vec3_make(2 * half_x, 0, 0), vec3_make(0, 0, 2 * half_z),
                           vec3_make(0, -1, 0), rgb_gray(3.0f));
}

/* E[1 / pdf(wi)] over the light's samples = the solid angle it subtends (the integral of 1 over the
 * directions towards it). Seen from a point on its axis at distance h, a 2a x 2b rectangle
 * subtends 4 asin(a b / sqrt((a^2 + h^2)(b^2 + h^2))). */
static void test_area_light__mean_inverse_pdf_is_solid_angle(void **state)
{
    (void)state;
    mc_print_seed("area light 1/pdf", SEED);
    const double a = 0.5, b = 0.3, h = 0.8;
    light l = area_light((float)a, (float)b, (float)h);
    stats_acc acc = stats_acc_make();
    rng g = rng_seeded(SEED, 0);
    for (int i = 0; i < 100000; i++) {
        light_sample ls;
        assert_true(light_sample_L(&l, vec3_make(0, 0, 0), rng_uniform2(&g), &ls));
        assert_false(ls.is_delta);
        assert_true(ls.pdf > 0.0f && isfinite(ls.pdf));
        stats_acc_add(&acc, 1.0 / ls.pdf);
    }
    double omega = 4.0 * asin(a * b / sqrt((a * a + h * h) * (b * b + h * h)));
    assert_mean_matches(&acc, omega, FRAMEWORK_CHECK_ALPHA, "mean 1 / pdf of the area light (solid angle)");
}

static void test_area_light__sample_lies_on_the_light(void **state)
{
    (void)state;
    light l = area_light(0.5f, 0.3f, 0.8f);
    vec3 p = vec3_make(0.7f, -0.2f, 0.1f);
    rng g = rng_seeded(SEED + 1, 0);
    for (int i = 0; i < 1000; i++) {
        light_sample ls;
        assert_true(light_sample_L(&l, p, rng_uniform2(&g), &ls));
        assert_float_near(1.0, vec3_length(ls.wi), 1e-5);
        vec3 q = vec3_add(p, vec3_scale(ls.wi, ls.dist));
        assert_float_near(0.8, q.y, 1e-5);
        assert_true(fabsf(q.x) <= 0.5f + 1e-5f && fabsf(q.z) <= 0.3f + 1e-5f);
        assert_rgb_near(l.radiance, ls.L, 0.0f);
        /* pdf = dist^2 / (cos_light area), cos_light against the unit direction */
        float cos_light = ls.wi.y;  /* the light faces -y, p is below it */
        assert_float_near(ls.dist * ls.dist / (cos_light * l.area), ls.pdf, 1e-3 * ls.pdf);
    }
}

static void test_area_light__is_dark_from_behind(void **state)
{
    (void)state;
    light l = area_light(0.5f, 0.3f, 0.8f);
    light_sample ls;
    assert_false(light_sample_L(&l, vec3_make(0, 2, 0), vec2_make(0.3f, 0.6f), &ls));
    assert_false(light_is_delta(&l));
}

static light point_light(float I, float c, float lin, float q)
{
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    l.radiance = rgb_gray(I);
    l.position = vec3_make(1, 2, 2);
    l.attenuation[0] = c;
    l.attenuation[1] = lin;
    l.attenuation[2] = q;
    return l;
}

static void test_point_light__inverse_square_with_attenuation(void **state)
{
    (void)state;
    vec3 p = vec3_make(1, 2, -1);  /* 3 m below the light along z */
    light l = point_light(9.0f, 1, 0, 0);
    light_sample ls;
    assert_true(light_sample_L(&l, p, vec2_make(0.1f, 0.9f), &ls));
    assert_true(ls.is_delta && light_is_delta(&l));
    assert_vec3_near(vec3_make(0, 0, 1), ls.wi, 1e-6f);
    assert_float_near(3.0, ls.dist, 1e-5);
    assert_float_near(1.0, ls.pdf, 0.0);
    assert_rgb_near(rgb_gray(1.0f), ls.L, 1e-6f);  /* 9 / 3^2 */
    l = point_light(9.0f, 0.5f, 0.25f, 0.5f);        /* 1 / (0.5 + 0.75 + 4.5) */
    assert_true(light_sample_L(&l, p, vec2_make(0.1f, 0.9f), &ls));
    assert_rgb_near(rgb_gray(1.0f / 5.75f), ls.L, 1e-6f);
}

static void test_directional_light__comes_from_minus_its_direction(void **state)
{
    (void)state;
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_DIRECTIONAL;
    l.radiance = rgb_make(1, 2, 3);
    l.direction = vec3_make(0, -1, 0);
    light_sample ls;
    assert_true(light_sample_L(&l, vec3_make(5, 1, 2), vec2_make(0.5f, 0.5f), &ls));
    assert_true(ls.is_delta && light_is_delta(&l));
    assert_vec3_near(vec3_make(0, 1, 0), ls.wi, 1e-6f);
    assert_true(isinf(ls.dist));
    assert_rgb_near(l.radiance, ls.L, 0.0f);
}

static void test_spot_light__cone_and_falloff(void **state)
{
    (void)state;
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_SPOT;
    l.radiance = rgb_gray(4.0f);
    l.position = vec3_make(0, 2, 0);
    l.direction = vec3_make(0, -1, 0);
    l.attenuation[0] = 1.0f;
    l.falloff_deg = 30.0f;
    l.falloff_exp = 2.0f;
    light_sample ls;
    assert_true(light_sample_L(&l, vec3_make(0, 0, 0), vec2_make(0.5f, 0.5f), &ls));
    assert_rgb_near(rgb_gray(1.0f), ls.L, 1e-6f);  /* on the axis: 4 / 2^2 */
    /* 20 degrees off the axis: 4 cos^2(20) / d^2 with d = 2 / cos(20) */
    float t = tanf(deg_to_rad(20.0f)) * 2.0f;
    assert_true(light_sample_L(&l, vec3_make(t, 0, 0), vec2_make(0.5f, 0.5f), &ls));
    double c = cos(deg_to_rad(20.0f)), d = 2.0 / c;
    assert_float_near(4.0 * c * c / (d * d), ls.L.r, 1e-5);
    /* 40 degrees off the axis: outside the cone */
    t = tanf(deg_to_rad(40.0f)) * 2.0f;
    assert_false(light_sample_L(&l, vec3_make(t, 0, 0), vec2_make(0.5f, 0.5f), &ls));
}

static void test_ambient_light__uniform_over_the_upper_hemisphere(void **state)
{
    (void)state;
    light l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_AMBIENT;
    l.radiance = rgb_gray(0.5f);
    rng g = rng_seeded(SEED + 2, 0);
    for (int i = 0; i < 1000; i++) {
        light_sample ls;
        assert_true(light_sample_L(&l, vec3_make(0, 0, 0), rng_uniform2(&g), &ls));
        assert_true(ls.wi.y >= 0.0f);
        assert_false(ls.is_delta);
        assert_float_near(1.0 / (2.0 * M_PI), ls.pdf, 1e-6);
    }
}

int lights_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_area_light__mean_inverse_pdf_is_solid_angle),
        cmocka_unit_test(test_area_light__sample_lies_on_the_light),
        cmocka_unit_test(test_area_light__is_dark_from_behind),
        cmocka_unit_test(test_point_light__inverse_square_with_attenuation),
        cmocka_unit_test(test_directional_light__comes_from_minus_its_direction),
        cmocka_unit_test(test_spot_light__cone_and_falloff),
        cmocka_unit_test(test_ambient_light__uniform_over_the_upper_hemisphere),
    };
    return cmocka_run_group_tests_name("framework: lights", tests, test_setup, NULL);  /* forget stubs earlier groups ran */
}
