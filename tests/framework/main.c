/* Test machinery: not part of any assignment. The framework suite: one binary, one group per module. */
int math_tests(void);
int rng_tests(void);
int image_tests(void);
int cli_tests(void);
int render_tests(void);
int film_tests(void);    /* the film and the sample-range merge */
int camera_file_tests(void);
int camera_tests(void);      /* the camera module: fov rule, framing, lens */
int dae_tests(void);
int scenes_tests(void);
int buf_tests(void);      /* the growable-array helper */
int file_tests(void);     /* whole-file reads and their refusals */
int trace_tests(void);    /* --trace-pixel and --crop */
int bvh_tests(void);      /* the BVH validator (framework/bvh.c) */
int output_tests(void);   /* a render's outputs as one unit */
int lights_tests(void);
int sampler_tests(void);
int stats_tests(void);    /* the statistics the tests and the grader share (framework/stats.c) */
int spawn_tests(void);      /* leaving a surface: offset ray origins (framework/spawn.c) */
int placement_tests(void);  /* a scene renders the same wherever it sits (framework/dae.c's origin) */
int parallel_tests(void);   /* parallel_for: every call once, the work counted for the caller */
int envmap_tests(void);     /* environment maps: the mapping, reading one, a render seeing it */
int material_tests(void);   /* the BSDF of a material, whatever its kind (framework/material.c) */
int visible_light_tests(void);  /* area lights made visible geometry (framework/visible_light.c) */

int main(void)
{
    int failed = 0;
    failed += math_tests();
    failed += rng_tests();
    failed += image_tests();
    failed += cli_tests();
    failed += render_tests();
    failed += film_tests();
    failed += camera_file_tests();
    failed += camera_tests();
    failed += dae_tests();
    failed += scenes_tests();
    failed += buf_tests();
    failed += file_tests();
    failed += output_tests();
    failed += lights_tests();
    failed += sampler_tests();
    failed += stats_tests();
    failed += bvh_tests();
    failed += trace_tests();
    failed += spawn_tests();
    failed += placement_tests();
    failed += parallel_tests();
    failed += envmap_tests();
    failed += material_tests();
    failed += visible_light_tests();
    return failed ? 1 : 0;
}
