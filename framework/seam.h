/* The seam between the framework and the students' parts, as one list: every part function the
 * framework calls, and every framework function the parts call. One X-macro list so that every
 * tool that needs the seam reads it from here: the trace (framework/trace.c) and the grader's
 * split suites, whose record and replay of a graded part's calls number and name the part
 * functions from it (grader/seam/seam.h).
 *
 * PL_SEAM_PART_FUNCTIONS(X): X(name, task) for each part function the framework calls, with the
 *   task that writes it ("2.2"). The framework calls the recorded ones through the wrappers in
 *   framework/render.c (pixel loop and radiance dispatch), which log their arguments and results
 *   when a trace is on; part-to-part calls (part 4's russian_roulette, and parts 3, 6 and 7's
 *   BSDFs, which parts 3 and 4 reach through framework/material.h) are not intercepted: the trace replays them
 *   from what it saw (framework/trace.h says how).
 * PL_SEAM_FRAMEWORK_FUNCTIONS(X): X(name, recorded) for each framework function the parts call;
 *   recorded is 1 when the function logs its result into an active trace itself.
 * Parts may not call: none of these (it declares no function). */
#ifndef PL_SEAM_H
#define PL_SEAM_H

#define PL_SEAM_PART_FUNCTIONS(X)            \
    X(camera_generate_ray, "1.1")            \
    X(triangle_intersect, "1.2")             \
    X(sphere_intersect, "1.3")               \
    X(pixel_sample_ray, "1.4")               \
    X(normal_shade, "example")               \
    X(aabb_intersect, "2.1")                 \
    X(bvh_build, "2.2")                      \
    X(bvh_intersect, "2.3")                  \
    X(bvh_occluded, "2.4")                   \
    X(bsdf_f, "3.1")                         \
    X(bsdf_pdf, "3.2")                       \
    X(bsdf_sample_f, "3.2")                  \
    X(zero_bounce_radiance, "3.3")           \
    X(direct_hemisphere, "3.4")              \
    X(direct_importance, "3.5")              \
    X(at_least_one_bounce_radiance, "4.1")   \
    X(russian_roulette, "4.2")               \
    X(adaptive_converged, "5.1")             \
    X(reflect, "6.1")                        \
    X(mirror_sample_f, "6.2")                \
    X(refract, "6.3")                        \
    X(refraction_sample_f, "6.4")            \
    X(glass_sample_f, "6.5")                 \
    X(beckmann_d, "7.1")                     \
    X(fresnel_conductor, "7.2")              \
    X(microfacet_g, "7.3")                   \
    X(microfacet_f, "7.4")                   \
    X(microfacet_pdf, "7.5")                 \
    X(microfacet_sample_f, "7.6")            \
    X(env_sample_uniform, "8.1")             \
    X(env_build_distribution, "8.2")         \
    X(env_pdf, "8.3")                        \
    X(env_sample_importance, "8.4")          \
    X(lens_sample_disk, "9.1")               \
    X(thin_lens_ray, "9.2")

#define PL_SEAM_FRAMEWORK_FUNCTIONS(X)       \
    X(render_intersect, 1)                   \
    X(render_occluded, 1)                    \
    X(one_bounce_radiance, 1)                \
    X(light_sample_L, 1)                     \
    X(material_f, 0)                         \
    X(material_pdf, 0)                       \
    X(material_sample_f, 0)                  \
    X(envmap_radiance, 0)                    \
    X(envmap_texel, 0)                       \
    X(envmap_direction, 0)                   \
    X(envmap_angles, 0)                      \
    X(rng_uniform, 1)                        \
    X(light_is_delta, 0)                     \
    X(scene_prim_intersect, 0)               \
    X(bvh_visit, 0)                          \
    X(sample_uniform_hemisphere, 0)          \
    X(sample_cosine_hemisphere, 0)           \
    X(sample_cosine_hemisphere_pdf, 0)       \
    X(sample_uniform_hemisphere_pdf, 0)      \
    X(render_light_samples, 0)               \
    X(spawn_ray, 0)                          \
    X(spawn_ray_to_light, 0)

/* One id per seam function: PL_SEAM_bsdf_f, PL_SEAM_render_intersect, ... */
typedef enum {
#define PL_SEAM_ID(name, extra) PL_SEAM_##name,
    PL_SEAM_PART_FUNCTIONS(PL_SEAM_ID)
    PL_SEAM_FRAMEWORK_FUNCTIONS(PL_SEAM_ID)
#undef PL_SEAM_ID
    PL_SEAM_COUNT
} pl_seam_id;

#endif
