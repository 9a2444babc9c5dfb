/* Test machinery: not part of any assignment. framework/material.c: the BSDF of a material,
 * whatever its kind, is the one place parts 3 and 4 reach a BSDF through. */
#include "../common/test.h"
#include "../../framework/material.h"
#include "../../framework/todo.h"
#include "../../parts/part3_direct/part3.h"
#include "../../framework/frame.h"
#include <string.h>

/* Every kind this course has no part for stands in as part 3's diffuse BSDF with its colour: the
 * same f, pdf and sample, bit for bit, as bsdf_f, bsdf_pdf and bsdf_sample_f give that material,
 * for directions above and below the surface. (A kind's own part, once the course has one, is
 * tested by that part's suite.) */
static void test_material__every_kind_without_a_part_is_part_3s_diffuse_bsdf(void **state)
{
    (void)state;
    (void)bsdf_f(&(material){.albedo = {0.5f, 0.5f, 0.5f}}, vec3_make(0, 0, 1), vec3_make(0, 0, 1));
    if (pl_todo_count() > 0) skip();  /* the student tree: part 3's own tests report its stubs */
    const material_kind kinds[] = {MATERIAL_DIFFUSE, MATERIAL_MIRROR, MATERIAL_GLASS, MATERIAL_REFRACTION,
                                   MATERIAL_MICROFACET};
    const vec3 wo = vec3_normalize(vec3_make(0.3f, -0.2f, 0.9f));
    const vec3 wis[] = {vec3_normalize(vec3_make(-0.4f, 0.1f, 0.8f)), vec3_make(0, 0, 1),
                        vec3_normalize(vec3_make(0.2f, 0.3f, -0.9f))};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        if (kinds[k] != MATERIAL_DIFFUSE && material_kind_shaded(kinds[k])) continue;  /* the course's part shades it */
        material m = material_make(rgb_make(0.7f, 0.5f, 0.3f), rgb_gray(0.0f));
        m.kind = kinds[k];
        for (size_t i = 0; i < sizeof wis / sizeof wis[0]; i++) {
            rgb a = material_f(&m, wo, wis[i]), b = bsdf_f(&m, wo, wis[i]);
            if (memcmp(&a, &b, sizeof a) != 0)
                fail_msg("kind %d: material_f is (%g, %g, %g), bsdf_f (%g, %g, %g)", (int)kinds[k], a.r, a.g, a.b,
                         b.r, b.g, b.b);
            float pa = material_pdf(&m, wo, wis[i]), pb = bsdf_pdf(&m, wo, wis[i]);
            if (memcmp(&pa, &pb, sizeof pa) != 0) fail_msg("kind %d: material_pdf is %g, bsdf_pdf %g", (int)kinds[k], pa, pb);
        }
        for (int j = 0; j < 16; j++) {
            vec2 u = vec2_make((j + 0.5f) / 16.0f, (float)((j * 7) % 16) / 16.0f);
            vec3 wa, wb;
            float pa, pb;
            rgb a = material_sample_f(&m, wo, u, &wa, &pa), b = bsdf_sample_f(&m, wo, u, &wb, &pb);
            if (memcmp(&a, &b, sizeof a) != 0 || memcmp(&wa, &wb, sizeof wa) != 0 || memcmp(&pa, &pb, sizeof pa) != 0)
                fail_msg("kind %d, u = (%g, %g): material_sample_f gives wi (%g, %g, %g), pdf %g; bsdf_sample_f wi "
                         "(%g, %g, %g), pdf %g", (int)kinds[k], u.x, u.y, wa.x, wa.y, wa.z, pa, wb.x, wb.y, wb.z, pb);
        }
    }
}

/* Which kinds are deltas and which have an inside follows the course's parts: part 6's mirror,
 * glass and refraction where it has part 6, nothing else. A delta's f and pdf are 0 for every pair
 * of directions (a light sample can never land on its one direction). */
static void test_material__delta_kinds_follow_the_course(void **state)
{
    (void)state;
    bool part6 = false;
#ifdef PL_HAS_PART6
    part6 = true;
#endif
    const material_kind kinds[] = {MATERIAL_DIFFUSE, MATERIAL_MIRROR, MATERIAL_GLASS, MATERIAL_REFRACTION,
                                   MATERIAL_MICROFACET};
    const bool delta[] = {false, part6, part6, part6, false}, inside[] = {false, false, part6, part6, false};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        material m = material_make(rgb_make(0.7f, 0.5f, 0.3f), rgb_gray(0.0f));
        m.kind = kinds[k];
        assert_int_equal(delta[k], material_is_delta(&m));
        assert_int_equal(inside[k], material_has_inside(&m));
        if (!delta[k]) continue;
        vec3 wo = vec3_normalize(vec3_make(0.3f, -0.2f, 0.9f));
        assert_true(rgb_is_black(material_f(&m, wo, vec3_make(-wo.x, -wo.y, wo.z))));
        assert_true(material_pdf(&m, wo, vec3_make(-wo.x, -wo.y, wo.z)) == 0.0f);
    }
}

/* shading_frame turns the normal towards the viewer, except on a surface that transmits: glass
 * keeps its outward normal, so a ray from inside sees wo.z < 0. */
static void test_shading_frame__glass_keeps_its_outward_normal(void **state)
{
    (void)state;
    hit h = {.n = vec3_make(0, 0, 1)};
    ray from_inside = ray_make(vec3_make(0, 0, -1), vec3_make(0, 0, 1), 0.0f, INFINITY);
    frame f = shading_frame(&from_inside, &h);
    assert_true(frame_to_local(&f, vec3_neg(from_inside.d)).z > 0.0f);  /* diffuse: turned to face the ray */
    h.transmits = 1;
    f = shading_frame(&from_inside, &h);
    assert_true(frame_to_local(&f, vec3_neg(from_inside.d)).z < 0.0f);  /* glass: outward, the ray below it */
}

int material_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_material__every_kind_without_a_part_is_part_3s_diffuse_bsdf),
        cmocka_unit_test(test_material__delta_kinds_follow_the_course),
        cmocka_unit_test(test_shading_frame__glass_keeps_its_outward_normal),
    };
    return cmocka_run_group_tests_name("material", tests, NULL, NULL);
}
