/* Test machinery: not part of any assignment. */
#include "../common/test.h"
#include "fixtures.h"
#include "../../framework/dae.h"
#include "../../framework/rng.h"
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fixture_for_each_scene(void (*visit)(const scene *s, const char *path))
{
    const char *patterns[] = {"scenes/*.dae", "scenes/*/*.dae"};
    int found = 0;
    for (int p = 0; p < 2; p++) {
        glob_t g;
        if (glob(patterns[p], 0, NULL, &g) != 0) continue;
        for (size_t i = 0; i < g.gl_pathc; i++, found++) {
            scene s;
            pl_diag diag = pl_diag_default();
            diag.on_warning = NULL;
            if (dae_load(g.gl_pathv[i], &s, &diag) != PL_OK) PL_FAIL("%s does not load: %s", g.gl_pathv[i], diag.error);
            visit(&s, g.gl_pathv[i]);
            scene_free(&s);
        }
        globfree(&g);
    }
    if (found == 0) PL_FAIL("no scenes found under scenes/ (run the tests from the repository root)");
}

static vec3 random_point(rng *g, float half)
{
    return vec3_make((2.0f * rng_uniform(g) - 1.0f) * half, (2.0f * rng_uniform(g) - 1.0f) * half,
                     (2.0f * rng_uniform(g) - 1.0f) * half);
}

void fixture_random_soup(scene *s, int n, uint64_t seed)
{
    rng g = rng_seeded(seed, 2);
    if (s->num_materials == 0) scene_add_material(s, material_make(rgb_gray(0.5f), rgb_gray(0.0f)));
    for (int i = 0; i < n; i++) {
        vec3 c = random_point(&g, 1.0f);
        float size = 0.2f * rng_uniform(&g) * rng_uniform(&g);
        vec3 a = vec3_add(c, random_point(&g, size)), b = vec3_add(c, random_point(&g, size));
        vec3 d = vec3_add(c, random_point(&g, size));
        switch (rng_u32(&g) % 10) {
        case 0: /* long and thin: a sliver across the soup */
            b = vec3_add(a, vec3_scale(random_point(&g, 1.0f), 1.5f));
            d = vec3_add(b, vec3_scale(random_point(&g, 1.0f), 0.01f));
            break;
        case 1: /* axis-aligned: a flat box, and rays may travel in its plane */
            a.y = b.y = d.y = c.y;
            break;
        case 2: /* degenerate: collinear */
            d = vec3_lerp(a, b, rng_uniform(&g));
            break;
        case 3: /* degenerate: repeated vertex, or a single point */
            d = b;
            if (rng_uniform(&g) < 0.5f) a = b;
            break;
        case 4: /* a duplicate of the previous triangle: an exact tie for every ray through it */
            if (s->num_triangles > 0) {
                triangle t = s->triangles[s->num_triangles - 1];
                a = t.p0, b = t.p1, d = t.p2;
            }
            break;
        case 5:
            if (rng_uniform(&g) < 0.3f) {
                sphere sp = {c, 0.02f + 0.2f * size, 0};
                scene_add_sphere(s, sp);
                continue;
            }
            break;
        default:
            break;
        }
        if (scene_add_triangle(s, triangle_make(a, b, d, 0)) < 0) PL_FAIL("out of memory");
    }
}

typedef struct { float key; int prim; } keyed_prim;

static int compare_keys(const void *a, const void *b)
{
    const keyed_prim *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->prim - y->prim;  /* a total order: the tree is the same on every platform */
}

/* Makes out->nodes[node] cover out->prim_index[begin .. end - 1]: a leaf, or two halves. */
static void median_node(bvh *out, const scene *s, keyed_prim *scratch, int node, int begin, int end, int max_leaf_size)
{
    aabb box = aabb_empty(), cb = aabb_empty();
    for (int i = begin; i < end; i++) {
        box = aabb_union(box, scene_prim_bounds(s, out->prim_index[i]));
        cb = aabb_extend(cb, scene_prim_centroid(s, out->prim_index[i]));
    }
    out->nodes[node].box = box;
    int count = end - begin;
    if (count <= max_leaf_size) {
        out->nodes[node].first = begin;
        out->nodes[node].count = count;
        return;
    }
    int axis = aabb_max_axis(cb);
    for (int i = 0; i < count; i++) {
        int p = out->prim_index[begin + i];
        scratch[i] = (keyed_prim){vec3_get(scene_prim_centroid(s, p), axis), p};
    }
    qsort(scratch, (size_t)count, sizeof *scratch, compare_keys);
    for (int i = 0; i < count; i++) out->prim_index[begin + i] = scratch[i].prim;
    int first = out->num_nodes;
    out->num_nodes += 2;
    out->nodes[node].first = first;
    out->nodes[node].count = 0;
    int mid = begin + count / 2;
    median_node(out, s, scratch, first, begin, mid, max_leaf_size);
    median_node(out, s, scratch, first + 1, mid, end, max_leaf_size);
}

void fixture_build_median(bvh *out, const scene *s, int max_leaf_size)
{
    int n = scene_prim_count(s);
    memset(out, 0, sizeof *out);
    if (n == 0) return;
    out->nodes = malloc((2 * (size_t)n - 1) * sizeof *out->nodes);
    out->prim_index = malloc((size_t)n * sizeof *out->prim_index);
    keyed_prim *scratch = malloc((size_t)n * sizeof *scratch);
    if (!out->nodes || !out->prim_index || !scratch) PL_FAIL("out of memory");
    for (int i = 0; i < n; i++) out->prim_index[i] = i;
    out->num_prims = n;
    out->num_nodes = 1;
    median_node(out, s, scratch, 0, 0, n, max_leaf_size);
    free(scratch);
}
