/* Test machinery: not part of any assignment.
 * The COLLADA loader: what each feature loads to (files in tests/data/valid, each stating its
 * expected values in its first comment, plus small documents built here), and how every malformed
 * input is rejected (tests/data/broken: each file's first line says the status, line and message). */
#include "../common/test.h"
#include "../common/warn_log.h"
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../../framework/dae.h"
#include "../../framework/material.h"
#include "../../framework/rng.h"

#define VALID "tests/data/valid/"
#define BROKEN "tests/data/broken/"
#define EPS 1e-5f

/* ---- helpers ----------------------------------------------------------------------------- */

/* Loads a file that must load; fails the test with the loader's message otherwise. */
static void load_ok(const char *path, scene *s, warn_log *w)
{
    pl_diag d = warn_log_diag(w);
    pl_status st = dae_load(path, s, &d);
    if (st != PL_OK) fail_msg("%s: %s: %s", path, pl_status_name(st), d.error);
}

/* printf into a new string (asprintf is GNU's and BSD's, not POSIX). Caller frees. */
static char *format(const char *fmt, ...) CMOCKA_PRINTF_ATTRIBUTE(1, 2);
static char *format(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(NULL, 0, fmt, args);
    va_end(args);
    assert_true(n >= 0);
    char *text = malloc((size_t)n + 1);
    assert_non_null(text);
    va_start(args, fmt);
    vsnprintf(text, (size_t)n + 1, fmt, args);
    va_end(args);
    return text;
}

/* A whole document around the given libraries and visual-scene nodes. Caller frees. */
static char *document(const char *up_axis, const char *libraries, const char *nodes)
{
    return format("<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
                  "<asset><up_axis>%s</up_axis></asset>\n%s\n"
                  "<library_visual_scenes><visual_scene id=\"vs\">\n%s\n</visual_scene></library_visual_scenes>\n"
                  "<scene><instance_visual_scene url=\"#vs\"/></scene></COLLADA>\n",
                  up_axis, libraries, nodes);
}

static void load_document_ok(const char *up_axis, const char *libraries, const char *nodes, scene *s,
                             warn_log *w)
{
    char *text = document(up_axis, libraries, nodes);
    pl_diag d = warn_log_diag(w);
    pl_status st = dae_load_memory(text, strlen(text), "inline.dae", s, &d);
    free(text);
    if (st != PL_OK) fail_msg("inline document: %s: %s", pl_status_name(st), d.error);
}

static void assert_scene_empty(const scene *s)
{
    assert_int_equal(0, s->num_triangles);
    assert_int_equal(0, s->num_spheres);
    assert_int_equal(0, s->num_lights);
    assert_int_equal(0, s->num_materials);
    assert_null(s->triangles);
    assert_null(s->spheres);
    assert_null(s->materials);
    assert_null(s->lights);
    assert_false(s->has_camera);
}

static const char TRIANGLE_GEOMETRY[] =
    "<library_geometries><geometry id=\"tri\"><mesh>"
    "<source id=\"tri-pos\"><float_array id=\"tri-pos-a\" count=\"9\">0 0 0  1 0 0  0 1 0</float_array>"
    "<technique_common><accessor source=\"#tri-pos-a\" count=\"3\" stride=\"3\"/></technique_common></source>"
    "<vertices id=\"tri-v\"><input semantic=\"POSITION\" source=\"#tri-pos\"/></vertices>"
    "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#tri-v\" offset=\"0\"/><p>0 1 2</p></triangles>"
    "</mesh></geometry></library_geometries>";

/* Numbers are read as strtof reads them, bit for bit, whatever their form: the loader's fast path
 * for short decimals must agree with the C library on every one (both round correctly). */
static void test_dae_load__numbers_match_strtof_exactly(void **state)
{
    (void)state;
    enum { TRIS = 400, NUMS = TRIS * 9 };
    static const char *const forms[] = {"%.0f", "%.1f", "%.3f", "%.6f", "%.7f", "%.9f", "%.10f", "%.12f", "%g", "%.8e"};
    char (*text)[40] = malloc(sizeof *text * NUMS);
    assert_non_null(text);
    rng g = rng_seeded(2024, 7);
    size_t len = 0;
    for (int i = 0; i < NUMS; i++) {
        double scale = pow(10.0, (double)(rng_u32(&g) % 12) - 6.0);
        double v = (rng_uniform(&g) * 2.0 - 1.0) * scale * 10.0;
        snprintf(text[i], sizeof text[i], forms[rng_u32(&g) % (sizeof forms / sizeof forms[0])], v);
        len += strlen(text[i]) + 1;
    }
    char *floats = malloc(len + 1), *at = floats;
    assert_non_null(floats);
    for (int i = 0; i < NUMS; i++) at += sprintf(at, "%s ", text[i]);
    char *p = malloc(TRIS * 3 * 8 + 1);
    assert_non_null(p);
    at = p;
    for (int i = 0; i < TRIS * 3; i++) at += sprintf(at, "%d ", i);
    char *lib = format("<library_geometries><geometry id=\"g\"><mesh><source id=\"s\">"
                       "<float_array id=\"a\" count=\"%d\">%s</float_array><technique_common>"
                       "<accessor source=\"#a\" count=\"%d\" stride=\"3\"/></technique_common></source>"
                       "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#s\"/></vertices>"
                       "<triangles count=\"%d\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/>"
                       "<p>%s</p></triangles></mesh></geometry></library_geometries>",
                       NUMS, floats, TRIS * 3, TRIS, p);
    char *node = format("<node id=\"n\"><instance_geometry url=\"#g\"/></node>");
    scene sc;
    warn_log w = {0};
    load_document_ok("Y_UP", lib, node, &sc, &w);
    assert_int_equal(TRIS, sc.num_triangles);
    int mismatches = 0;
    for (int t = 0; t < TRIS; t++) {
        const vec3 *corners[3] = {&sc.triangles[t].p0, &sc.triangles[t].p1, &sc.triangles[t].p2};
        for (int k = 0; k < 9; k++) {
            float got = k % 3 == 0 ? corners[k / 3]->x : k % 3 == 1 ? corners[k / 3]->y : corners[k / 3]->z;
            float want = strtof(text[t * 9 + k], NULL);
            if (got != want && mismatches++ < 5)  /* value, not bits: the transform makes -0 +0 */
                print_error("'%s': loader %a, strtof %a\n", text[t * 9 + k], got, want);
        }
    }
    assert_int_equal(0, mismatches);
    scene_free(&sc);
    free(lib);
    free(node);
    free(p);
    free(floats);
    free(text);
}

/* ---- errors ------------------------------------------------------------------------------ */

static void test_dae_load__missing_file_is_io_error_naming_it(void **state)
{
    (void)state;
    scene s;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, dae_load(BROKEN "no_such_file.dae", &s, &d));
    assert_non_null(strstr(d.error, BROKEN "no_such_file.dae"));
    assert_scene_empty(&s);
}

/* The instance cap (1,000,000 by default) is a limit, not a wall: the message names the flag that
 * raises it, and a raised cap loads the 101^3-node fan-out of the broken corpus. */
static void test_dae_load__instance_cap_names_its_flag_and_can_be_raised(void **state)
{
    (void)state;
    scene s;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_INVALID, dae_load(BROKEN "instance_fanout_nodes.dae", &s, &d));
    if (!strstr(d.error, "--max-instances N raises it")) fail_msg("the message does not name the flag: %s", d.error);
    dae_limits limits = dae_limits_default();
    limits.max_instances = 2000000;
    if (dae_load_limited(BROKEN "instance_fanout_nodes.dae", &limits, &s, &d) != PL_OK) fail_msg("%s", d.error);
    scene_free(&s);
}

/* Reads "<!-- expect: STATUS LINE MESSAGE -->" from the file's first line. */
static bool read_expectation(const char *path, pl_status *status, long *line, char *message, size_t size)
{
    char first[1024], word[16];
    FILE *f = fopen(path, "r");
    if (!f) return false;
    bool ok = fgets(first, sizeof first, f) != NULL;
    fclose(f);
    int used = 0;
    if (!ok || sscanf(first, "<!-- expect: %15s %ld %n", word, line, &used) != 2 || used == 0) return false;
    const char *msg = first + used, *end = strstr(msg, " -->");
    if (!end || (size_t)(end - msg) >= size) return false;
    snprintf(message, size, "%.*s", (int)(end - msg), msg);
    if (strcmp(word, "PARSE") == 0) *status = PL_ERR_PARSE;
    else if (strcmp(word, "INVALID") == 0) *status = PL_ERR_INVALID;
    else return false;
    return true;
}

static int compare_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void test_dae_load__every_broken_file_is_rejected_with_file_line_and_element(void **state)
{
    (void)state;
    DIR *dir = opendir(BROKEN);
    assert_non_null(dir);
    char *names[256];
    int n = 0;
    for (struct dirent *e; (e = readdir(dir)) && n < 256;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && strcmp(e->d_name + len - 4, ".dae") == 0) names[n++] = strdup(e->d_name);
    }
    closedir(dir);
    qsort(names, (size_t)n, sizeof *names, compare_names);
    int failures = 0;
    for (int i = 0; i < n; i++) {
        char path[512], message[512], want[1100];
        snprintf(path, sizeof path, BROKEN "%s", names[i]);
        pl_status expected;
        long line;
        if (!read_expectation(path, &expected, &line, message, sizeof message)) {
            print_error("%s: first line is not <!-- expect: STATUS LINE MESSAGE -->\n", path);
            failures++;
            continue;
        }
        scene s;
        warn_log w;
        pl_diag d = warn_log_diag(&w);
        pl_status st = dae_load(path, &s, &d);
        snprintf(want, sizeof want, "%s:%ld: %s", path, line, message);
        if (st != expected || strncmp(d.error, want, strlen(want)) != 0) {
            print_error("%s:\n  expected %s: %s...\n  got      %s: %s\n", path, pl_status_name(expected), want,
                        pl_status_name(st), d.error);
            failures++;
        }
        if (s.num_triangles || s.num_spheres || s.num_lights || s.num_materials || s.has_camera) {
            print_error("%s: the scene is not empty after a failed load\n", path);
            failures++;
        }
        free(names[i]);
    }
    assert_true(n >= 50);  /* the corpus is all there */
    assert_int_equal(0, failures);
}

static char *read_whole(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)size + 1);
    assert_non_null(buf);
    assert_int_equal((size_t)size, fread(buf, 1, (size_t)size, f));
    fclose(f);
    buf[size] = '\0';
    *len = (size_t)size;
    return buf;
}

/* A failed load must say where, and leave nothing behind (ASan checks the leaks). */
static void check_rejected(const char *text, size_t len, const char *name)
{
    scene s;
    warn_log w;
    pl_diag d = warn_log_diag(&w);
    pl_status st = dae_load_memory(text, len, name, &s, &d);
    if (st == PL_OK) fail_msg("%s (%zu bytes) loaded, but it is truncated", name, len);
    assert_int_equal(PL_ERR_PARSE, st);
    assert_int_equal(0, strncmp(d.error, name, strlen(name)));
    assert_scene_empty(&s);
}

static void test_dae_load__truncated_files_are_rejected_at_every_cut(void **state)
{
    (void)state;
    size_t len;
    char *text = read_whole("scenes/cornell_spheres.dae", &len);
    size_t end = strstr(text, "</COLLADA>") - text;  /* cuts inside the root element */
    for (int k = 0; k < 97; k++) check_rejected(text, end * (size_t)k / 97, "cut.dae");
    free(text);
}

static void test_dae_load__random_corruption_never_crashes(void **state)
{
    (void)state;
    size_t len;
    char *original = read_whole("scenes/cornell_spheres.dae", &len);
    char *text = malloc(len);
    assert_non_null(text);
    uint64_t x = 184;  /* fixed seed: the same corruptions every run */
    printf("[ INFO     ] corruption seed 184\n");
    int loaded = 0, rejected = 0;
    for (int round = 0; round < 300; round++) {
        memcpy(text, original, len);
        for (int k = 0; k < 1 + round % 4; k++) {
            x = x * 6364136223846793005u + 1442695040888963407u;
            size_t at = (size_t)(x >> 33) % len;
            text[at] = (char)(x >> 17);
        }
        scene s;
        warn_log w;
        pl_diag d = warn_log_diag(&w);
        pl_status st = dae_load_memory(text, len, "corrupt.dae", &s, &d);
        if (st == PL_OK) {
            loaded++;
            scene_free(&s);
        } else {
            rejected++;
            assert_int_equal(0, strncmp(d.error, "corrupt.dae:", 12));
            assert_scene_empty(&s);
        }
    }
    /* Pure noise, too. */
    for (int round = 0; round < 20; round++) {
        for (size_t i = 0; i < 512; i++) {
            x = x * 6364136223846793005u + 1442695040888963407u;
            text[i] = (char)(x >> 40);
        }
        check_rejected(text, 512, "noise.dae");
    }
    check_rejected("", 0, "empty.dae");
    assert_true(rejected > 0);  /* corruption was actually exercised */
    free(text);
    free(original);
}

/* Line numbers stay exact past 65535 lines (libxml2 needs XML_PARSE_BIG_LINES for that), and a large
 * mesh loads (not timed here: `make bench` and the report time the bunny). */
static void test_dae_load__large_mesh_loads_and_errors_keep_exact_lines(void **state)
{
    (void)state;
    const int side = 151;  /* 151 x 151 grid: 22,801 vertices (one number a line), 45,000 triangles */
    size_t cap = 8u << 20, len = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    long line = 1;
    len += (size_t)snprintf(text + len, cap - len,
                            "<COLLADA><asset><up_axis>Y_UP</up_axis></asset><library_geometries>"
                            "<geometry id=\"g\"><mesh><source id=\"s\"><float_array id=\"a\" count=\"%d\">\n",
                            side * side * 3);
    line++;
    for (int j = 0; j < side; j++)
        for (int i = 0; i < side; i++, line += 3)
            len += (size_t)snprintf(text + len, cap - len, "%d\n0\n%d\n", i, j);
    len += (size_t)snprintf(text + len, cap - len,
                            "</float_array><technique_common><accessor source=\"#a\" count=\"%d\" stride=\"3\"/>"
                            "</technique_common></source><vertices id=\"v\"><input semantic=\"POSITION\" source=\"#s\"/>"
                            "</vertices><triangles count=\"%d\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>\n",
                            side * side, 2 * (side - 1) * (side - 1));
    line++;
    for (int j = 0; j + 1 < side; j++)
        for (int i = 0; i + 1 < side; i++, line++) {
            int a = j * side + i;
            len += (size_t)snprintf(text + len, cap - len, "%d %d %d %d %d %d\n", a, a + side, a + 1, a + 1,
                                    a + side, a + side + 1);
        }
    /* The <p> element starts on the line before the first index line. */
    long p_line = line - (side - 1) * (side - 1) - 1;
    size_t body = len;
    const char *tail = "</p></triangles></mesh></geometry></library_geometries><library_visual_scenes>"
                       "<visual_scene id=\"vs\"><node><instance_geometry url=\"#g\"/></node></visual_scene>"
                       "</library_visual_scenes><scene><instance_visual_scene url=\"#vs\"/></scene></COLLADA>\n";
    len += (size_t)snprintf(text + len, cap - len, "%s", tail);

    scene s;
    warn_log w;
    pl_diag d = warn_log_diag(&w);
    assert_int_equal(PL_OK, dae_load_memory(text, len, "grid.dae", &s, &d));
    assert_int_equal(2 * (side - 1) * (side - 1), s.num_triangles);
    assert_vec3_near(vec3_make(side - 1, 0, side - 1), s.triangles[s.num_triangles - 1].p2, 0);
    scene_free(&s);

    /* One index too many at the very end: the error names <p>'s own line. */
    len = body + (size_t)snprintf(text + body, cap - body, "7 %s", tail);
    assert_int_equal(PL_ERR_PARSE, dae_load_memory(text, len, "grid.dae", &s, &d));
    char want[128];
    snprintf(want, sizeof want, "grid.dae:%ld: <p>: expected %d indices", p_line, 6 * (side - 1) * (side - 1));
    assert_true(p_line > 65535);
    if (strncmp(d.error, want, strlen(want)) != 0) fail_msg("expected '%s...', got '%s'", want, d.error);
    free(text);
}

/* ---- nodes and axes ---------------------------------------------------------------------- */

static void test_dae_transforms__compose_in_document_order_parent_first(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "nested_transforms_y_up.dae", &s, &w);
    assert_int_equal(1, s.num_triangles);
    /* (x, y, z) -> scale 2 -> rotate 90 about z -> translate (1,2,3) -> parent translate (10,0,0) */
    assert_vec3_near(vec3_make(11, 2, 3), s.triangles[0].p0, EPS);
    assert_vec3_near(vec3_make(11, 4, 3), s.triangles[0].p1, EPS);
    assert_vec3_near(vec3_make(9, 2, 3), s.triangles[0].p2, EPS);
    assert_int_equal(0, w.count);
    scene_free(&s);
}

static void test_dae_up_axis__x_up_maps_x_to_world_up(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "x_up.dae", &s, &w);
    /* file (x, y, z) -> world (-y, x, z) */
    assert_vec3_near(vec3_make(-4, 11, 3), s.triangles[0].p1, EPS);
    scene_free(&s);
}

static void test_dae_up_axis__z_up_maps_like_cs184_before_the_node_transform(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_document_ok("Z_UP", TRIANGLE_GEOMETRY,
                     "<node><translate>1 2 3</translate><instance_geometry url=\"#tri\"/></node>", &s, &w);
    /* file (x, y, z) -> world (-x, z, y): vertex (1,0,0) + (1,2,3) = (2,2,3) -> (-2,3,2) */
    assert_vec3_near(vec3_make(-2, 3, 2), s.triangles[0].p1, EPS);
    assert_vec3_near(vec3_make(-1, 3, 2), s.triangles[0].p0, EPS);
    /* the face normal (0,0,1) in the file is world +y */
    assert_vec3_near(vec3_make(0, 1, 0), s.triangles[0].n0, EPS);
    scene_free(&s);
}

static void test_dae_up_axis__cs184_layout_with_y_up_meshes_lands_as_stored(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "cs184_layout.dae", &s, &w);
    assert_int_equal(2, s.num_triangles);
    assert_vec3_near(vec3_make(1, 0, -1), s.triangles[0].p0, EPS);
    assert_vec3_near(vec3_make(-1, 0, 1), s.triangles[0].p1, EPS);
    assert_vec3_near(vec3_make(-1, 0, -1), s.triangles[1].p1, EPS);
    for (int i = 0; i < 2; i++) {
        assert_vec3_near(vec3_make(0, 1, 0), s.triangles[i].n0, EPS);
        assert_vec3_near(vec3_make(0, 1, 0), triangle_make(s.triangles[i].p0, s.triangles[i].p1, s.triangles[i].p2, 0).n0, EPS);
    }
    assert_int_equal(1, s.num_spheres);
    assert_vec3_near(vec3_make(0.4f, 0.3f, 0.3f), s.spheres[0].center, EPS);
    assert_float_near(0.3, s.spheres[0].radius, EPS);
    assert_int_equal(0, w.count);
    scene_free(&s);
}

static void test_dae_instance_node__instances_library_nodes_under_each_parent(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "instance_node.dae", &s, &w);
    assert_int_equal(2, s.num_triangles);
    assert_vec3_near(vec3_make(1, 0, 0), s.triangles[0].p1, EPS);
    assert_vec3_near(vec3_make(6, 0, 0), s.triangles[1].p1, EPS);
    assert_int_equal(0, w.count);
    scene_free(&s);
}

/* ---- meshes ------------------------------------------------------------------------------ */

static void test_dae_mesh__every_primitive_list_is_fan_triangulated(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "polygons_mixed.dae", &s, &w);
    assert_int_equal(11, s.num_triangles);
    /* the pentagon 0 1 2 3 4 (triangles 3..5) fans from its first corner */
    const vec3 v[5] = {vec3_make(0, 0, 0), vec3_make(1, 0, 0), vec3_make(1, 1, 0), vec3_make(0, 1, 0),
                       vec3_make(-0.5f, 0.5f, 0)};
    for (int k = 0; k < 3; k++) {
        const triangle *t = &s.triangles[3 + k];
        assert_vec3_near(v[0], t->p0, EPS);
        assert_vec3_near(v[k + 1], t->p1, EPS);
        assert_vec3_near(v[k + 2], t->p2, EPS);
    }
    /* each list's material symbol picks its binding; <polygons> without one takes the first */
    rgb a = rgb_make(0.1f, 0.2f, 0.3f), b = rgb_make(0.4f, 0.5f, 0.6f);
    for (int i = 0; i < 11; i++) {
        rgb want = (i == 6 || i == 7) ? b : a;
        assert_rgb_near(want, s.materials[s.triangles[i].material].albedo, EPS);
    }
    assert_int_equal(2, s.num_materials);
    scene_free(&s);
}

static void test_dae_mesh__normals_follow_the_inverse_transpose(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "normals.dae", &s, &w);
    assert_int_equal(3, s.num_triangles);
    vec3 want = vec3_normalize(vec3_make(1, 0, 2));
    assert_vec3_near(want, s.triangles[0].n0, EPS);
    assert_vec3_near(want, s.triangles[0].n1, EPS);
    assert_vec3_near(want, s.triangles[0].n2, EPS);
    /* no normals in the file: the face normal of the transformed triangle */
    assert_vec3_near(want, s.triangles[1].n0, EPS);
    assert_vec3_near(want, s.triangles[1].n2, EPS);
    /* a mirroring transform keeps the front side the front */
    assert_vec3_near(vec3_normalize(vec3_make(-1, 0, 1)), s.triangles[2].n0, EPS);
    scene_free(&s);
}

/* ---- lights and camera ------------------------------------------------------------------- */

static void test_dae_lights__every_kind_fills_its_fields(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "lights.dae", &s, &w);
    assert_int_equal(6, s.num_lights);
    const light *l = s.lights;

    assert_int_equal(LIGHT_POINT, l[0].kind);
    assert_vec3_near(vec3_make(1, 2, 3), l[0].position, EPS);
    assert_rgb_near(rgb_make(5, 6, 7), l[0].radiance, EPS);
    assert_float_near(1.0, l[0].attenuation[0], EPS);
    assert_float_near(0.5, l[0].attenuation[1], EPS);
    assert_float_near(0.25, l[0].attenuation[2], EPS);

    assert_int_equal(LIGHT_DIRECTIONAL, l[1].kind);
    assert_vec3_near(vec3_make(0, -1, 0), l[1].direction, EPS);

    assert_int_equal(LIGHT_SPOT, l[2].kind);
    assert_vec3_near(vec3_make(0, 3, 0), l[2].position, EPS);
    assert_vec3_near(vec3_make(0, -1, 0), l[2].direction, EPS);
    assert_float_near(30.0, l[2].falloff_deg, EPS);
    assert_float_near(2.0, l[2].falloff_exp, EPS);
    assert_float_near(1.0, l[2].attenuation[0], EPS);

    assert_int_equal(LIGHT_AMBIENT, l[3].kind);
    assert_rgb_near(rgb_make(0.1f, 0.2f, 0.3f), l[3].radiance, EPS);

    assert_int_equal(LIGHT_AREA, l[4].kind);  /* CGL wins over technique_common's point */
    assert_rgb_near(rgb_gray(10), l[4].radiance, EPS);
    assert_vec3_near(vec3_make(0, 0.5f, 0), l[4].position, EPS);
    assert_vec3_near(vec3_make(0.5f, 0, 0), l[4].edge_u, EPS);
    assert_vec3_near(vec3_make(0, 0, 2), l[4].edge_v, EPS);
    assert_vec3_near(vec3_make(0, 1, 0), l[4].direction, EPS);
    assert_float_near(1.0, l[4].area, EPS);

    assert_int_equal(LIGHT_POINT, l[5].kind);  /* CGL point wins over technique_common's spot */
    assert_rgb_near(rgb_gray(3), l[5].radiance, EPS);
    assert_int_equal(0, w.count);
    scene_free(&s);
}

static void test_dae_lights__area_light_from_the_cs184_cornell_matrix(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_document_ok("Z_UP",
                     "<library_lights><light id=\"l\"><extra><technique profile=\"CGL\"><area><color>10 10 10</color>"
                     "</area></technique></extra></light></library_lights>",
                     "<node><matrix>0.6 0 0 0  0 0.8 0 0  0 0 1 1.49  0 0 0 1</matrix>"
                     "<instance_light url=\"#l\"/></node>",
                     &s, &w);
    assert_int_equal(1, s.num_lights);
    const light *l = &s.lights[0];
    assert_int_equal(LIGHT_AREA, l->kind);
    assert_vec3_near(vec3_make(0, 1.49f, 0), l->position, EPS);
    assert_vec3_near(vec3_make(-0.6f, 0, 0), l->edge_u, EPS);
    assert_vec3_near(vec3_make(0, 0, 0.8f), l->edge_v, EPS);
    assert_vec3_near(vec3_make(0, -1, 0), l->direction, EPS);  /* faces down, into the box */
    assert_float_near(0.48, l->area, EPS);
    scene_free(&s);
}

static const char CS184_CAMERA[] =
    "<library_cameras><camera id=\"c\"><optics><technique_common><perspective>"
    "<xfov>49.13434</xfov><aspect_ratio>1.333333</aspect_ratio><znear>0.1</znear><zfar>100</zfar>"
    "</perspective></technique_common></optics></camera></library_cameras>";

static void test_dae_camera__xfov_and_aspect_give_the_vertical_fov(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    /* file camera at (0, 3.1, 0.75) looking down file -y with file +z up */
    load_document_ok("Z_UP", CS184_CAMERA,
                     "<node><matrix>-1 0 0 0  0 0 1 3.1  0 1 0 0.75  0 0 0 1</matrix>"
                     "<instance_camera url=\"#c\"/></node>",
                     &s, &w);
    assert_true(s.has_camera);
    const camera *c = &s.camera;
    assert_float_near(49.13434, c->hfov, 1e-4);
    /* 2 atan(tan(49.13434 / 2 deg) / 1.333333) = 37.8493 deg */
    assert_float_near(37.8493, c->vfov, 1e-3);
    assert_false(c->fov_is_vertical);
    assert_float_near(0.1, c->znear, EPS);
    assert_float_near(100.0, c->zfar, 1e-3);
    assert_float_near(4.7, c->focal_distance, EPS);
    assert_float_near(0.0, c->lens_radius, 0);
    assert_vec3_near(vec3_make(0, 0.75f, 3.1f), c->position, EPS);
    assert_vec3_near(vec3_make(0, 0, -1), mat4_dir(c->camera_to_world, vec3_make(0, 0, -1)), EPS);
    assert_vec3_near(vec3_make(0, 1, 0), mat4_dir(c->camera_to_world, vec3_make(0, 1, 0)), EPS);
    assert_vec3_near(c->position, mat4_point(c->camera_to_world, vec3_make(0, 0, 0)), EPS);
    scene_free(&s);
}

static void test_dae_camera__yfov_only_fixes_the_vertical_fov(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "camera_yfov.dae", &s, &w);
    assert_true(s.has_camera);
    assert_true(s.camera.fov_is_vertical);
    assert_float_near(30.0, s.camera.vfov, EPS);
    assert_float_near(56.3728, s.camera.hfov, 1e-3);
    assert_vec3_near(vec3_make(0, 1, 5), s.camera.position, EPS);  /* the first camera */
    assert_int_equal(1, w.count);
    assert_int_equal(1, warn_log_count(&w, "more than one camera"));
    scene_free(&s);
}

/* A file in the course's profile keeps its last camera, as CS184's Application::load does (it sets
 * its camera at every camera node), and says so once; the scene's origin follows that camera. */
static void test_dae_camera__a_course_file_keeps_its_last_camera(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "cs184_two_cameras.dae", &s, &w);
    assert_true(s.course_profile);
    /* the second camera node: file (-1.6, 2.4, 1.4), world (1.6, 1.4, 2.4), looking at (0, 0.6, 0) */
    assert_vec3_near(vec3_make(1.6f, 1.4f, 2.4f), s.camera.position, EPS);
    vec3 ahead = vec3_normalize(vec3_make(-1.6f, -0.8f, -2.4f));
    assert_vec3_near(ahead, mat4_dir(s.camera.camera_to_world, vec3_make(0, 0, -1)), 1e-5f);
    assert_int_equal(1, warn_log_count(&w, "more than one camera; using the last"));
    scene_free(&s);
}

/* ---- materials and warnings -------------------------------------------------------------- */

static void test_dae_materials__every_cgl_kind_loads_with_one_warning_per_kind(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "materials.dae", &s, &w);
    assert_int_equal(8, s.num_triangles);
    const material *m[8];
    for (int i = 0; i < 8; i++) m[i] = &s.materials[s.triangles[i].material];

    assert_int_equal(MATERIAL_DIFFUSE, m[0]->kind);  /* CGL emission: light, no reflection */
    assert_rgb_near(rgb_make(10, 9, 8), m[0]->Le, EPS);
    assert_rgb_near(rgb_gray(0), m[0]->albedo, EPS);
    assert_int_equal(MATERIAL_MIRROR, m[1]->kind);
    assert_rgb_near(rgb_make(0.9f, 0.8f, 0.7f), m[1]->albedo, EPS);
    assert_int_equal(MATERIAL_MIRROR, m[2]->kind);
    assert_int_equal(MATERIAL_GLASS, m[3]->kind);
    assert_int_equal(MATERIAL_REFRACTION, m[4]->kind);
    assert_rgb_near(rgb_make(0.6f, 0.7f, 0.8f), m[4]->albedo, EPS);
    assert_int_equal(MATERIAL_MICROFACET, m[5]->kind);
    assert_int_equal(MATERIAL_DIFFUSE, m[6]->kind);  /* profile_COMMON emission and diffuse */
    assert_rgb_near(rgb_make(1, 2, 3), m[6]->Le, EPS);
    assert_rgb_near(rgb_make(0.2f, 0.3f, 0.4f), m[6]->albedo, EPS);
    assert_rgb_near(rgb_gray(0.5f), m[7]->albedo, EPS);  /* no material bound: grey 0.5 */
    assert_rgb_near(rgb_gray(0), m[7]->Le, EPS);
    for (int i = 1; i < 6; i++) assert_rgb_near(rgb_gray(0), m[i]->Le, EPS);

    /* Each kind's own parameters, kept for the parts that shade them (defaults where absent). */
    assert_rgb_near(rgb_make(0.9f, 0.8f, 0.7f), m[1]->reflectance, EPS);
    assert_rgb_near(rgb_make(1, 1, 1), m[3]->transmittance, EPS);
    assert_rgb_near(rgb_make(0.95f, 0.9f, 0.85f), m[3]->reflectance, EPS);
    assert_float_near(1.5, m[3]->ior, EPS);
    assert_rgb_near(rgb_make(0.6f, 0.7f, 0.8f), m[4]->transmittance, EPS);
    assert_float_near(1.33, m[4]->ior, EPS);
    assert_rgb_near(rgb_gray(1), m[4]->reflectance, EPS);  /* <refraction> has none: the default */
    assert_float_near(0.5, m[5]->alpha, EPS);
    assert_rgb_near(rgb_make(0.2f, 0.9f, 1.1f), m[5]->eta, EPS);
    assert_rgb_near(rgb_make(3.9f, 2.45f, 2.14f), m[5]->k, EPS);
    /* The stand-in for the metal: its reflectance at normal incidence, ((eta-1)^2+k^2)/((eta+1)^2+k^2). */
    assert_float_near((0.64 + 3.9 * 3.9) / (1.44 + 3.9 * 3.9), m[5]->albedo.r, 1e-5);
    assert_float_near(1.5, m[6]->ior, EPS);  /* a diffuse material holds the defaults */
    assert_float_near(0.5, m[6]->alpha, EPS);

    /* Once per kind the course has no part for (material_kind_shaded): part 6 shades the first three. */
    int unshaded = 0;
    for (material_kind k = MATERIAL_MIRROR; k <= MATERIAL_MICROFACET; k++) unshaded += !material_kind_shaded(k);
    assert_int_equal(unshaded, w.count);
    assert_int_equal(!material_kind_shaded(MATERIAL_MIRROR), warn_log_count(&w, "mirror materials are not supported yet"));
    assert_int_equal(!material_kind_shaded(MATERIAL_GLASS), warn_log_count(&w, "glass materials are not supported yet"));
    assert_int_equal(!material_kind_shaded(MATERIAL_REFRACTION),
                     warn_log_count(&w, "refraction materials are not supported yet"));
    assert_int_equal(!material_kind_shaded(MATERIAL_MICROFACET),
                     warn_log_count(&w, "microfacet materials are not supported yet"));
    if (unshaded) assert_non_null(strstr(w.all, "materials.dae:"));  /* warnings are located too */
    scene_free(&s);
}

static void test_dae_materials__one_sphere_geometry_instanced_with_two_materials(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_document_ok(
        "Y_UP",
        "<library_effects>"
        "<effect id=\"e1\"><profile_COMMON><technique sid=\"c\"><lambert><diffuse><color>1 0 0 1</color>"
        "</diffuse></lambert></technique></profile_COMMON></effect>"
        "<effect id=\"e2\"><profile_COMMON><technique sid=\"c\"><lambert><diffuse><color>0 1 0 1</color>"
        "</diffuse></lambert></technique></profile_COMMON></effect></library_effects>"
        "<library_materials><material id=\"m1\"><instance_effect url=\"#e1\"/></material>"
        "<material id=\"m2\"><instance_effect url=\"#e2\"/></material></library_materials>"
        "<library_geometries><geometry id=\"ball\"><extra><technique profile=\"CGL\"><sphere><radius>2</radius>"
        "</sphere></technique></extra></geometry></library_geometries>",
        "<node><translate>1 2 3</translate><scale>0.5 0.5 0.5</scale><instance_geometry url=\"#ball\">"
        "<bind_material><technique_common><instance_material symbol=\"x\" target=\"#m1\"/></technique_common>"
        "</bind_material></instance_geometry></node>"
        "<node><translate>-4 0 0</translate><instance_geometry url=\"#ball\">"
        "<bind_material><technique_common><instance_material symbol=\"x\" target=\"#m2\"/></technique_common>"
        "</bind_material></instance_geometry></node>"
        "<node><translate>4 0 0</translate><instance_geometry url=\"#ball\">"
        "<bind_material><technique_common><instance_material symbol=\"x\" target=\"#m1\"/></technique_common>"
        "</bind_material></instance_geometry></node>",
        &s, &w);
    assert_int_equal(3, s.num_spheres);
    assert_vec3_near(vec3_make(1, 2, 3), s.spheres[0].center, EPS);
    assert_float_near(1.0, s.spheres[0].radius, EPS);  /* radius 2 scaled by 0.5 */
    assert_float_near(2.0, s.spheres[1].radius, EPS);
    assert_rgb_near(rgb_make(1, 0, 0), s.materials[s.spheres[0].material].albedo, EPS);
    assert_rgb_near(rgb_make(0, 1, 0), s.materials[s.spheres[1].material].albedo, EPS);
    /* a material bound twice is one scene material */
    assert_int_equal(s.spheres[0].material, s.spheres[2].material);
    assert_int_equal(2, s.num_materials);
    scene_free(&s);
}

static void test_dae_warnings__unsupported_features_warn_once_per_kind(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "unsupported.dae", &s, &w);
    assert_int_equal(2, s.num_triangles);
    for (int i = 0; i < 2; i++) assert_rgb_near(rgb_gray(0.5f), s.materials[s.triangles[i].material].albedo, EPS);
    assert_int_equal(0, s.num_lights);
    assert_int_equal(4, w.count);
    assert_int_equal(1, warn_log_count(&w, "<environment> lights are not supported"));
    assert_int_equal(1, warn_log_count(&w, "textures are not supported"));
    assert_int_equal(1, warn_log_count(&w, "<instance_controller>) are not supported"));
    assert_int_equal(1, warn_log_count(&w, "animations are not supported"));
    scene_free(&s);
}

static void test_dae_blender_cruft__loads_quietly(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_ok(VALID "blender_cruft.dae", &s, &w);
    if (w.count) fail_msg("unexpected warnings:\n%s", w.all);
    assert_int_equal(4, s.num_triangles);
    assert_int_equal(1, s.num_lights);
    assert_true(s.has_camera);
    assert_vec3_near(vec3_make(-0.3f, 2, -0.5f), s.lights[0].position, EPS);
    assert_rgb_near(rgb_gray(0.64f), s.materials[s.triangles[0].material].albedo, EPS);
    /* the second quad's ".3" heights: file (.5, -1, .3) is world (-0.5, 0.3, -1) */
    assert_vec3_near(vec3_make(-0.5f, 0.3f, -1), s.triangles[2].p1, EPS);
    scene_free(&s);
}

static void test_dae_load_memory__names_the_buffer_and_records_the_path(void **state)
{
    (void)state;
    scene s;
    warn_log w;
    load_document_ok("Y_UP", TRIANGLE_GEOMETRY, "<node><instance_geometry url=\"#tri\"/></node>", &s, &w);
    assert_string_equal("inline.dae", s.path);
    assert_false(s.has_camera);
    scene_free(&s);
    load_ok(VALID "x_up.dae", &s, &w);
    assert_string_equal(VALID "x_up.dae", s.path);
    scene_free(&s);
}

int dae_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dae_load__missing_file_is_io_error_naming_it),
        cmocka_unit_test(test_dae_load__every_broken_file_is_rejected_with_file_line_and_element),
        cmocka_unit_test(test_dae_load__instance_cap_names_its_flag_and_can_be_raised),
        cmocka_unit_test(test_dae_load__numbers_match_strtof_exactly),
        cmocka_unit_test(test_dae_load__truncated_files_are_rejected_at_every_cut),
        cmocka_unit_test(test_dae_load__random_corruption_never_crashes),
        cmocka_unit_test(test_dae_load__large_mesh_loads_and_errors_keep_exact_lines),
        cmocka_unit_test(test_dae_transforms__compose_in_document_order_parent_first),
        cmocka_unit_test(test_dae_up_axis__x_up_maps_x_to_world_up),
        cmocka_unit_test(test_dae_up_axis__z_up_maps_like_cs184_before_the_node_transform),
        cmocka_unit_test(test_dae_up_axis__cs184_layout_with_y_up_meshes_lands_as_stored),
        cmocka_unit_test(test_dae_instance_node__instances_library_nodes_under_each_parent),
        cmocka_unit_test(test_dae_mesh__every_primitive_list_is_fan_triangulated),
        cmocka_unit_test(test_dae_mesh__normals_follow_the_inverse_transpose),
        cmocka_unit_test(test_dae_lights__every_kind_fills_its_fields),
        cmocka_unit_test(test_dae_lights__area_light_from_the_cs184_cornell_matrix),
        cmocka_unit_test(test_dae_camera__xfov_and_aspect_give_the_vertical_fov),
        cmocka_unit_test(test_dae_camera__yfov_only_fixes_the_vertical_fov),
        cmocka_unit_test(test_dae_camera__a_course_file_keeps_its_last_camera),
        cmocka_unit_test(test_dae_materials__every_cgl_kind_loads_with_one_warning_per_kind),
        cmocka_unit_test(test_dae_materials__one_sphere_geometry_instanced_with_two_materials),
        cmocka_unit_test(test_dae_warnings__unsupported_features_warn_once_per_kind),
        cmocka_unit_test(test_dae_blender_cruft__loads_quietly),
        cmocka_unit_test(test_dae_load_memory__names_the_buffer_and_records_the_path),
    };
    return cmocka_run_group_tests_name("dae", tests, NULL, NULL);
}
