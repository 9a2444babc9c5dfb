/* Test machinery: not part of any assignment.
 * The shipped scenes (the .dae files in scenes/): each loads quietly with the expected contents, and the
 * Cornell boxes are what the handout says they are (closed, walls facing in, the emissive quad
 * coinciding with the area light, the camera looking into the box). */
#include "../common/test.h"
#include <stdio.h>
#include <string.h>
#include "../../framework/dae.h"
#include "../../framework/material.h"

#define EPS 1e-4f

typedef struct {
    const char *path;
    int triangles, spheres, lights;
    int stand_ins;       /* kinds of material a later part shades: in a course without it, one warning each */
    material_kind kind;  /* ... and that part's kind (MATERIAL_DIFFUSE: none) */
} scene_spec;

static const scene_spec SCENES[] = {
    {"scenes/cornell_empty.dae", 12, 0, 1, 0, MATERIAL_DIFFUSE},
    {"scenes/cornell_spheres.dae", 12, 2, 1, 0, MATERIAL_DIFFUSE},
    {"scenes/cornell_bunny.dae", 12 + 3674, 0, 1, 0, MATERIAL_DIFFUSE},
    {"scenes/lights_point_dir.dae", 20, 1, 2, 0, MATERIAL_DIFFUSE},
    {"scenes/env_shapes.dae", 20, 1, 0, 0, MATERIAL_DIFFUSE},  /* lit by an environment map (-e): no light of its own */
    {"scenes/cornell_open.dae", 8, 2, 0, 0, MATERIAL_DIFFUSE},  /* the spheres' box without its ceiling, for an environment map */
    {"scenes/cornell_grazing.dae", 12, 2, 1, 0, MATERIAL_DIFFUSE},  /* 100 m out: its own test below */
    {"scenes/cornell_two_lights.dae", 14, 2, 2, 0, MATERIAL_DIFFUSE},  /* its own test below */
    {"scenes/cornell_mirror_glass.dae", 12, 2, 1, 2, MATERIAL_GLASS},  /* part 6's: a mirror and a glass sphere */
    {"scenes/cornell_microfacet.dae", 12, 2, 1, 1, MATERIAL_MICROFACET},  /* part 7's: two metals */
};

static void count_warning(void *user, const char *msg)
{
    (void)msg;
    ++*(int *)user;
}

/* Loads path, which must give exactly `expected` warnings. */
static void load_scene_warning(const char *path, scene *s, int expected)
{
    int warnings = 0;
    pl_diag d = {{0}, 0, count_warning, &warnings};
    pl_status st = dae_load(path, s, &d);
    if (st != PL_OK) fail_msg("%s: %s: %s", path, pl_status_name(st), d.error);
    if (warnings != expected) fail_msg("%s: %d warnings, expected %d", path, warnings, expected);
}

static void load_scene(const char *path, scene *s) { load_scene_warning(path, s, 0); }

static void test_scenes__each_loads_quietly_with_expected_contents(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof SCENES / sizeof SCENES[0]; i++) {
        const scene_spec *spec = &SCENES[i];
        scene s;
        load_scene_warning(spec->path, &s, material_kind_shaded(spec->kind) ? 0 : spec->stand_ins);
        if (s.num_triangles != spec->triangles || s.num_spheres != spec->spheres || s.num_lights != spec->lights)
            fail_msg("%s: expected %d triangles, %d spheres, %d lights; got %d, %d, %d", spec->path, spec->triangles,
                     spec->spheres, spec->lights, s.num_triangles, s.num_spheres, s.num_lights);
        assert_true(s.has_camera);
        aabb b = scene_bounds(&s);
        assert_false(aabb_is_empty(b));
        assert_true(vec3_is_finite(b.min) && vec3_is_finite(b.max));
        assert_true(b.max.x - b.min.x < 10 && b.max.y - b.min.y < 10 && b.max.z - b.min.z < 10);
        for (int t = 0; t < s.num_triangles; t++) {
            assert_float_near(1.0, vec3_length(s.triangles[t].n0), 1e-3);
            assert_in_range(s.triangles[t].material, 0, s.num_materials - 1);
        }
        scene_free(&s);
    }
}

/* The box of every Cornell scene: x, z in [-1, 1], floor 0, ceiling 1.5. */
static bool in_box(vec3 p)
{
    return p.x >= -1 - EPS && p.x <= 1 + EPS && p.y >= -EPS && p.y <= 1.5f + EPS && p.z >= -1 - EPS && p.z <= 1 + EPS;
}

static void check_cornell_box(const scene *s)
{
    const vec3 centre = vec3_make(0, 0.75f, 0);
    /* the only light: CS184's area light, just below the ceiling, facing down */
    assert_int_equal(1, s->num_lights);
    const light *l = &s->lights[0];
    assert_int_equal(LIGHT_AREA, l->kind);
    assert_vec3_near(vec3_make(0, 1.49f, 0), l->position, EPS);
    assert_vec3_near(vec3_make(0, -1, 0), l->direction, EPS);
    assert_float_near(0.48, l->area, EPS);
    assert_rgb_near(rgb_gray(10), l->radiance, EPS);

    float emissive_area = 0;
    int red = 0, blue = 0;
    for (int i = 0; i < s->num_triangles; i++) {
        const triangle *t = &s->triangles[i];
        const material *m = &s->materials[t->material];
        assert_true(in_box(t->p0) && in_box(t->p1) && in_box(t->p2));
        vec3 face = vec3_cross(vec3_sub(t->p1, t->p0), vec3_sub(t->p2, t->p0));
        if (!rgb_is_black(m->Le)) {
            /* the emissive quad lies in the light's plane, faces the same way, glows as bright */
            emissive_area += 0.5f * vec3_length(face);
            assert_vec3_near(l->direction, t->n0, EPS);
            assert_float_near(0.0, vec3_dot(vec3_sub(t->p0, l->position), l->direction), EPS);
            assert_rgb_near(l->radiance, m->Le, EPS);
            continue;
        }
        /* walls face the inside of the box (bunny triangles face every way: skip those) */
        bool wall = fabsf(fabsf(vec3_normalize(face).x) + fabsf(vec3_normalize(face).y) +
                          fabsf(vec3_normalize(face).z) - 1) < EPS &&
                    vec3_length(face) > 1.0f;
        if (!wall) continue;
        assert_true(vec3_dot(t->n0, vec3_sub(centre, t->p0)) > 0);
        assert_true(vec3_dot(vec3_normalize(face), t->n0) > 0.99f);  /* file normals agree with winding */
        if (t->p0.x < -1 + EPS && t->p1.x < -1 + EPS && t->p2.x < -1 + EPS) {
            red++;
            assert_true(m->albedo.r > 3 * m->albedo.g && m->albedo.r > 3 * m->albedo.b);
        }
        if (t->p0.x > 1 - EPS && t->p1.x > 1 - EPS && t->p2.x > 1 - EPS) {
            blue++;
            assert_true(m->albedo.b > 3 * m->albedo.r && m->albedo.b > 3 * m->albedo.g);
        }
    }
    assert_float_near(l->area, emissive_area, EPS);
    assert_int_equal(2, red);
    assert_int_equal(2, blue);

    /* the camera stands outside the open side, looking in, with CS184's lens */
    const camera *c = &s->camera;
    assert_true(s->has_camera);
    assert_true(c->position.z > 1);
    assert_float_near(49.13434, c->hfov, 1e-4);
    assert_false(c->fov_is_vertical);
    vec3 view = mat4_dir(c->camera_to_world, vec3_make(0, 0, -1));
    vec3 to_centre = vec3_normalize(vec3_sub(centre, c->position));
    assert_true(vec3_dot(view, to_centre) > cosf(deg_to_rad(c->vfov * 0.5f)));
}

static void test_scenes__cornell_boxes_are_closed_lit_and_framed(void **state)
{
    (void)state;
    for (int i = 0; i < 3; i++) {
        scene s;
        load_scene(SCENES[i].path, &s);
        check_cornell_box(&s);
        scene_free(&s);
    }
}

static void test_scenes__cornell_spheres_rest_on_the_floor_inside_the_box(void **state)
{
    (void)state;
    scene s;
    load_scene("scenes/cornell_spheres.dae", &s);
    for (int i = 0; i < 2; i++) {
        const sphere *sp = &s.spheres[i];
        assert_float_near(0.35, sp->radius, EPS);
        assert_float_near(sp->radius, sp->center.y, EPS);
        assert_true(fabsf(sp->center.x) + sp->radius < 1 && fabsf(sp->center.z) + sp->radius < 1);
        assert_true(rgb_is_black(s.materials[sp->material].Le));
    }
    assert_true(s.spheres[0].material != s.spheres[1].material);
    scene_free(&s);
}

/* The side-lit box (the grazing_direct case), 100 m from the origin along (1, 1, 1): moved back,
 * the light and its quad on the red wall facing +x, the quad reflecting nothing, both spheres on
 * the floor inside the box. */
/* Two area lights of different sizes and radiance under the ceiling, each with an emissive quad of its
 * own area and radiance in its plane (the part 3 cases that need more than one light). */
static void test_scenes__cornell_two_lights_differ_and_each_has_its_quad(void **state)
{
    (void)state;
    scene s;
    load_scene("scenes/cornell_two_lights.dae", &s);
    assert_int_equal(2, s.num_lights);
    const light *big = &s.lights[0], *small = &s.lights[1];
    assert_int_equal(LIGHT_AREA, big->kind);
    assert_int_equal(LIGHT_AREA, small->kind);
    assert_float_near(0.35, big->area, EPS);
    assert_float_near(0.0625, small->area, EPS);
    assert_rgb_near(rgb_gray(4), big->radiance, EPS);
    assert_rgb_near(rgb_gray(30), small->radiance, EPS);
    for (int k = 0; k < 2; k++) {
        const light *l = &s.lights[k];
        assert_float_near(1.49, l->position.y, EPS);
        assert_vec3_near(vec3_make(0, -1, 0), l->direction, EPS);
        float area = 0;
        for (int i = 0; i < s.num_triangles; i++) {
            const triangle *t = &s.triangles[i];
            const material *m = &s.materials[t->material];
            if (rgb_is_black(m->Le) || fabsf(m->Le.r - l->radiance.r) > EPS) continue;
            vec3 c = vec3_scale(vec3_add(t->p0, vec3_add(t->p1, t->p2)), 1.0f / 3.0f);
            assert_true(fabsf(c.x - l->position.x) < 0.5f && fabsf(c.z - l->position.z) < 0.5f);
            area += 0.5f * vec3_length(vec3_cross(vec3_sub(t->p1, t->p0), vec3_sub(t->p2, t->p0)));
        }
        assert_float_near(l->area, area, EPS);
    }
    scene_free(&s);
}

static void test_scenes__cornell_grazing_is_lit_from_the_red_wall(void **state)
{
    (void)state;
    scene s;
    load_scene("scenes/cornell_grazing.dae", &s);
    /* The file puts the box 100 m out on each axis; the loader stores it relative to the scene's
     * origin (scene.h): back to the box's own coordinates. */
    const vec3 back = vec3_make((float)(s.origin[0] - 100), (float)(s.origin[1] - 100), (float)(s.origin[2] - 100));
    for (int i = 0; i < s.num_triangles; i++) {
        triangle *t = &s.triangles[i];
        t->p0 = vec3_add(t->p0, back), t->p1 = vec3_add(t->p1, back), t->p2 = vec3_add(t->p2, back);
    }
    for (int i = 0; i < s.num_spheres; i++) s.spheres[i].center = vec3_add(s.spheres[i].center, back);
    assert_int_equal(1, s.num_lights);
    s.lights[0].position = vec3_add(s.lights[0].position, back);
    const light *l = &s.lights[0];
    assert_int_equal(LIGHT_AREA, l->kind);
    assert_vec3_near(vec3_make(-0.99f, 0.55f, -0.2f), l->position, EPS);
    assert_vec3_near(vec3_make(1, 0, 0), l->direction, EPS);
    assert_float_near(0.24, l->area, EPS);
    float emissive_area = 0;
    for (int i = 0; i < s.num_triangles; i++) {
        const triangle *t = &s.triangles[i];
        const material *m = &s.materials[t->material];
        assert_true(in_box(t->p0) && in_box(t->p1) && in_box(t->p2));
        if (rgb_is_black(m->Le)) continue;
        emissive_area += 0.5f * vec3_length(vec3_cross(vec3_sub(t->p1, t->p0), vec3_sub(t->p2, t->p0)));
        assert_vec3_near(l->direction, t->n0, EPS);
        assert_float_near(0.0, vec3_dot(vec3_sub(t->p0, l->position), l->direction), EPS);
        assert_true(rgb_is_black(m->albedo));  /* an emitter reflects nothing */
    }
    assert_float_near(l->area, emissive_area, EPS);
    for (int i = 0; i < s.num_spheres; i++) {
        const sphere *sp = &s.spheres[i];
        assert_float_near(sp->radius, sp->center.y, EPS);
        assert_true(fabsf(sp->center.x) + sp->radius < 1 && fabsf(sp->center.z) + sp->radius < 1);
    }
    scene_free(&s);
}

static void test_scenes__cornell_bunny_stands_on_the_floor(void **state)
{
    (void)state;
    scene s;
    load_scene("scenes/cornell_bunny.dae", &s);
    aabb bunny = aabb_empty();
    for (int i = 12; i < s.num_triangles; i++) {  /* the box and light come first */
        const triangle *t = &s.triangles[i];
        bunny = aabb_extend(aabb_extend(aabb_extend(bunny, t->p0), t->p1), t->p2);
    }
    assert_float_near(0.0, bunny.min.y, 1e-3);
    assert_float_near(0.9, bunny.max.y - bunny.min.y, 1e-3);
    assert_true(bunny.min.x > -1 && bunny.max.x < 1 && bunny.min.z > -1 && bunny.max.z < 1);
    scene_free(&s);
}

static void test_scenes__lights_point_dir_has_a_point_and_a_directional_light(void **state)
{
    (void)state;
    scene s;
    load_scene("scenes/lights_point_dir.dae", &s);
    assert_int_equal(LIGHT_POINT, s.lights[0].kind);
    assert_vec3_near(vec3_make(1.5f, 3, 2), s.lights[0].position, EPS);
    assert_int_equal(LIGHT_DIRECTIONAL, s.lights[1].kind);
    assert_float_near(1.0, vec3_length(s.lights[1].direction), EPS);
    assert_true(s.lights[1].direction.y < -0.5f);  /* sunlight travels downwards */
    for (int i = 0; i < s.num_materials; i++) assert_true(rgb_is_black(s.materials[i].Le));
    aabb b = scene_bounds(&s);
    assert_float_near(0.0, b.min.y, EPS);  /* the floor */
    scene_free(&s);
}

int scenes_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scenes__each_loads_quietly_with_expected_contents),
        cmocka_unit_test(test_scenes__cornell_boxes_are_closed_lit_and_framed),
        cmocka_unit_test(test_scenes__cornell_spheres_rest_on_the_floor_inside_the_box),
        cmocka_unit_test(test_scenes__cornell_grazing_is_lit_from_the_red_wall),
        cmocka_unit_test(test_scenes__cornell_two_lights_differ_and_each_has_its_quad),
        cmocka_unit_test(test_scenes__cornell_bunny_stands_on_the_floor),
        cmocka_unit_test(test_scenes__lights_point_dir_has_a_point_and_a_directional_light),
    };
    return cmocka_run_group_tests_name("scenes", tests, NULL, NULL);
}
