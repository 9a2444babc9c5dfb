/* Test machinery: not part of any assignment. --trace-pixel and --crop (framework/trace.h): the
 * traced pixel is the rendered pixel bit for bit in every configuration and at any thread count,
 * a cropped render is the same pixels as the whole one, and the JSON trace follows its schema. */
#include "../common/test.h"
#include "../../framework/trace.h"
#include "../../framework/dae.h"
#include "../../framework/exr.h"
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* A scene, its BVH and a render context over given options. */
typedef struct {
    scene s;
    accel a;
    options o;
    render_ctx ctx;
} world;

static void world_open(world *w, const char *path, options o)
{
    pl_diag d = pl_diag_default();
    if (dae_load(path, &w->s, &d) != PL_OK) fail_msg("%s: %s", path, d.error);
    assert_int_equal(PL_OK, accel_build(&w->a, &w->s, true, 4, &d));
    w->o = o;
    render_ctx_init(&w->ctx, &w->s, &w->a, &w->o);
}

static void world_close(world *w)
{
    accel_free(&w->a);
    scene_free(&w->s);
}

/* The configurations of every part: normals (1-2), direct with -H and with light sampling (3),
 * global with and without -o 0 (4), adaptive (5). */
static options config(int which)
{
    options o = options_default();
    o.width = 24, o.height = 18, o.spp = 6, o.light_samples = 2, o.seed = 7;
    switch (which) {
    case 0: o.normals = true; break;
    case 1: o.hemisphere = true; break;
    case 2: break;
    case 3: o.max_depth = 5; break;
    case 4: o.max_depth = 4, o.accumulate = false; break;
    default: o.max_depth = 3, o.adaptive = true, o.adaptive_batch = 4, o.spp = 24, o.adaptive_tol = 0.2f; break;
    }
    return o;
}

static film render_whole(world *w, int threads)
{
    film f;
    pl_diag d = pl_diag_default();
    w->o.threads = threads;
    assert_int_equal(PL_OK, film_alloc(&f, w->o.width, w->o.height));
    assert_int_equal(PL_OK, render_film(&w->ctx, &f, NULL, &d));
    return f;
}

static trace_result trace_quietly(world *w, int x, int y, bool json)
{
    FILE *sink = fopen("/dev/null", "w");
    assert_non_null(sink);
    trace_request req = {x, y, 0, -1, json};
    trace_result res;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, trace_pixel(&w->ctx, &req, sink, &res, &d));
    fclose(sink);
    return res;
}

static void test_trace_pixel__equals_the_rendered_pixel_bit_for_bit(void **state)
{
    const char *scenes[] = {"scenes/cornell_spheres.dae", "scenes/lights_point_dir.dae", "scenes/cornell_empty.dae"};
    rng pick = rng_seeded(19, 0);  /* fixed seed: the same "random" pixels every run */
    for (int sc = 0; sc < 3; sc++)
        for (int c = 0; c < 6; c++) {
            world w;
            world_open(&w, scenes[sc], config(c));
            film f = render_whole(&w, 1 + (c % 3));  /* -t 1, 2 and 3 */
            for (int k = 0; k < 4; k++) {
                int x = (int)(rng_uniform(&pick) * w.o.width), y = (int)(rng_uniform(&pick) * w.o.height);
                trace_result r = trace_quietly(&w, x, y, k == 0);
                const film_pixel *p = &f.pixels[(w.o.height - 1 - y) * w.o.width + x];
                if (memcmp(&r.pixel, p, sizeof *p) != 0)
                    fail_msg("%s, configuration %d, pixel (%d, %d): traced %u samples, mean %g; rendered %u, mean %g",
                             scenes[sc], c, x, y, r.pixel.n, film_pixel_mean(&r.pixel, 3), p->n, film_pixel_mean(p, 3));
            }
            film_free(&f);
            world_close(&w);
        }
}

static void test_crop__same_pixels_as_the_whole_image(void **state)
{
    world w;
    world_open(&w, "scenes/cornell_spheres.dae", config(3));
    film whole = render_whole(&w, 2);
    w.o.crop = true, w.o.crop_x0 = 5, w.o.crop_y0 = 3, w.o.crop_x1 = 22, w.o.crop_y1 = 11, w.o.threads = 3;
    render_ctx_init(&w.ctx, &w.s, &w.a, &w.o);
    film part;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, film_alloc(&part, 17, 8));
    assert_int_equal(PL_OK, render_film(&w.ctx, &part, NULL, &d));
    for (int y = 3; y < 11; y++)
        for (int x = 5; x < 22; x++) {
            const film_pixel *a = &whole.pixels[(w.o.height - 1 - y) * w.o.width + x];
            const film_pixel *b = &part.pixels[(10 - y) * 17 + (x - 5)];
            if (memcmp(a, b, sizeof *a) != 0) fail_msg("pixel (%d, %d) differs in the crop", x, y);
        }
    film_free(&part);
    film_free(&whole);
    world_close(&w);
}

/* The program end to end: a --crop render's EXR film holds the whole render's pixels. */
static void test_pathtracer__crop_exr_matches_the_whole_exr(void **state)
{
    const char *common = "bin/pathtracer -q -s 4 -m 3 -r 32 24 --seed 3 scenes/cornell_spheres.dae";
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s -t 2 -f /tmp/pathlab-trace-whole.exr >/dev/null", common);
    assert_int_equal(0, system(cmd));
    snprintf(cmd, sizeof cmd, "%s -t 3 --crop 7 2 19 21 -f /tmp/pathlab-trace-crop.exr >/dev/null", common);
    assert_int_equal(0, system(cmd));
    film whole, part;
    exr_info info;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, exr_read("/tmp/pathlab-trace-whole.exr", &whole, &info, &d));
    assert_int_equal(PL_OK, exr_read("/tmp/pathlab-trace-crop.exr", &part, &info, &d));
    assert_int_equal(12, part.width);
    assert_int_equal(19, part.height);
    for (int y = 2; y < 21; y++)
        for (int x = 7; x < 19; x++)
            if (memcmp(&whole.pixels[(23 - y) * 32 + x], &part.pixels[(20 - y) * 12 + (x - 7)], sizeof(film_pixel)) != 0)
                fail_msg("pixel (%d, %d) of the --crop EXR differs from the whole render's", x, y);
    film_free(&whole);
    film_free(&part);
}

/* The program end to end, as a student would check it: the mean a JSON trace prints is the EXR's
 * pixel to the bit (JSON reals are printed with enough digits to read back the same float). */
static void test_pathtracer__traced_mean_is_the_exr_pixel(void **state)
{
    const char *common = "bin/pathtracer -q -s 8 -l 2 -m 4 -r 40 30 --seed 11 scenes/cornell_spheres.dae";
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s -t 3 -f /tmp/pathlab-trace-render.exr >/dev/null", common);
    assert_int_equal(0, system(cmd));
    film f;
    exr_info info;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, exr_read("/tmp/pathlab-trace-render.exr", &f, &info, &d));
    int pixels[][2] = {{3, 27}, {20, 15}, {37, 2}};
    for (int k = 0; k < 3; k++) {
        int x = pixels[k][0], y = pixels[k][1];
        snprintf(cmd, sizeof cmd, "%s --trace-pixel %d %d --trace-format json > /tmp/pathlab-trace.json", common, x, y);
        assert_int_equal(0, system(cmd));
        json_error_t err;
        json_t *doc = json_load_file("/tmp/pathlab-trace.json", 0, &err);
        if (!doc) fail_msg("the JSON trace does not parse: %s", err.text);
        rgb want = film_pixel_rgb(&f.pixels[(29 - y) * 40 + x]);
        json_t *mean = json_object_get(doc, "mean");
        rgb got = rgb_make((float)json_number_value(json_array_get(mean, 0)), (float)json_number_value(json_array_get(mean, 1)),
                           (float)json_number_value(json_array_get(mean, 2)));
        if (memcmp(&want, &got, sizeof want) != 0)
            fail_msg("pixel (%d, %d): the trace says %.9g %.9g %.9g, the EXR %.9g %.9g %.9g", x, y, got.r, got.g, got.b,
                     want.r, want.g, want.b);
        json_decref(doc);
    }
    film_free(&f);
}

/* ---- a JSON Schema validator for the keywords framework/trace.schema.json uses --------------- */

static bool type_is(const json_t *v, const char *type)
{
    if (!strcmp(type, "object")) return json_is_object(v);
    if (!strcmp(type, "array")) return json_is_array(v);
    if (!strcmp(type, "string")) return json_is_string(v);
    if (!strcmp(type, "integer")) return json_is_integer(v);
    if (!strcmp(type, "number")) return json_is_number(v);
    if (!strcmp(type, "boolean")) return json_is_boolean(v);
    fail_msg("the schema names a type this validator does not know: %s", type);
    return false;
}

static bool type_ok(const json_t *v, const json_t *type)
{
    if (json_is_string(type)) return type_is(v, json_string_value(type));
    size_t i;
    json_t *t;
    json_array_foreach(type, i, t) if (type_is(v, json_string_value(t))) return true;
    return false;
}

static char why[400];  /* what validate found wrong */
#define BAD(...) return snprintf(why, sizeof why, __VA_ARGS__), false

/* False, with why naming the JSON path, at the first value that breaks the schema. */
static bool validate(const json_t *v, const json_t *schema, const json_t *root, const char *path)
{
    const json_t *ref = json_object_get(schema, "$ref");
    if (ref) {
        const char *name = json_string_value(ref) + strlen("#/$defs/");
        schema = json_object_get(json_object_get(root, "$defs"), name);
        assert_non_null(schema);
    }
    const json_t *type = json_object_get(schema, "type"), *en = json_object_get(schema, "enum");
    if (type && !type_ok(v, type)) BAD("%s: wrong type", path);
    if (en) {
        bool found = false;
        size_t i;
        json_t *e;
        json_array_foreach(en, i, e) found |= json_equal(e, v);
        if (!found) BAD("%s: %s is not one of the schema's values", path, json_string_value(v));
    }
    char sub[256];
    if (json_is_object(v)) {
        size_t i;
        json_t *r;
        json_array_foreach(json_object_get(schema, "required"), i, r)
            if (!json_object_get(v, json_string_value(r))) BAD("%s: no \"%s\"", path, json_string_value(r));
        const char *key;
        json_t *field;
        json_object_foreach((json_t *)v, key, field) {
            const json_t *sch = json_object_get(json_object_get(schema, "properties"), key);
            if (!sch && json_is_false(json_object_get(schema, "additionalProperties"))) BAD("%s: unexpected \"%s\"", path, key);
            snprintf(sub, sizeof sub, "%s.%s", path, key);
            if (sch && !validate(field, sch, root, sub)) return false;
        }
    }
    if (json_is_array(v)) {
        const json_t *lo = json_object_get(schema, "minItems"), *hi = json_object_get(schema, "maxItems");
        if (lo && json_array_size(v) < (size_t)json_integer_value(lo)) BAD("%s: too few items", path);
        if (hi && json_array_size(v) > (size_t)json_integer_value(hi)) BAD("%s: too many items", path);
        size_t i;
        json_t *item;
        json_array_foreach(v, i, item) {
            snprintf(sub, sizeof sub, "%s[%zu]", path, i);
            if (json_object_get(schema, "items") && !validate(item, json_object_get(schema, "items"), root, sub)) return false;
        }
    }
    return true;
}

static json_t *trace_json(world *w, int x, int y)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    trace_request req = {x, y, 0, -1, true};
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, trace_pixel(&w->ctx, &req, f, NULL, &d));
    rewind(f);
    json_error_t err;
    json_t *doc = json_loadf(f, 0, &err);
    fclose(f);
    if (!doc) fail_msg("the JSON trace does not parse: line %d: %s", err.line, err.text);
    return doc;
}

static void test_trace_json__follows_its_schema(void **state)
{
    json_error_t err;
    json_t *schema = json_load_file("framework/trace.schema.json", 0, &err);
    if (!schema) fail_msg("framework/trace.schema.json: line %d: %s", err.line, err.text);
    for (int c = 0; c < 7; c++) {  /* 6: directional lights, at infinite distance ("inf") */
        world w;
        world_open(&w, c < 6 ? "scenes/cornell_spheres.dae" : "scenes/lights_point_dir.dae", config(c < 6 ? c : 2));
        json_t *doc = trace_json(&w, 12, 9);
        if (!validate(doc, schema, schema, "trace")) fail_msg("configuration %d: %s", c, why);
        assert_true(json_array_size(json_object_get(doc, "samples")) > 0);
        json_decref(doc);
        world_close(&w);
    }
    /* The validator itself: a trace with a field the schema does not know, or a wrong type, fails. */
    json_t *bad = json_pack("{s:s}", "format", "pathlab-trace-1");
    json_t *bad_event = json_pack("{s:s, s:s, s:s}", "kind", "hit", "level", "one", "text", "x");
    json_t *event_schema = json_object_get(json_object_get(schema, "$defs"), "event");
    assert_false(validate(bad, schema, schema, "bad"));
    assert_false(validate(bad_event, event_schema, schema, "bad_event"));
    json_decref(bad);
    json_decref(bad_event);
    json_decref(schema);
}

/* Every bad --trace-* or --crop flag: exit status 2 and a message naming the flag. */
static void test_pathtracer__bad_trace_and_crop_flags_exit_2(void **state)
{
    const char *flags[][2] = {
        {"--trace-pixel 64 0", "--trace-pixel 64 0: outside the 64x48 image"},
        {"--trace-pixel 3", "--trace-pixel Y: expected an integer"},
        {"--trace-pixel 1 1 --trace-sample 5:2", "--trace-sample: expected K or A:B"},
        {"--trace-pixel 1 1 --trace-format xml", "--trace-format: expected text or json"},
        {"--trace-sample 2", "--trace-sample and --trace-format need --trace-pixel"},
        {"--crop 10 10 5 20", "--crop 10 10 5 20: expected X0 < X1"},
        {"--crop 0 0 65 48", "--crop 0 0 65 48: expected X0 < X1 <= 64"},
        {"--crop 0 0 8 8 --heatmap /tmp/pathlab-trace-heat.png", "--crop: --heatmap draws the whole image"},
    };
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++) {
        char cmd[512], err[512] = "";
        snprintf(cmd, sizeof cmd, "bin/pathtracer -r 64 48 %s scenes/cornell_spheres.dae 2>&1 >/dev/null", flags[i][0]);
        FILE *p = popen(cmd, "r");
        assert_non_null(p);
        size_t n = fread(err, 1, sizeof err - 1, p);
        err[n] = '\0';
        int status = pclose(p);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 2) fail_msg("'%s' exited with %d, expected 2", cmd, WEXITSTATUS(status));
        if (!strstr(err, flags[i][1])) fail_msg("'%s' said '%s', expected it to say '%s'", cmd, err, flags[i][1]);
    }
}

/* The traces the handouts show are what the solution prints today (handout/traces.sh). Only in the
 * course's tree: a student's own correct code may round differently in the last printed digit. */
static void test_handout__traces_are_current(void **state)
{
    if (access("course", F_OK) != 0) skip();
    int status = system("sh handout/traces.sh --check >/dev/null 2>&1");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail_msg("a handout's trace is stale: run sh handout/traces.sh --check to see which, --write to renew them");
}

int trace_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trace_pixel__equals_the_rendered_pixel_bit_for_bit),
        cmocka_unit_test(test_crop__same_pixels_as_the_whole_image),
        cmocka_unit_test(test_pathtracer__crop_exr_matches_the_whole_exr),
        cmocka_unit_test(test_trace_json__follows_its_schema),
        cmocka_unit_test(test_pathtracer__traced_mean_is_the_exr_pixel),
        cmocka_unit_test(test_pathtracer__bad_trace_and_crop_flags_exit_2),
        cmocka_unit_test(test_handout__traces_are_current),
    };
    return cmocka_run_group_tests_name("trace", tests, NULL, NULL);
}
