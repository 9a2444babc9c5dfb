/* Where the framework calls the students' parts. The framework depends on a part's header only at
 * the places it calls that part's tasks, and every such place is listed here; types, helpers and
 * counters the framework stores, frees or provides live in framework headers (bvh.h, frame.h,
 * scene.h, ...), so a part's header declares that part's tasks and nothing else.
 *
 *   framework/scene.c    part 1: triangle_intersect, sphere_intersect (scene_prim_intersect)
 *   framework/render.c   parts 1, 3, 4, 5: camera rays, radiance estimators, adaptive sampling
 *   framework/heatmap.c  parts 1, 2: camera rays, bvh_intersect for the node-visit picture
 *   framework/accel.c    part 2: bvh_build (checked by bvh_validate), bvh_intersect, bvh_occluded
 *   framework/trace.c    parts 3, 4: --trace-pixel replays bsdf_f, bsdf_pdf, bsdf_sample_f,
 *                        zero_bounce_radiance and russian_roulette on copies (framework/seam.h)
 *
 * Keep this list in step with `grep -l 'parts/' framework/*.c`. No framework header includes a
 * part header. */
#ifndef PL_PARTS_H
#define PL_PARTS_H
#endif
