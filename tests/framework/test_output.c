/* Test machinery: not part of any assignment.
 * The outputs of a render as one unit (framework/output.c, file.c): names checked before loading,
 * temporaries exclusive and cleaned up, all files renamed together or none, valid JSON. Most tests
 * run bin/pathtracer in a scratch folder, as a user would. */
#include "../common/test.h"
#include "../common/scratch.h"
#include "../../framework/output.h"
#include "../../framework/file.h"
#include <dirent.h>
#include <dlfcn.h>
#include <jansson.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef __linux__
#include <sys/mount.h>  /* Linux's mount(2): a full disk (macOS's mount takes other arguments) */
#endif
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define SCENE "scenes/cornell_spheres.dae"

SCRATCH_FOLDER(dir, "output")

/* file.c's mkstemp resolves to this one (defined in the executable): when a test sets
 * raise_after_mkstemp, SIGTERM arrives right after the temporary exists, before anything else runs. */
static volatile int raise_after_mkstemp;

int mkstemp(char *template)
{
    static int (*real)(char *);
    if (!real) *(void **)&real = dlsym(RTLD_NEXT, "mkstemp");
    int fd = real(template);
    if (fd >= 0 && raise_after_mkstemp) raise(SIGTERM);
    return fd;
}


/* Runs bin/pathtracer with args (a format with %s for the scratch folder); returns its exit code. */
static int render(const char *args_fmt)
{
    char args[1024], cmd[1200];
    snprintf(args, sizeof args, args_fmt, dir, dir, dir);
    snprintf(cmd, sizeof cmd, "bin/pathtracer -q %s >/dev/null 2>%s/stderr.txt", args, dir);
    int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* The names in the scratch folder, sorted, space-separated (stderr.txt left out). */
static void listing(char *out, size_t size)
{
    char *names[64];
    int n = 0;
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d)) && n < 64;)
        if (e->d_name[0] != '.' || strlen(e->d_name) > 2)
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, "stderr.txt"))
                names[n++] = strdup(e->d_name);
    if (d) closedir(d);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (strcmp(names[j], names[i]) < 0) { char *t = names[i]; names[i] = names[j]; names[j] = t; }
    out[0] = '\0';
    for (int i = 0; i < n; i++) {
        strncat(out, names[i], size - strlen(out) - 2);
        if (i + 1 < n) strncat(out, " ", size - strlen(out) - 1);
        free(names[i]);
    }
}

static void expect_files(const char *want)
{
    char got[2048];
    listing(got, sizeof got);
    if (strcmp(got, want)) fail_msg("the folder holds '%s', expected '%s'", got, want);
}

static void expect_refused(const char *args_fmt, const char *message)
{
    int code = render(args_fmt);
    char path[128], err[2048] = "";
    snprintf(path, sizeof path, "%s/stderr.txt", dir);
    FILE *f = fopen(path, "r");
    if (f) {
        size_t n = fread(err, 1, sizeof err - 1, f);
        err[n] = '\0';
        fclose(f);
    }
    if (code != 2 || !strstr(err, message))
        fail_msg("'%s': exit %d, stderr '%s'; expected exit 2 and '%s'", args_fmt, code, err, message);
}

/* Every bad name is refused before the scene loads: the scene here does not even exist, and the
 * message is still about the output. */
static void test_output__bad_names_refused_before_loading(void **state)
{
    (void)state;
    char sub[128];
    snprintf(sub, sizeof sub, "%s/a_folder.png", dir);
    assert_int_equal(0, mkdir(sub, 0755));
    expect_refused("-f %s/a_folder.png /no/such/scene.dae", "is a directory");
    expect_refused("-f %s/x.png --heatmap %s/x.png /no/such/scene.dae", "name the same file");
    expect_refused("-f %s/x.png --heatmap %s/x_rate.png /no/such/scene.dae", "name the same file");
    expect_refused("--heatmap %s/heat.jpg /no/such/scene.dae", "expected a file name ending in .png");
    expect_refused("-f %s/x.tiff /no/such/scene.dae", "expected a file name ending in");
    expect_refused("-r 32768 32768 -f %s/x.png /no/such/scene.dae", "-r 32768 32768");
    rmdir(sub);
    expect_files("");
}

/* `-f sc.png` derives sc.json: when the scene is sc.json, the render must not replace it. */
static void test_output__derived_name_never_overwrites_an_input(void **state)
{
    (void)state;
    char cmd[256];
    snprintf(cmd, sizeof cmd, "cp " SCENE " %s/sc.json", dir);
    assert_int_equal(0, system(cmd));
    expect_refused("-r 8 8 -f %s/sc.png %s/sc.json", "would overwrite the scene");
    expect_files("sc.json");
}

/* An output name that is a symlink is replaced, never written through: its target is untouched. */
static void test_output__symlinked_name_is_replaced_not_followed(void **state)
{
    (void)state;
    char victim[128], link[128];
    snprintf(victim, sizeof victim, "%s/victim.txt", dir);
    snprintf(link, sizeof link, "%s/x.png", dir);
    scratch_write(victim, "precious");
    assert_int_equal(0, symlink(victim, link));
    assert_int_equal(0, render("--normals -r 16 12 -f %s/x.png " SCENE));
    char buf[16] = "";
    FILE *f = fopen(victim, "r");
    assert_non_null(f);
    assert_non_null(fgets(buf, sizeof buf, f));
    fclose(f);
    assert_string_equal("precious", buf);
    struct stat st;
    assert_int_equal(0, lstat(link, &st));
    assert_true(S_ISREG(st.st_mode));
    expect_files("victim.txt x.json x.png x_rate.png");
}

/* Temporary names are not predictable and are created exclusively: two at once differ, and
 * neither is a name anyone could have planted. */
static void test_output__temporaries_are_exclusive_and_hidden(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/x.png", dir);
    file_temp a, b;
    assert_int_equal(PL_OK, file_temp_create(path, &a, NULL));
    assert_int_equal(PL_OK, file_temp_create(path, &b, NULL));
    assert_string_not_equal(a.tmp, b.tmp);
    assert_non_null(strstr(a.tmp, "/.x.png."));
    file_temp_discard(&a);
    file_temp_discard(&b);
    expect_files("");
}

static pl_status encode_text(FILE *f, const void *user, pl_diag *diag)
{
    (void)diag;
    return fputs(user, f) >= 0 ? PL_OK : PL_ERR_IO;
}

static pl_status encode_failing(FILE *f, const void *user, pl_diag *diag)
{
    (void)f, (void)user;
    return pl_fail(diag, PL_ERR_IO, "the encoder failed on purpose");
}

/* One failing file: none of the set appears, the old files stay as they were, no temporary is left. */
static void test_output__one_failure_writes_none(void **state)
{
    (void)state;
    char img[128], old[128];
    snprintf(img, sizeof img, "%s/x.png", dir);
    snprintf(old, sizeof old, "%s/x.json", dir);
    scratch_write(old, "old sidecar");
    options o = options_default();
    o.output = img;
    o.scene_path = SCENE;
    output_set set;
    pl_diag d = pl_diag_default();
    assert_int_equal(PL_OK, output_plan(&set, &o, &d));
    output_bind(&set, OUTPUT_IMAGE, encode_text, "image");
    output_bind(&set, OUTPUT_RATE_MAP, encode_failing, NULL);
    output_bind(&set, OUTPUT_SIDECAR, encode_text, "new sidecar");
    assert_int_equal(PL_ERR_IO, output_write(&set, OUTPUT_IMAGE, OUTPUT_SIDECAR, &d));
    assert_non_null(strstr(d.error, "failed on purpose"));
    expect_files("x.json");
    output_bind(&set, OUTPUT_RATE_MAP, encode_text, "rate");
    assert_int_equal(PL_OK, output_write(&set, OUTPUT_IMAGE, OUTPUT_SIDECAR, &d));
    expect_files("x.json x.png x_rate.png");
    output_free(&set);
}

/* A forked child plays a render killed by SIGTERM: it runs `child` on <dir>/x.png, which must end
 * in the signal (an exit is a code saying what went wrong first); then nothing may be left. */
static void expect_killed_leaving_nothing(void (*child)(const char *path))
{
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        char path[128];
        snprintf(path, sizeof path, "%s/x.png", dir);
        child(path);
        _exit(4);  /* not reached: SIGTERM first */
    }
    int status;
    assert_int_equal(pid, waitpid(pid, &status, 0));
    if (WIFEXITED(status)) fail_msg("the child exited %d instead of dying of SIGTERM", WEXITSTATUS(status));
    assert_true(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
    expect_files("");
}

static void half_written_then_killed(const char *path)
{
    file_temp t;
    if (file_temp_create(path, &t, NULL) != PL_OK) _exit(3);
    fputs("half an image", t.f);
    fflush(t.f);
    raise(SIGTERM);
}

/* SIGTERM while a temporary exists removes it. */
static void test_output__signal_removes_temporaries(void **state)
{
    (void)state;
    expect_killed_leaving_nothing(half_written_then_killed);
}

/* Mounts a 64 KB tmpfs at <dir>/small and fills it to the last byte, so any output fails however
 * well it compresses (a stubbed render is one flat colour). Skips the test unless run as root. */
static void mount_full_disk(char *mnt, size_t size)
{
    snprintf(mnt, size, "%s/small", dir);
    assert_int_equal(0, mkdir(mnt, 0755));
#ifdef __linux__
    bool mounted = geteuid() == 0 && mount("tmpfs", mnt, "tmpfs", 0, "size=64k") == 0;
#else
    bool mounted = false;
#endif
    if (!mounted) {
        print_message("skipped: mounting a small tmpfs needs root on Linux (run the tests as root to check full disks)\n");
        rmdir(mnt);
        skip();
    }
    char filler[160];
    snprintf(filler, sizeof filler, "%s/filler", mnt);
    FILE *f = fopen(filler, "w");
    assert_non_null(f);
    static const char block[512];
    while (fwrite(block, 1, sizeof block, f) == sizeof block && fflush(f) == 0) {}
    fclose(f);
}

/* Unmounts it; returns what it held besides the filler, space-separated. */
static void unmount_full_disk(const char *mnt, char *names, size_t size)
{
    names[0] = '\0';
    DIR *d = opendir(mnt);
    for (struct dirent *e; d && (e = readdir(d));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, "filler"))
            strncat(names, e->d_name, size - strlen(names) - 2);
    if (d) closedir(d);
    char filler[160];
    snprintf(filler, sizeof filler, "%s/filler", mnt);
    unlink(filler);
#ifdef __linux__
    umount(mnt);
#endif
    rmdir(mnt);
}

static void read_stderr(char *err, size_t size)
{
    char path[128];
    snprintf(path, sizeof path, "%s/stderr.txt", dir);
    err[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    size_t n = fread(err, 1, size - 1, f);
    err[n] = '\0';
    fclose(f);
}

/* A full disk: a clear error naming the file, and no file. */
static void test_output__full_disk_leaves_nothing(void **state)
{
    (void)state;
    char mnt[128], names[1024], err[2048];
    mount_full_disk(mnt, sizeof mnt);
    int code = render("-t 2 -s 2 -r 400 300 -f %s/small/x.png " SCENE);
    unmount_full_disk(mnt, names, sizeof names);
    assert_int_equal(1, code);
    if (names[0]) fail_msg("the full filesystem holds '%s', expected nothing", names);
    read_stderr(err, sizeof err);
    if (!strstr(err, "small/x.png")) fail_msg("the message does not name the file: '%s'", err);
}

/* The heat map is one of the render's outputs: when the image cannot be written, it is not either. */
static void test_output__heatmap_commits_with_the_image(void **state)
{
    (void)state;
    int first = render("--normals -r 16 12 --heatmap %s/h.png -f %s/x.png " SCENE);
    char err[2048];
    read_stderr(err, sizeof err);
    if (first != 0 && strstr(err, "not implemented")) {
        /* The heat map shows part 2's BVH: in a student's tree that is a stub until part 2 is done,
         * and this framework test must not wait for it. */
        print_message("skipped: part 2's BVH is still a stub, and the heat map needs it\n");
        skip();
    }
    assert_int_equal(0, first);
    expect_files("h.png x.json x.png x_rate.png");
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -f %s/*.png %s/*.json", dir, dir);
    assert_int_equal(0, system(cmd));
    char mnt[128], names[1024];
    mount_full_disk(mnt, sizeof mnt);
    int code = render("--normals -r 64 48 --heatmap %s/h.png -f %s/small/x.png " SCENE);
    unmount_full_disk(mnt, names, sizeof names);
    assert_int_equal(1, code);
    if (names[0]) fail_msg("the full filesystem holds '%s', expected nothing", names);
    expect_files("");
}

/* A path that is not UTF-8 still gives a sidecar that parses. */
static void test_output__non_utf8_path_gives_valid_json(void **state)
{
    (void)state;
    assert_int_equal(0, render("--normals -r 8 6 -f %s/caf\xe9.png " SCENE));
    char path[128];
    snprintf(path, sizeof path, "%s/caf\xe9.json", dir);
    json_error_t err;
    json_t *j = json_load_file(path, JSON_REJECT_DUPLICATES, &err);
    if (!j) fail_msg("%s: invalid JSON at line %d: %s", path, err.line, err.text);
    assert_non_null(strstr(json_string_value(json_object_get(j, "command_line")), "caf\xef\xbf\xbd.png"));
    json_decref(j);
}

/* ---- --merge writes through the same plan and temporaries as a render --------------------- */

/* Renders samples 0:1 and 1:2 of a tiny render as <dir>/r0.exr and <dir>/r1.exr. */
static void render_two_pieces(void)
{
    assert_int_equal(0, render("--normals -r 8 6 -s 2 --samples 0:1 -f %s/r0.exr " SCENE));
    assert_int_equal(0, render("--normals -r 8 6 -s 2 --samples 1:2 -f %s/r1.exr " SCENE));
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -f %s/*.json %s/*_rate.png", dir, dir);
    assert_int_equal(0, system(cmd));
}

/* Runs a shell line (a format with %s for the scratch folder, up to six times); returns the exit code. */
static int shell(const char *fmt)
{
    char line[1024], cmd[1200];
    snprintf(line, sizeof line, fmt, dir, dir, dir, dir, dir, dir);
    snprintf(cmd, sizeof cmd, "%s >/dev/null 2>%s/stderr.txt", line, dir);
    int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static void expect_text(const char *name, const char *want)
{
    char path[128], buf[64] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    if (!fgets(buf, sizeof buf, f)) buf[0] = '\0';
    fclose(f);
    assert_string_equal(want, buf);
}

/* The old merge wrote <out>.tmp.<pid> with fopen: a symlink planted under that name (the shell's
 * pid, which exec hands on) made it overwrite the link's target. */
static void test_output__merge_never_follows_a_planted_temp_name(void **state)
{
    (void)state;
    render_two_pieces();
    assert_int_equal(0, shell("echo precious > %s/victim.txt; ln -s %s/victim.txt %s/m.exr.tmp.$$; "
                              "exec bin/pathtracer --merge -f %s/m.exr %s/r0.exr %s/r1.exr"));
    expect_text("victim.txt", "precious\n");
    char path[128];
    snprintf(path, sizeof path, "%s/m.exr", dir);
    struct stat st;
    assert_int_equal(0, lstat(path, &st));
    assert_true(S_ISREG(st.st_mode));
}

static void expect_merge_refused(const char *fmt, const char *message)
{
    int code = shell(fmt);
    char err[2048];
    read_stderr(err, sizeof err);
    if (code != 2 || !strstr(err, message))
        fail_msg("'%s': exit %d, stderr '%s'; expected exit 2 and '%s'", fmt, code, err, message);
}

/* Merge outputs are checked before any input is read: not an input, not a directory, a known
 * extension, a folder that exists. The inputs here need not even exist. */
static void test_output__merge_checks_its_output_first(void **state)
{
    (void)state;
    render_two_pieces();
    char sums[2][64];
    for (int i = 0; i < 2; i++) {
        char path[128];
        snprintf(path, sizeof path, "%s/r%d.exr", dir, i);
        struct stat st;
        assert_int_equal(0, stat(path, &st));
        snprintf(sums[i], sizeof sums[i], "%lld", (long long)st.st_size);
    }
    expect_merge_refused("bin/pathtracer --merge -f %s/r0.exr %s/r0.exr %s/r1.exr", "would overwrite");
    expect_merge_refused("bin/pathtracer --merge -f %s/./r1.exr %s/r0.exr %s/r1.exr", "would overwrite");
    expect_merge_refused("mkdir %s/d.exr && bin/pathtracer --merge -f %s/d.exr %s/no-such-input.exr", "is a directory");
    expect_merge_refused("bin/pathtracer --merge -f %s/no/such/folder/m.exr %s/no-such-input.exr", "cannot write into");
    expect_merge_refused("bin/pathtracer --merge -f %s/m.jpg %s/no-such-input.exr", "OUT.exr|OUT.png|OUT.hdr");
    char sub[128];
    snprintf(sub, sizeof sub, "%s/d.exr", dir);
    rmdir(sub);
    expect_files("r0.exr r1.exr");
    for (int i = 0; i < 2; i++) {
        char path[128];
        snprintf(path, sizeof path, "%s/r%d.exr", dir, i);
        struct stat st;
        assert_int_equal(0, stat(path, &st));
        char now[64];
        snprintf(now, sizeof now, "%lld", (long long)st.st_size);
        assert_string_equal(sums[i], now);
    }
}

/* ---- the cleanup table ----------------------------------------------------------------------- */

/* A stop signal between creating a temporary and registering it for cleanup must not leave it:
 * mkstemp (above) raises SIGTERM the moment the file exists. */
static void killed_inside_create(const char *path)
{
    raise_after_mkstemp = 1;
    file_temp t;
    file_temp_create(path, &t, NULL);  /* SIGTERM, at the latest when the signals are unblocked */
}

static void test_output__signal_right_after_create_leaves_nothing(void **state)
{
    (void)state;
    expect_killed_leaving_nothing(killed_inside_create);
}

/* Fills the cleanup table, is refused one more (exit 5, or 6 for a message without the name), dies. */
static void table_full_then_killed(const char *path)
{
    file_temp t[FILE_MAX_TEMPS + 1];
    for (int i = 0; i < FILE_MAX_TEMPS; i++)
        if (file_temp_create(path, &t[i], NULL) != PL_OK) _exit(3);
    pl_diag d = pl_diag_default();
    if (file_temp_create(path, &t[FILE_MAX_TEMPS], &d) == PL_OK) _exit(5);
    if (!strstr(d.error, "x.png")) _exit(6);
    raise(SIGTERM);
}

/* Every temporary is tracked: the table holds every file a render writes, and one more than it
 * holds is refused, not created untracked. A stop signal then removes them all. */
static void test_output__every_temporary_is_tracked_or_refused(void **state)
{
    (void)state;
    assert_true(FILE_MAX_TEMPS >= OUTPUT_KINDS);
    expect_killed_leaving_nothing(table_full_then_killed);
}

/* A film stream's refusal names what the case expects, never a number the stream holds: a render
 * is student code, and a header whose sizes came back in the message would carry 8 bytes of
 * whatever it read out to the student (these two are the bits of the floats 2.2 and 5.5). */
static void test_output__film_refusal_never_echoes_the_stream(void **state)
{
    (void)state;
    static unsigned char stream[12345];
    const uint32_t claimed[2] = {1074580685u, 1085276160u};
    memcpy(stream, "PLFILM1\n", 8);
    for (int k = 0; k < 8; k++) stream[8 + k] = (unsigned char)(claimed[k / 4] >> (8 * (k % 4)));
    film got = {0};
    output_film_counts counts;
    pl_diag d = pl_diag_default();
    assert_int_not_equal(output_film_receive(stream, 48, 160, 120, &got, &counts, &d), PL_OK);
    assert_non_null(strstr(d.error, "160x120"));
    assert_null(strstr(d.error, "1074580685"));
    assert_null(strstr(d.error, "1085276160"));
    /* The right size but a length of the candidate's choosing: refused without that length. */
    for (int k = 0; k < 8; k++) stream[8 + k] = (unsigned char)(k % 4 == 0 ? 2 : 0);
    assert_int_not_equal(output_film_receive(stream, sizeof stream, 2, 2, &got, &counts, &d), PL_OK);
    assert_null(strstr(d.error, "12345"));
    assert_int_not_equal(output_film_receive(stream, 21, 2, 2, &got, &counts, &d), PL_OK);
    assert_null(strstr(d.error, "21"));
}

int output_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_output__bad_names_refused_before_loading, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__derived_name_never_overwrites_an_input, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__symlinked_name_is_replaced_not_followed, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__temporaries_are_exclusive_and_hidden, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__one_failure_writes_none, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__signal_removes_temporaries, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__full_disk_leaves_nothing, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__non_utf8_path_gives_valid_json, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__heatmap_commits_with_the_image, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__merge_never_follows_a_planted_temp_name, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__merge_checks_its_output_first, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__signal_right_after_create_leaves_nothing, dir_setup, dir_teardown),
        cmocka_unit_test_setup_teardown(test_output__every_temporary_is_tracked_or_refused, dir_setup, dir_teardown),
        cmocka_unit_test(test_output__film_refusal_never_echoes_the_stream),
    };
    return cmocka_run_group_tests_name("outputs", tests, NULL, NULL);
}
