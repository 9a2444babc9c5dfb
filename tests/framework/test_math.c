/* Test machinery: not part of any assignment. Vectors, matrices, frames and boxes. */
#include "../common/test.h"
#include "../../framework/mat4.h"
#include "../../framework/frame.h"
#include "../../framework/aabb.h"

static void test_vec3__cross_is_right_handed(void **state)
{
    assert_vec3_near(vec3_make(0, 0, 1), vec3_cross(vec3_make(1, 0, 0), vec3_make(0, 1, 0)), 0);
    assert_float_near(32.0, vec3_dot(vec3_make(1, 2, 3), vec3_make(4, 5, 6)), 0);
}

static void test_vec3_normalize__zero_stays_zero(void **state)
{
    assert_vec3_near(vec3_make(0, 0, 0), vec3_normalize(vec3_make(0, 0, 0)), 0);
    assert_vec3_near(vec3_make(0.6f, 0.8f, 0), vec3_normalize(vec3_make(3, 4, 0)), 1e-6f);
}

static void test_mat4_rotate__quarter_turn_about_z(void **state)
{
    mat4 r = mat4_rotate(vec3_make(0, 0, 1), 90.0f);
    assert_vec3_near(vec3_make(0, 1, 0), mat4_point(r, vec3_make(1, 0, 0)), 1e-6f);
}

static void test_mat4_mul__applies_right_factor_first(void **state)
{
    /* T * S: scale first, then translate. */
    mat4 m = mat4_mul(mat4_translate(vec3_make(1, 2, 3)), mat4_scale(vec3_make(2, 2, 2)));
    assert_vec3_near(vec3_make(3, 4, 5), mat4_point(m, vec3_make(1, 1, 1)), 1e-6f);
    assert_vec3_near(vec3_make(2, 2, 2), mat4_dir(m, vec3_make(1, 1, 1)), 1e-6f);
}

static void test_mat4_inverse__undoes_the_transform(void **state)
{
    mat4 m = mat4_mul(mat4_translate(vec3_make(1, -2, 3)), mat4_mul(mat4_rotate(vec3_make(1, 1, 0), 33.0f),
                                                                 mat4_scale(vec3_make(2, 3, 0.5f))));
    mat4 inv;
    assert_true(mat4_inverse(m, &inv));
    vec3 p = vec3_make(0.3f, -0.7f, 2.0f);
    assert_vec3_near(p, mat4_point(inv, mat4_point(m, p)), 1e-5f);
    mat4 singular = mat4_scale(vec3_make(1, 0, 1));
    assert_false(mat4_inverse(singular, &inv));
}

static void test_mat4_normal__stays_perpendicular_under_nonuniform_scale(void **state)
{
    mat4 m = mat4_scale(vec3_make(4, 1, 1));
    vec3 tangent = mat4_dir(m, vec3_make(1, -1, 0));   /* a surface direction, transformed */
    vec3 n = mat4_normal(m, vec3_make(1, 1, 0));       /* its normal, transformed */
    assert_float_near(0.0, vec3_dot(tangent, n), 1e-6);
    assert_float_near(1.0, vec3_length(n), 1e-6);
}

static void test_mat4_lookat__looks_down_minus_z(void **state)
{
    mat4 m = mat4_lookat(vec3_make(0, 0, 5), vec3_make(0, 0, 0), vec3_make(0, 1, 0));
    assert_vec3_near(vec3_make(0, 0, -1), mat4_dir(m, vec3_make(0, 0, -1)), 1e-6f);
    assert_vec3_near(vec3_make(0, 0, 5), mat4_point(m, vec3_make(0, 0, 0)), 1e-6f);
    m = mat4_lookat(vec3_make(3, 0, 0), vec3_make(0, 0, 0), vec3_make(0, 1, 0));
    assert_vec3_near(vec3_make(-1, 0, 0), mat4_dir(m, vec3_make(0, 0, -1)), 1e-6f);
    assert_vec3_near(vec3_make(0, 1, 0), mat4_dir(m, vec3_make(0, 1, 0)), 1e-6f);
}

static void test_frame__is_orthonormal_for_many_normals(void **state)
{
    vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0.577f, -0.577f, 0.577f}, {1e-4f, 0, -1}};
    for (size_t i = 0; i < sizeof normals / sizeof normals[0]; i++) {
        vec3 n = vec3_normalize(normals[i]);
        frame f = frame_from_normal(n);
        assert_float_near(1.0, vec3_length(f.s), 1e-5);
        assert_float_near(1.0, vec3_length(f.t), 1e-5);
        assert_float_near(0.0, vec3_dot(f.s, f.t), 1e-5);
        assert_float_near(0.0, vec3_dot(f.s, n), 1e-5);
        assert_vec3_near(vec3_make(0, 0, 1), frame_to_local(&f, n), 1e-5f);
        vec3 w = vec3_normalize(vec3_make(0.2f, -0.5f, 0.7f));
        assert_vec3_near(w, frame_to_world(&f, frame_to_local(&f, w)), 1e-5f);
    }
}

static void test_aabb__union_area_and_axis(void **state)
{
    aabb b = aabb_extend(aabb_extend(aabb_empty(), vec3_make(0, 0, 0)), vec3_make(1, 2, 3));
    assert_float_near(2.0 * (2 + 6 + 3), aabb_surface_area(b), 1e-6);
    assert_int_equal(2, aabb_max_axis(b));
    assert_float_near(0.0, aabb_surface_area(aabb_empty()), 0);
    assert_true(aabb_is_empty(aabb_empty()));
    assert_true(aabb_contains(b, aabb_extend(aabb_empty(), vec3_make(0.5f, 1, 1))));
}

int math_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vec3__cross_is_right_handed),
        cmocka_unit_test(test_vec3_normalize__zero_stays_zero),
        cmocka_unit_test(test_mat4_rotate__quarter_turn_about_z),
        cmocka_unit_test(test_mat4_mul__applies_right_factor_first),
        cmocka_unit_test(test_mat4_inverse__undoes_the_transform),
        cmocka_unit_test(test_mat4_normal__stays_perpendicular_under_nonuniform_scale),
        cmocka_unit_test(test_mat4_lookat__looks_down_minus_z),
        cmocka_unit_test(test_frame__is_orthonormal_for_many_normals),
        cmocka_unit_test(test_aabb__union_area_and_axis),
    };
    return cmocka_run_group_tests_name("math", tests, NULL, NULL);
}
