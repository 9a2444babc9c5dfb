/* Test machinery: not part of any assignment. Image files: tone curve, round trips, atomic writes. */
#include "../common/test.h"
#include "../../framework/image.h"
#include "../../framework/colormap.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* A fresh folder under /tmp for one test's files. */
static void make_dir(char *out, size_t n)
{
    snprintf(out, n, "/tmp/pathlab-test-XXXXXX");
    assert_non_null(mkdtemp(out));
}

static int count_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        if (e->d_name[0] != '.') n++;
    if (d) closedir(d);
    return n;
}

static void test_tonemap__matches_cs184_curve(void **state)
{
    assert_int_equal(0, tonemap_channel(0.0f));
    assert_int_equal(0, tonemap_channel(-1.0f));
    assert_int_equal(0, tonemap_channel(NAN));
    assert_int_equal(255, tonemap_channel(10.0f));
    /* v = 0.5: (0.5 sqrt 2)^(1/2.2) = 0.8543 -> 218 */
    assert_int_equal(218, tonemap_channel(0.5f));
    /* v = 1/sqrt(2) is exactly white */
    assert_int_equal(255, tonemap_channel(0.70710678f));
}

static void test_image_write_png__round_trips_tone_mapped_bytes(void **state)
{
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.png", dir);
    image img, back;
    assert_int_equal(PL_OK, image_alloc(&img, 3, 2));
    image_set(&img, 0, 0, rgb_make(0.5f, 0, 1));
    image_set(&img, 2, 1, rgb_make(0.1f, 0.2f, 0.3f));
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, image_write_png(&img, path, &d));
    assert_int_equal(PL_OK, image_read(path, &back, &d));
    assert_int_equal(3, back.width);
    assert_int_equal(2, back.height);
    for (int i = 0; i < 6; i++) {
        assert_float_near(tonemap_channel(img.pixels[i].r) / 255.0, back.pixels[i].r, 1e-6);
        assert_float_near(tonemap_channel(img.pixels[i].b) / 255.0, back.pixels[i].b, 1e-6);
    }
    assert_int_equal(1, count_files(dir));  /* no temporary file left behind */
    image_free(&img);
    image_free(&back);
    remove(path);
    rmdir(dir);
}

static void test_image_write_hdr__round_trips_linear_values(void **state)
{
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.hdr", dir);
    image img, back;
    assert_int_equal(PL_OK, image_alloc(&img, 4, 4));
    for (int i = 0; i < 16; i++) img.pixels[i] = rgb_make(0.01f * i, 3.0f + i, 100.0f);
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, image_write(&img, path, &d));
    assert_int_equal(PL_OK, image_read(path, &back, &d));
    for (int i = 0; i < 16; i++) {
        /* RGBE keeps 8 mantissa bits relative to the largest channel (100): error < 100/128. */
        assert_float_near(img.pixels[i].g, back.pixels[i].g, 100.0 / 128);
        assert_float_near(100.0, back.pixels[i].b, 100.0 / 128);
    }
    image_free(&img);
    image_free(&back);
    remove(path);
    rmdir(dir);
}

static void test_image_write__bad_folder_or_extension_fails_cleanly(void **state)
{
    image img;
    assert_int_equal(PL_OK, image_alloc(&img, 2, 2));
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, image_write(&img, "/nonexistent-dir/x.png", &d));
    assert_non_null(strstr(d.error, "/nonexistent-dir/x.png"));
    assert_int_equal(PL_ERR_INVALID, image_write(&img, "/tmp/x.jpg", &d));
    assert_non_null(strstr(d.error, ".png or .hdr"));
    assert_int_equal(-1, access("/tmp/x.jpg", F_OK));
    image_free(&img);
}

static void test_image_read__missing_file_names_it(void **state)
{
    image img;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_ERR_IO, image_read("/tmp/does-not-exist.png", &img, &d));
    assert_non_null(strstr(d.error, "/tmp/does-not-exist.png"));
}

static void test_colormap_rate__blue_green_red(void **state)
{
    uint8_t c[3];
    colormap_rate(0.0f, c);
    assert_memory_equal(((uint8_t[]){0, 0, 255}), c, 3);
    colormap_rate(0.5f, c);
    assert_memory_equal(((uint8_t[]){0, 255, 0}), c, 3);
    colormap_rate(1.0f, c);
    assert_memory_equal(((uint8_t[]){255, 0, 0}), c, 3);
    colormap_rate(0.75f, c);
    assert_memory_equal(((uint8_t[]){128, 128, 0}), c, 3);
    colormap_rate(7.0f, c);  /* clamped */
    assert_memory_equal(((uint8_t[]){255, 0, 0}), c, 3);
}

int image_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tonemap__matches_cs184_curve),
        cmocka_unit_test(test_image_write_png__round_trips_tone_mapped_bytes),
        cmocka_unit_test(test_image_write_hdr__round_trips_linear_values),
        cmocka_unit_test(test_image_write__bad_folder_or_extension_fails_cleanly),
        cmocka_unit_test(test_image_read__missing_file_names_it),
        cmocka_unit_test(test_colormap_rate__blue_green_red),
    };
    return cmocka_run_group_tests_name("image", tests, NULL, NULL);
}
