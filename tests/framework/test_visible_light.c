/* Test machinery: not part of any assignment. Area lights made visible geometry
 * (framework/visible_light.h): which lights a file's emissive mesh covers, the two triangles of one
 * that none covers, the loader's choice, and renders that show the light once. */
#include "../common/test.h"
#include "../common/warn_log.h"
#include "../../framework/visible_light.h"
#include "../../framework/light.h"
#include "../../framework/dae.h"
#include "../../framework/file.h"
#include "../../framework/render.h"
#include "../../framework/todo.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- a light and quads over it, by hand ---------------------------------------------------------
 * CS184's Cornell light in pathlab's world: centred at (0, 1.49, 0), x in [-0.3, 0.3], z in
 * [-0.4, 0.4] (0.48 m^2), facing down, radiance 10. */

#define LIGHT_Y 1.49f

static void scene_with_light(scene *s)
{
    memset(s, 0, sizeof *s);
    light l = light_make_area(vec3_make(0, LIGHT_Y, 0), vec3_make(-0.6f, 0, 0), vec3_make(0, 0, 0.8f),
                              vec3_make(0, -1, 0), rgb_gray(10));
    assert_true(scene_add_light(s, l) == 0);
}

/* An axis-aligned quad at height y over x in [x0, x1], z in [z0, z1], as two triangles; facing down
 * (as the light) or up, emissive or not. */
static void add_quad(scene *s, float y, float x0, float x1, float z0, float z1, bool down, bool emissive)
{
    int m = scene_add_material(s, material_make(rgb_gray(emissive ? 0.0f : 0.5f), rgb_gray(emissive ? 10.0f : 0.0f)));
    vec3 a = {x0, y, z0}, b = {x1, y, z0}, c = {x1, y, z1}, d = {x0, y, z1};
    /* (a, b, c) turns from +x to +z: its normal is -y, down. */
    scene_add_triangle(s, down ? triangle_make(a, b, c, m) : triangle_make(a, c, b, m));
    scene_add_triangle(s, down ? triangle_make(a, c, d, m) : triangle_make(a, d, c, m));
}

static double coverage(const scene *s) { return visible_light_coverage(s, &s->lights[0], s->num_triangles); }

/* Shares worked out on paper from the rectangles' overlaps with the light's 0.6 x 0.8 m. */
static void test_visible_light_coverage__is_the_share_of_the_light_emissive_triangles_lie_over(void **state)
{
    (void)state;
    static const struct {
        const char *what;
        float dy, x0, x1, z0, z1;
        bool down, emissive;
        double want;
    } quads[] = {
        {"the light's own quad", 0, -0.3f, 0.3f, -0.4f, 0.4f, true, true, 1.0},
        {"the quad facing up (a file's choice: still over it)", 0, -0.3f, 0.3f, -0.4f, 0.4f, false, true, 1.0},
        {"a quad 0.1 mm below it (within the tolerance)", -1e-4f, -0.3f, 0.3f, -0.4f, 0.4f, true, true, 1.0},
        {"a quad 1 cm below it", -0.01f, -0.3f, 0.3f, -0.4f, 0.4f, true, true, 0.0},
        {"a white (not emissive) quad", 0, -0.3f, 0.3f, -0.4f, 0.4f, true, false, 0.0},
        {"its left half", 0, -0.3f, 0.0f, -0.4f, 0.4f, true, true, 0.5},
        {"a quad over x in [0.1, 0.5]: 0.2 x 0.8 of it", 0, 0.1f, 0.5f, -0.4f, 0.4f, true, true, 0.16 / 0.48},
        {"a 2 x 2 m quad around it", 0, -1, 1, -1, 1, true, true, 1.0},
        {"a quad beside it", 0, 0.5f, 0.9f, -0.4f, 0.4f, true, true, 0.0},
    };
    for (size_t k = 0; k < sizeof quads / sizeof quads[0]; k++) {
        /* one quad at a time over a fresh light: the shares never add up across cases */
        scene s;
        scene_with_light(&s);
        add_quad(&s, LIGHT_Y + quads[k].dy, quads[k].x0, quads[k].x1, quads[k].z0, quads[k].z1, quads[k].down,
                 quads[k].emissive);
        if (fabs(coverage(&s) - quads[k].want) > 1e-5)
            fail_msg("%s: covers %.6f of the light, expected %.6f", quads[k].what, coverage(&s), quads[k].want);
        scene_free(&s);
    }
}

/* A triangle cut by the light's edges: the half of the light below its diagonal, and a triangle
 * whose corners all lie outside the light while it covers the light's centre. */
static void test_visible_light_coverage__clips_triangles_to_the_light(void **state)
{
    (void)state;
    scene s;
    scene_with_light(&s);
    int m = scene_add_material(&s, material_make(rgb_gray(0), rgb_gray(1)));
    scene_add_triangle(&s, triangle_make(vec3_make(-0.3f, LIGHT_Y, -0.4f), vec3_make(0.3f, LIGHT_Y, -0.4f),
                                         vec3_make(-0.3f, LIGHT_Y, 0.4f), m));
    assert_float_near(0.5, coverage(&s), 1e-6);
    /* The triangle (-0.6, -0.4) (0.6, -0.4) (0, 0.8) in (x, z) holds the light but for two corners cut
     * off by its slanted sides (z = 0.8 - 2|x|): each a triangle of legs 0.1 and 0.2 at (+-0.3, 0.4). */
    s.num_triangles = 0;
    scene_add_triangle(&s, triangle_make(vec3_make(-0.6f, LIGHT_Y, -0.4f), vec3_make(0.6f, LIGHT_Y, -0.4f),
                                         vec3_make(0, LIGHT_Y, 0.8f), m));
    assert_float_near((0.48 - 2 * 0.5 * 0.1 * 0.2) / 0.48, coverage(&s), 1e-6);
    scene_free(&s);
}

/* ---- the light's own triangles ------------------------------------------------------------------ */

static float triangle_area(const triangle *t)
{
    return 0.5f * vec3_length(vec3_cross(vec3_sub(t->p1, t->p0), vec3_sub(t->p2, t->p0)));
}

/* The two triangles tile the light exactly (their area is its, and they cover all of it), glow
 * its radiance on the side it emits to (face and vertex normals), and reflect nothing; whichever
 * way edge_u x edge_v turns. */
static void test_visible_light_add__tiles_the_light_and_glows_on_its_side(void **state)
{
    (void)state;
    for (int flip = 0; flip < 2; flip++) {
        scene s;
        scene_with_light(&s);
        /* flipped, edge_u x edge_v points along the light's direction instead of against it */
        if (flip) s.lights[0].edge_u = vec3_neg(s.lights[0].edge_u);
        int first = visible_light_add(&s, 0);
        assert_int_equal(0, first);
        assert_int_equal(2, s.num_triangles);
        assert_int_equal(1, s.visible_lights);
        /* area and coverage together: no gap, no overlap */
        assert_float_near(0.48, triangle_area(&s.triangles[0]) + triangle_area(&s.triangles[1]), 1e-6);
        assert_float_near(1.0, coverage(&s), 1e-6);
        for (int i = 0; i < 2; i++) {
            const triangle *t = &s.triangles[i];
            vec3 face = vec3_normalize(vec3_cross(vec3_sub(t->p1, t->p0), vec3_sub(t->p2, t->p0)));
            assert_vec3_near(vec3_make(0, -1, 0), face, 1e-6f);
            assert_vec3_near(vec3_make(0, -1, 0), t->n0, 0);
            assert_vec3_near(vec3_make(0, -1, 0), t->n2, 0);
            const material *m = &s.materials[t->material];
            assert_rgb_near(rgb_gray(10), m->Le, 0);
            assert_rgb_near(rgb_gray(0), m->albedo, 0);
        }
        scene_free(&s);
    }
}

/* ---- the loader ----------------------------------------------------------------------------------- */

#define VALID "tests/data/valid/"

static void load(const char *path, scene *s, warn_log *w)
{
    pl_diag d = warn_log_diag(w);
    if (dae_load(path, s, &d) != PL_OK) fail_msg("%s: %s", path, d.error);
}

/* The second assignment's box, its quad commented out: the light becomes two triangles after the
 * box's ten, and the status line says so. Every file with its quad keeps its triangles as they are:
 * pathlab's own scenes and a course file of the first assignment's kind. */
static void test_dae_load__makes_visible_only_the_lights_no_mesh_covers(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load(VALID "cs184_cbspheres_hw2_like.dae", &s, &w);
    assert_int_equal(1, s.visible_lights);
    /* the box's five quads, then the light's two triangles, which cover it whole */
    assert_int_equal(12, s.num_triangles);
    assert_float_near(1.0, visible_light_coverage(&s, &s.lights[0], s.num_triangles), 1e-6);
    assert_rgb_near(rgb_gray(10), s.materials[s.triangles[10].material].Le, 0);
    char line[256];
    visible_light_status_line(&s, line, sizeof line);
    if (!strstr(line, "1 area light made visible")) fail_msg("status line: %s", line);
    scene_free(&s);

    static const char *covered[] = {"scenes/cornell_empty.dae", "scenes/cornell_spheres.dae", "scenes/cornell_bunny.dae",
                                    "scenes/cornell_grazing.dae", "scenes/cornell_two_lights.dae",
                                    "scenes/cornell_mirror_glass.dae", "scenes/cornell_microfacet.dae",
                                    "scenes/analytic/furnace.dae", VALID "cs184_camera_off_axis.dae"};
    for (size_t k = 0; k < sizeof covered / sizeof covered[0]; k++) {
        load(covered[k], &s, &w);
        if (s.visible_lights != 0) fail_msg("%s: %d lights made visible under its own quads", covered[k], s.visible_lights);
        visible_light_status_line(&s, line, sizeof line);
        assert_string_equal("", line);
        scene_free(&s);
    }
}

/* A quad over half the light: the light is made visible whole, as CS184's framework makes every
 * area light, with one warning naming the light's line. */
static void test_dae_load__warns_about_a_partly_covered_light(void **state)
{
    (void)state;
    char *text;
    size_t len;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all(VALID "cs184_camera_off_axis.dae", "scene", 1 << 20, &text, &len, &d));
    /* The quad's corners run from -0.5 to 0.5 in its own x: move its left edge to the middle. */
    const char *quad = "-.5 -.5 0  .5 -.5 0  .5 .5 0  -.5 .5 0";
    char *at = strstr(text, quad);
    assert_non_null(at);
    memcpy(at, "0.0 -.5 0  .5 -.5 0  .5 .5 0  0.0 .5 0", strlen(quad));
    scene s;
    warn_log w;
    d = warn_log_diag(&w);
    assert_int_equal(PL_OK, dae_load_memory(text, len, "half.dae", &s, &d));
    free(text);
    assert_int_equal(1, s.visible_lights);
    assert_int_equal(1, warn_log_count(&w, "cover 50% of this area light"));
    /* located: the message's line starts with the file's name and a line number */
    const char *found = strstr(w.all, "cover 50%"), *line = found;
    while (line > w.all && line[-1] != '\n') line--;
    if (strncmp(line, "half.dae:", 9) != 0) fail_msg("not located: %.*s", (int)(found - line) + 9, line);
    scene_free(&s);
}

/* A document holding one CGL area light under the node matrix given, and nothing else. */
static char *lone_light(const char *matrix, size_t *len)
{
    static const char fmt[] =
        "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
        "<library_lights><light id=\"l\"><extra><technique profile=\"CGL\"><area><color>10 10 10</color></area>"
        "</technique></extra></light></library_lights>\n"
        "<library_visual_scenes><visual_scene id=\"vs\"><node><matrix>%s</matrix>\n"
        "<instance_light url=\"#l\"/></node></visual_scene></library_visual_scenes>\n"
        "<scene><instance_visual_scene url=\"#vs\"/></scene></COLLADA>\n";
    char *text = malloc(sizeof fmt + strlen(matrix));
    assert_non_null(text);
    *len = (size_t)sprintf(text, fmt, matrix);
    return text;
}

/* The triangles a light becomes obey the loader's caps, refused at the light's <instance_light>:
 * the primitive limit, and coordinates within +-1e18. */
static void test_dae_load__a_light_made_visible_keeps_the_caps(void **state)
{
    (void)state;
    size_t len;
    scene s;
    pl_diag d = pl_diag_default();
    dae_limits one = dae_limits_default();
    one.max_primitives = 1;
    char *text = lone_light("0.6 0 0 0  0 0.8 0 0  0 0 1 1.49  0 0 0 1", &len);
    /* the document has no primitive of its own: the light's two are what the limit of one refuses */
    assert_int_equal(PL_ERR_INVALID, dae_load_memory_limited(text, len, "s.dae", &one, &s, &d));
    if (!strstr(d.error, "s.dae:4: <instance_light>: the scene would hold more than 1 primitives"))
        fail_msg("%s", d.error);
    assert_int_equal(PL_OK, dae_load_memory(text, len, "s.dae", &s, &d));
    assert_int_equal(2, s.num_triangles);
    scene_free(&s);
    free(text);
    text = lone_light("0.6 0 0 0  0 0.8 0 0  0 0 1 1e19  0 0 0 1", &len);
    assert_int_equal(PL_ERR_INVALID, dae_load_memory(text, len, "s.dae", &s, &d));
    if (!strstr(d.error, "s.dae:4: <instance_light>: a corner of the area light made visible is"))
        fail_msg("%s", d.error);
    free(text);
}

/* ---- renders ------------------------------------------------------------------------------------ */

/* The fixture as the first assignment's copy would be: the quad's node not commented out. */
static char *with_the_quad(size_t *len)
{
    char *text;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, file_read_all(VALID "cs184_cbspheres_hw2_like.dae", "scene", 1 << 20, &text, &len[0], &d));
    char *open = strstr(text, "<!--\n      <node id=\"Light\""), *close = open ? strstr(open, "-->") : NULL;
    assert_non_null(close);
    memset(open, ' ', 4);  /* blanked, so the document keeps its length and lines */
    memset(close, ' ', 3);
    return text;
}

/* A 64x48 render of s from pathlab's Cornell camera (the light in the frame), -m max_depth. */
static void render_box(scene *s, int max_depth, bool hemisphere, image *out)
{
    s->camera.camera_to_world = mat4_lookat(vec3_make(0, 0.75f, 3.1f), vec3_make(0, 0.75f, 0), vec3_make(0, 1, 0));
    s->camera.position = vec3_make(0, 0.75f, 3.1f);
    options o = options_default();
    o.framing = FRAMING_LITERAL;
    o.width = 64, o.height = 48, o.spp = 16, o.max_depth = max_depth, o.hemisphere = hemisphere, o.threads = 2;
    accel a;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, accel_build(&a, s, true, 4, &d));
    render_ctx ctx;
    render_ctx_init(&ctx, s, &a, &o);
    assert_int_equal(PL_OK, image_alloc(out, o.width, o.height));
    render_stats st;
    assert_int_equal(PL_OK, render_image(&ctx, out, NULL, &st, &d));
    accel_free(&a);
}

/* The largest mean of an 8x8 block's change, relative, between a and b; and the brightest pixel. */
static double block_change(const image *a, const image *b, float *brightest)
{
    double worst = 0;
    *brightest = 0;
    for (int by = 0; by < a->height; by += 8)
        for (int bx = 0; bx < a->width; bx += 8) {
            double sa = 0, sb = 0;
            for (int y = by; y < by + 8; y++)
                for (int x = bx; x < bx + 8; x++) {
                    rgb p = a->pixels[y * a->width + x], q = b->pixels[y * b->width + x];
                    sa += p.r + p.g + p.b, sb += q.r + q.g + q.b;
                    *brightest = fmaxf(*brightest, fmaxf(q.r, fmaxf(q.g, q.b)));
                }
            double change = fabs(sb - sa) / fmax(sa, 1e-3);
            if (change > worst) worst = change;
        }
    return worst;
}

/* The second assignment's box renders as the first assignment's, whose quad shows the light: seen
 * directly (-m 0), in direct light, in the mirror and through the glass (-m 5), and by hemisphere
 * sampling (-H), where the light is found only by hitting it. Twice the light (a second emitter
 * counted where the quad is) or none (a pure light source) changes blocks by far more. */
static void test_render__a_light_made_visible_renders_as_the_quad_over_it_would(void **state)
{
    (void)state;
    size_t len;
    char *text = with_the_quad(&len);
    scene quad, made;
    warn_log w;
    pl_diag dw = warn_log_diag(&w);
    assert_int_equal(PL_OK, dae_load_memory(text, len, "quad.dae", &quad, &dw));
    free(text);
    load(VALID "cs184_cbspheres_hw2_like.dae", &made, &w);
    assert_int_equal(0, quad.visible_lights);
    /* -m 0: the light seen; -m 1: direct light and the mirror; -m 5: the glass and its caustic;
     * -H: light found only by rays that hit an emitter */
    static const struct { int depth; bool hemisphere; } runs[] = {{0, false}, {1, false}, {5, false}, {1, true}};
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        image a, b;
        render_box(&quad, runs[k].depth, runs[k].hemisphere, &a);
        render_box(&made, runs[k].depth, runs[k].hemisphere, &b);
        if (pl_todo_count() > 0) {  /* the student tree: the parts' own tests report their stubs */
            image_free(&a), image_free(&b), scene_free(&quad), scene_free(&made);
            skip();
        }
        float brightest;
        double change = block_change(&a, &b, &brightest);
        if (change > 0.01 || fabsf(brightest - 10.0f) > 1e-3f)
            fail_msg("-m %d%s: an 8x8 block changed by %.2f%% from the box with its quad; the brightest pixel is "
                     "%.4f, expected the light's 10", runs[k].depth, runs[k].hemisphere ? " -H" : "", 100 * change,
                     brightest);
        image_free(&a);
        image_free(&b);
    }
    scene_free(&quad);
    scene_free(&made);
}

int visible_light_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_visible_light_coverage__is_the_share_of_the_light_emissive_triangles_lie_over),
        cmocka_unit_test(test_visible_light_coverage__clips_triangles_to_the_light),
        cmocka_unit_test(test_visible_light_add__tiles_the_light_and_glows_on_its_side),
        cmocka_unit_test(test_dae_load__makes_visible_only_the_lights_no_mesh_covers),
        cmocka_unit_test(test_dae_load__warns_about_a_partly_covered_light),
        cmocka_unit_test(test_dae_load__a_light_made_visible_keeps_the_caps),
        cmocka_unit_test(test_render__a_light_made_visible_renders_as_the_quad_over_it_would),
    };
    return cmocka_run_group_tests_name("visible_light", tests, NULL, NULL);
}
