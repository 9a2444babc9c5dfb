/* Grader machinery: not part of any assignment.
 * The allow-list: every function a student's part may call, in one place (handout/README.md,
 * "What your part may call", says the same to students; make test-grader checks both against the
 * PL_PART_API marks of the framework headers). A part's compiled objects may refer only
 * to these names, to its own functions and to the other parts' (grade_inspect.c checks it).
 *
 * Why so narrow: part code runs inside the grader's test and render processes, so any function it
 * can reach is a way to act outside its task. Files (exr_read, file_write_atomic, image_write...)
 * could read a reference or write a result; the work counters' readers and resets (counters_take,
 * counters_add_*, counters_trace_*: framework/counters.h) could hide the work a BVH does from the
 * work-per-ray verdict; scene builders and the render loops are the framework's to drive, not a task's. What is
 * left is what the tasks need: math, random numbers, samplers, the scene, BVH, light and BSDF
 * accessors, the intersection entry points, the stub helpers, and parallel_for, whose threads the
 * sandbox confines like the process's own and whose counted work it hands back to the caller. */
#include "grade_allow.h"
#include <stdio.h>
#include <string.h>

/* The framework API part code is meant to call: exactly the functions the framework headers mark
 * PL_PART_API (framework/part_api.h; make test-grader checks the two agree). Its static inline
 * helpers need no entry. */
static const char *const allowed_framework[] = {
    /* math: 4x4 transforms */
    "mat4_dir", "mat4_from_basis", "mat4_identity", "mat4_inverse", "mat4_lookat", "mat4_mul", "mat4_normal",
    "mat4_point", "mat4_rotate", "mat4_scale", "mat4_translate", "mat4_transpose",
    /* random numbers and samplers, each sampler with its pdf */
    "rng_for_sample", "rng_seeded", "rng_u32", "rng_uniform", "sample_cosine_hemisphere",
    "sample_cosine_hemisphere_pdf", "sample_uniform_disk", "sample_uniform_disk_pdf", "sample_uniform_hemisphere",
    "sample_uniform_hemisphere_pdf", "sample_uniform_sphere", "sample_uniform_sphere_pdf", "sample_uniform_triangle",
    /* scene, BVH and light accessors; bvh_visit reads a node and counts the visit (bvh.h) */
    "scene_bounds", "scene_prim_bounds", "scene_prim_centroid", "bvh_free", "bvh_visit", "light_is_delta",
    "light_sample_L", "envmap_angles", "envmap_direction", "envmap_radiance", "envmap_texel",
    /* the BSDF of a material, whatever its kind (material.h) */
    "material_f", "material_pdf", "material_sample_f",
    /* the intersection entry points and the estimators a later part builds on */
    "scene_prim_intersect", "accel_intersect", "accel_occluded", "linear_intersect", "linear_occluded",
    "render_intersect", "render_occluded", "one_bounce_radiance", "radiance_estimate", "render_light_samples",
    /* leaving a surface: offset origins for bounce and shadow rays (spawn.h) */
    "spawn_ray", "spawn_ray_to_light",
    /* independent work on every core (parallel.h): the one way part code may use threads */
    "parallel_for",
    /* stubs and statuses: PL_TODO and friends (todo.h), a failure with its message (status.h) */
    "pl_todo_report", "pl_fail", "pl_warn", "pl_status_name", "pl_diag_default",
    NULL};

/* From libc: memory, strings, sorting and printing (to the console only: no FILE can be opened).
 * Nothing that touches files, processes, sockets, the environment, time or exit. The _chk forms
 * are what -D_FORTIFY_SOURCE turns the same calls into; the last four are the compiler's. */
static const char *const allowed_libc[] = {
    "memcpy", "memmove", "memset", "memcmp", "strlen", "strcmp", "strncmp", "strchr", "strstr",
    "malloc", "calloc", "realloc", "free", "qsort", "bsearch", "abs", "labs",
    "printf", "fprintf", "puts", "fputs", "putchar", "fputc", "snprintf", "sprintf", "vsnprintf", "fflush",
    "stdout", "stderr", "__printf_chk", "__fprintf_chk", "__sprintf_chk", "__snprintf_chk", "__memcpy_chk",
    "__memset_chk", "__memmove_chk", "__assert_fail", "__stack_chk_fail", "_GLOBAL_OFFSET_TABLE_", NULL};

/* From libm, each also in its float and long double forms (name + "f", name + "l"): pure maths in
 * every precision (a part written in long double is as correct as one in float). */
static const char *const allowed_libm[] = {
    "sqrt", "cbrt", "hypot", "exp", "exp2", "expm1", "log", "log2", "log10", "log1p", "pow", "sin", "cos", "tan",
    "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "fabs", "floor", "ceil", "round", "trunc", "fmod",
    "fmin", "fmax", "copysign", "nextafter", "ldexp", "frexp", "erf", "erfc", "lgamma", "tgamma", "sincos", NULL};

static bool in_list(const char *const *list, const char *s)
{
    for (; *list; list++)
        if (!strcmp(*list, s)) return true;
    return false;
}

static bool libm_function(const char *s)
{
    char base[64];
    size_t n = strlen(s);
    if (n == 0 || n >= sizeof base) return false;
    if (in_list(allowed_libm, s)) return true;
    snprintf(base, sizeof base, "%.*s", (int)n - 1, s);
    return (s[n - 1] == 'f' || s[n - 1] == 'l') && in_list(allowed_libm, base);
}

const char *const *grade_allow_framework(void) { return allowed_framework; }

bool grade_allow_add_all(grade_names *set)
{
    bool ok = true;
    for (const char *const *lists[] = {allowed_framework, allowed_libc}, *const *const *l = lists; l < lists + 2; l++)
        for (const char *const *s = *l; ok && *s; s++) ok = grade_names_add(set, *s);
    for (const char *const *s = allowed_libm; ok && *s; s++) {
        char forms[2][64];
        snprintf(forms[0], sizeof forms[0], "%sf", *s);
        snprintf(forms[1], sizeof forms[1], "%sl", *s);
        ok = grade_names_add(set, *s) && grade_names_add(set, forms[0]) && grade_names_add(set, forms[1]);
    }
    return ok;
}

bool grade_allow_has(const char *name)
{
    return in_list(allowed_framework, name) || in_list(allowed_libc, name) || libm_function(name);
}
