/* BVH benchmark (make bench): not part of any assignment, and not a test.
 *
 *   bvh_bench [--runs N] SCENE...     SCENE is a .dae file or proc:N (a bumpy sphere of ~N triangles)
 *
 * For each scene: the BVH build time, then millions of rays per second through part 2's traversal
 * for three fixed ray sets, on 1 and 2 threads, each the median of N runs (5):
 *   camera   one ray through each pixel centre of an 800x600 image;
 *   diffuse  from each camera hit, one cosine-distributed bounce (fixed seed);
 *   shadow   from each camera hit towards a point light (any hit, t up to just before the light).
 * Built with -DPL_HAVE_EMBREE (bench/bench.mk does it when Embree's headers are installed), the same
 * triangles and rays also go through Embree's rtcIntersect1 / rtcOccluded1, side by side with the
 * ratio. The renderer never links Embree. Output: Markdown tables on stdout. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../framework/accel.h"
#include "../framework/clock.h"
#include "../framework/counters.h"
#include "../parts/part2_bvh/part2.h"
#include "../framework/dae.h"
#include "../framework/frame.h"
#include "../framework/heatmap.h"
#include "../framework/parallel.h"
#include "../framework/rng.h"
#include "../framework/sampler.h"
#include "../parts/part1_raygen/part1.h"
#include "../framework/procmesh.h"
#ifdef PL_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#define WIDTH 800
#define HEIGHT 600
#define MAX_THREADS 2
#define BLOCK 256      /* rays per work item: threads take blocks as they finish, so both get sky and mesh */
#define MAX_RUNS 15

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_doubles);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* ---- the scenes ------------------------------------------------------------------------------ */

/* Loads a .dae, or makes proc:N. The camera: the file's, or one framing the bumpy sphere closely. */
static int load_scene(const char *name, scene *s, camera *cam)
{
    memset(s, 0, sizeof *s);
    if (strncmp(name, "proc:", 5) == 0) {
        long n = atol(name + 5);
        scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
        if (n < 1 || procmesh_bumpy_sphere(s, procmesh_rows_for(n), vec3_make(0, 0, 0), 1.0f, 0) != PL_OK) {
            fprintf(stderr, "bvh_bench: %s: expected proc:N with N >= 1 (and the memory for it)\n", name);
            return 1;
        }
        *cam = camera_default_framing(scene_bounds(s));
        cam->camera_to_world = mat4_lookat(vec3_make(0.0f, 0.8f, 2.6f), vec3_make(0, 0, 0), vec3_make(0, 1, 0));
        cam->position = vec3_make(0.0f, 0.8f, 2.6f);
    } else {
        pl_diag diag = pl_diag_default();
        if (dae_load(name, s, &diag) != PL_OK) {
            fprintf(stderr, "bvh_bench: %s\n", diag.error);
            return 1;
        }
        *cam = s->has_camera ? s->camera : camera_default_framing(scene_bounds(s));
    }
    cam->fov_is_vertical = false;
    camera_set_aspect(cam, (float)WIDTH / HEIGHT);
    return 0;
}

/* A point light for shadow rays: the scene's first point or area light, else above the bounds. */
static vec3 light_position(const scene *s)
{
    for (int i = 0; i < s->num_lights; i++)
        if (s->lights[i].kind == LIGHT_POINT || s->lights[i].kind == LIGHT_AREA) return s->lights[i].position;
    aabb b = scene_bounds(s);
    float diag = vec3_length(aabb_extent(b));
    return vec3_add(aabb_centroid(b), vec3_make(0.3f * diag, diag, 0.6f * diag));
}

/* ---- the rays ---------------------------------------------------------------------------------- */

typedef struct {
    ray *camera, *diffuse, *shadow;
    int num_camera, num_diffuse, num_shadow;
} ray_sets;

static int make_rays(const scene *s, const accel *a, const camera *cam, ray_sets *out)
{
    int n = WIDTH * HEIGHT;
    out->camera = malloc((size_t)n * sizeof(ray));
    out->diffuse = malloc((size_t)n * sizeof(ray));
    out->shadow = malloc((size_t)n * sizeof(ray));
    if (!out->camera || !out->diffuse || !out->shadow) return 1;
    vec3 light_pos = light_position(s);
    out->num_camera = out->num_diffuse = out->num_shadow = 0;
    for (int y = 0; y < HEIGHT; y++) {
        for (int x = 0; x < WIDTH; x++) {
            ray r = camera_generate_ray(cam, (x + 0.5f) / WIDTH, (y + 0.5f) / HEIGHT);
            out->camera[out->num_camera++] = r;
            hit h;
            if (!accel_intersect(a, &r, &h)) continue;
            vec3 p = ray_at(&r, h.t);
            vec3 normal = vec3_dot(h.n, r.d) > 0.0f ? vec3_neg(h.n) : h.n;  /* the side the ray came from */
            rng g = rng_for_sample(7, (uint64_t)y * WIDTH + x, 0);
            frame f = frame_from_normal(normal);
            vec3 wi = frame_to_world(&f, sample_cosine_hemisphere(rng_uniform2(&g)));
            out->diffuse[out->num_diffuse++] = ray_make(p, wi, EPS_F, INFINITY);
            out->shadow[out->num_shadow++] = ray_make(p, vec3_sub(light_pos, p), EPS_F, 1.0f - EPS_F);
        }
    }
    return 0;
}

/* ---- tracing on T threads ---------------------------------------------------------------------- */

typedef enum { QUERY_CLOSEST, QUERY_ANY } query;

/* What traces one ray: part 2's BVH or Embree. Returns 1 on a hit. */
typedef int (*trace_fn)(const void *engine, const ray *r, query q);

typedef struct {
    trace_fn trace;
    const void *engine;
    const ray *rays;
    int num_rays;
    query q;
    long *hits;             /* per block, so no two threads write one count */
} trace_job;

/* Block i of BLOCK rays, on whichever thread parallel_for hands it to. */
static void trace_block(void *arg, int i)
{
    trace_job *job = arg;
    int end = (i + 1) * BLOCK < job->num_rays ? (i + 1) * BLOCK : job->num_rays;
    long hits = 0;
    for (int k = i * BLOCK; k < end; k++) hits += job->trace(job->engine, &job->rays[k], job->q);
    job->hits[i] = hits;
}

/* Seconds to trace every ray on `threads` threads (parallel_for_threads); *hits counts the rays
 * that hit. */
static double trace_all(trace_fn trace, const void *engine, const ray *rays, int n, query q, int threads, long *hits)
{
    int blocks = (n + BLOCK - 1) / BLOCK;
    long *per_block = calloc((size_t)(blocks > 0 ? blocks : 1), sizeof *per_block);
    if (!per_block) {
        fprintf(stderr, "bvh_bench: out of memory\n");
        exit(1);
    }
    trace_job job = {trace, engine, rays, n, q, per_block};
    double t0 = clock_seconds();
    parallel_for_threads(threads, blocks, trace_block, &job);
    double seconds = clock_seconds() - t0;
    *hits = 0;
    for (int i = 0; i < blocks; i++) *hits += per_block[i];
    free(per_block);
    return seconds;
}

/* Median million rays per second over runs. */
static double mrays_per_second(trace_fn trace, const void *engine, const ray *rays, int n, query q, int threads,
                               int runs, long *hits)
{
    double rate[MAX_RUNS];
    for (int i = 0; i < runs; i++) rate[i] = n / trace_all(trace, engine, rays, n, q, threads, hits) * 1e-6;
    return median(rate, runs);
}

static int trace_pathlab(const void *engine, const ray *r, query q)
{
    const accel *a = engine;
    if (q == QUERY_ANY) return bvh_occluded(&a->bvh, a->scene, r);
    ray probe = *r;
    hit h;
    return bvh_intersect(&a->bvh, a->scene, &probe, &h);
}

/* ---- Embree: the same triangles, the same rays ------------------------------------------------- */
#ifdef PL_HAVE_EMBREE
typedef struct {
    RTCDevice device;
    RTCScene scene;
} embree;

/* Builds an Embree scene of s's triangles (medium quality, Embree's default); returns seconds. */
static double embree_build(embree *e, const scene *s)
{
    double t0 = clock_seconds();
    e->scene = rtcNewScene(e->device);
    RTCGeometry geom = rtcNewGeometry(e->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                       3 * (size_t)s->num_triangles);
    unsigned *index = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                              (size_t)s->num_triangles);
    for (int i = 0; i < s->num_triangles; i++) {
        const triangle *t = &s->triangles[i];
        vec3 p[3] = {t->p0, t->p1, t->p2};
        for (int k = 0; k < 3; k++) {
            v[9 * i + 3 * k + 0] = p[k].x;
            v[9 * i + 3 * k + 1] = p[k].y;
            v[9 * i + 3 * k + 2] = p[k].z;
            index[3 * i + k] = (unsigned)(3 * i + k);
        }
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(e->scene, geom);
    rtcReleaseGeometry(geom);
    rtcSetSceneBuildQuality(e->scene, RTC_BUILD_QUALITY_MEDIUM);
    rtcCommitScene(e->scene);
    return clock_seconds() - t0;
}

static int trace_embree(const void *engine, const ray *r, query q)
{
    const embree *e = engine;
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    struct RTCRayHit rh;
    rh.ray.org_x = r->o.x, rh.ray.org_y = r->o.y, rh.ray.org_z = r->o.z;
    rh.ray.dir_x = r->d.x, rh.ray.dir_y = r->d.y, rh.ray.dir_z = r->d.z;
    rh.ray.tnear = r->min_t;
    rh.ray.tfar = r->max_t;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    if (q == QUERY_ANY) {
        rtcOccluded1(e->scene, &context, &rh.ray);
        return rh.ray.tfar < 0.0f;  /* Embree marks an occluded ray with tfar = -inf */
    }
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(e->scene, &context, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}
#endif

/* ---- one scene ---------------------------------------------------------------------------------- */

static int bench_scene(const char *name, int runs)
{
    scene s;
    camera cam;
    if (load_scene(name, &s, &cam)) return 1;

    /* Build: the median of `runs` builds; the last one is kept. */
    double build[MAX_RUNS];
    accel a;
    pl_diag diag = pl_diag_default();
    for (int i = 0; i < runs; i++) {
        if (i > 0) accel_free(&a);
        if (accel_build(&a, &s, true, 4, &diag) != PL_OK || !a.use_bvh) {
            fprintf(stderr, "bvh_bench: %s: no BVH (%s)\n", name, diag.error[0] ? diag.error : "part 2 is a stub");
            scene_free(&s);
            return 1;
        }
        build[i] = a.build_seconds;
    }
    double build_s = median(build, runs);
    accel_shape shape = accel_bvh_shape(&a);

    ray_sets rays;
    if (make_rays(&s, &a, &cam, &rays)) {
        fprintf(stderr, "bvh_bench: out of memory for rays\n");
        return 1;
    }
    const char *kind_name[3] = {"camera", "diffuse", "shadow"};
    const ray *kind_rays[3] = {rays.camera, rays.diffuse, rays.shadow};
    int kind_count[3] = {rays.num_camera, rays.num_diffuse, rays.num_shadow};
    query kind_query[3] = {QUERY_CLOSEST, QUERY_CLOSEST, QUERY_ANY};

#ifdef PL_HAVE_EMBREE
    embree e;
    char config[32];
    snprintf(config, sizeof config, "threads=%d", parallel_threads());  /* the threads part 2's build may use */
    e.device = rtcNewDevice(config);
    double ebuild[MAX_RUNS];
    for (int i = 0; i < runs; i++) {
        if (i > 0) rtcReleaseScene(e.scene);
        ebuild[i] = embree_build(&e, &s);
    }
    double ebuild_s = median(ebuild, runs);
    printf("| %s | %d | build, s (%d nodes, depth %d) | %d | %.4f | %.4f | %.2f |\n", name, s.num_triangles,
           shape.nodes, shape.depth, parallel_threads(), build_s, ebuild_s, build_s / ebuild_s);
#else
    printf("| %s | %d | build, s (%d nodes, depth %d) | %d | %.4f | - | - |\n", name, s.num_triangles, shape.nodes,
           shape.depth, parallel_threads(), build_s);
#endif
    fflush(stdout);

    for (int k = 0; k < 3; k++) {
        for (int threads = 1; threads <= MAX_THREADS; threads++) {
            long hits = 0;
            (void)counters_take();
            double ours = mrays_per_second(trace_pathlab, &a, kind_rays[k], kind_count[k], kind_query[k], threads, runs, &hits);
            double visits = threads == 1 ? (double)counters_take().node_visits / ((double)runs * kind_count[k]) : 0.0;
#ifdef PL_HAVE_EMBREE
            long ehits = 0;
            double theirs = mrays_per_second(trace_embree, &e, kind_rays[k], kind_count[k], kind_query[k], threads, runs, &ehits);
            if (threads == 1)
                fprintf(stderr, "  %s %s: %d rays, %ld hit (Embree %ld), %.1f nodes visited per ray\n", name,
                        kind_name[k], kind_count[k], hits, ehits, visits);
            printf("| | | %s rays (%d), Mrays/s | %d | %.2f | %.2f | %.2f |\n", kind_name[k], kind_count[k], threads, ours,
                   theirs, ours / theirs);
#else
            if (threads == 1)
                fprintf(stderr, "  %s %s: %d rays, %ld hit, %.1f nodes visited per ray\n", name, kind_name[k],
                        kind_count[k], hits, visits);
            printf("| | | %s rays (%d), Mrays/s | %d | %.2f | - | - |\n", kind_name[k], kind_count[k], threads, ours);
#endif
            fflush(stdout);
        }
    }
#ifdef PL_HAVE_EMBREE
    rtcReleaseScene(e.scene);
    rtcReleaseDevice(e.device);
#endif
    free(rays.camera);
    free(rays.diffuse);
    free(rays.shadow);
    accel_free(&a);
    scene_free(&s);
    return 0;
}

int main(int argc, char **argv)
{
    int runs = 5, first = 1;
    if (argc > 2 && strcmp(argv[1], "--runs") == 0) {
        runs = atoi(argv[2]);
        first = 3;
    }
    if (runs < 1 || runs > MAX_RUNS || first >= argc) {
        fprintf(stderr, "usage: bvh_bench [--runs N (1..%d)] SCENE.dae|proc:N ...\n", MAX_RUNS);
        return 2;
    }
    printf("Each figure is the median of %d runs. Build: seconds, lower is better (both builds use every\n"
           "core: part 2's builds the top subtrees side by side). Rays: millions per second, higher is better.\n\n", runs);
    printf("| scene | triangles | what | threads | pathlab | Embree | pathlab / Embree |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- |\n");
    int failed = 0;
    for (int i = first; i < argc; i++) failed |= bench_scene(argv[i], runs);
    return failed;
}
