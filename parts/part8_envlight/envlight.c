/* Part 8, tasks 8.1 to 8.4: the environment light. Handout: handout/part8.md. */
#include "part8.h"
#include "../../framework/sampler.h"
#include "../../framework/todo.h"
#include <math.h>
#include <stdlib.h>  /* malloc and free: task 8.2 may want a table of its own (the row weights, say) */

/* === PART 8 | TASK 8.1 | env_sample_uniform ===========================================
 * The environment light sampled uniformly over the sphere (handout/part8.md, section 8.1).
 * In:  e, the map; u in [0,1)^2, uniform.
 * Out: *wi, a unit direction, every region of the sphere drawn in proportion to its solid angle;
 *      *pdf = 1 / (4 pi); returns the radiance arriving from *wi (envmap_radiance).
 * Must: the mean of L cos / pdf over the upper hemisphere of a surface is its irradiance; half the
 *       directions fall below any surface (the light estimator skips them), which is the price of
 *       not looking at the map.
 * Test: make test-part8
 * ====================================================================================== */
rgb env_sample_uniform(const envmap *e, vec2 u, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    *wi = sample_uniform_sphere(u);
    *pdf = sample_uniform_sphere_pdf(*wi);
    return envmap_radiance(e, *wi);
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 1.0f, 0.0f); *pdf = 1.0f; return PL_TODO_RGB("8.1", "env_sample_uniform"); */
}

/* BEGIN SOLUTION */
/* Turns n weights into a CDF of n + 1 entries, summed in double; all-zero weights give the uniform
 * CDF. Returns the weights' total. */
static double weights_to_cdf(float *cdf, int n, double (*weight)(const envmap *, int, int), const envmap *e, int row)
{
    double total = 0.0;
    for (int i = 0; i < n; i++) total += weight(e, i, row);
    double sum = 0.0;
    cdf[0] = 0.0f;
    for (int i = 0; i < n; i++) {
        sum += weight(e, i, row);
        cdf[i + 1] = total > 0.0 ? (float)(sum / total) : (float)(i + 1) / (float)n;
    }
    cdf[n] = 1.0f;
    return total;
}

static double texel_weight(const envmap *e, int x, int y) { return rgb_luminance(envmap_texel(e, x, y)); }

/* A row's weight: its texels' luminance, times sin(theta) at its centre. */
static double row_weight(const envmap *e, int y, int unused)
{
    (void)unused;
    double sum = 0.0;
    for (int x = 0; x < e->width; x++) sum += texel_weight(e, x, y);
    return sum * sin(((double)y + 0.5) * M_PI / e->height);
}
/* END SOLUTION */

/* === PART 8 | TASK 8.2 | env_build_distribution =======================================
 * The tables that importance-sample the map (handout/part8.md, section 8.2).
 * In:  e, the map (e->width x e->height texels); d, tables the framework allocated for it.
 * Out: d->marginal_cdf[y] = P(row < y) and, for each row y, d->conditional_cdf[y (width + 1) + x]
 *      = P(column < x | row y), for texel weights w(x, y) = luminance(texel) * sin(theta_y),
 *      theta_y the polar angle of row y's centre, (y + 1/2) pi / height.
 * Must: each table starts at 0, never decreases and ends at 1; a texel's probability is
 *       proportional to its weight (sin(theta) because a row near a pole covers less of the
 *       sphere); a row of weight 0 still gets a CDF (any, say uniform): it is never drawn; an all-
 *       black map gets uniform tables.
 * Test: make test-part8
 * ====================================================================================== */
void env_build_distribution(const envmap *e, env_distribution *d)
{
    /* BEGIN SOLUTION */
    for (int y = 0; y < e->height; y++)
        weights_to_cdf(d->conditional_cdf + (size_t)y * (e->width + 1), e->width, texel_weight, e, y);
    weights_to_cdf(d->marginal_cdf, e->height, row_weight, e, 0);
    /* END SOLUTION */
    /* STUB: (void)e, (void)d; (void)PL_TODO("8.2", "env_build_distribution"); */
}

/* === PART 8 | TASK 8.3 | env_pdf ========================================================
 * The density per steradian of env_sample_importance's directions (handout/part8.md, 8.3).
 * In:  e, d (tables filled by task 8.2); wi, a direction (unit).
 * Out: p(x, y) * width * height / (2 pi^2 sin(theta)), where (x, y) is the texel wi falls in,
 *      p(x, y) its probability in d's tables (the marginal's step at y times row y's step at x)
 *      and theta wi's polar angle (envmap_angles); 0 where sin(theta) is 0.
 * Must: integrates to 1 over the sphere; without the 1 / sin(theta) (the Jacobian of the
 *       mapping) the light is too bright near the horizon and too dark near the poles.
 * Test: make test-part8
 * ====================================================================================== */
float env_pdf(const envmap *e, const env_distribution *d, vec3 wi)
{
    /* BEGIN SOLUTION */
    vec2 a = envmap_angles(wi);
    /* sin(theta) from the direction itself: sinf(a.x) loses digits near a pole, where acos does. */
    float s = hypotf(wi.x, wi.z) / vec3_length(wi);
    if (!(s > 0.0f))
        return 0.0f;
    int x = (int)(a.y * (0.5f / PL_PI) * (float)e->width), y = (int)(a.x / PL_PI * (float)e->height);
    x = x < 0 ? 0 : x >= e->width ? e->width - 1 : x;
    y = y < 0 ? 0 : y >= e->height ? e->height - 1 : y;
    const float *row = d->conditional_cdf + (size_t)y * (e->width + 1);
    float p = (d->marginal_cdf[y + 1] - d->marginal_cdf[y]) * (row[x + 1] - row[x]);
    return p * (float)e->width * (float)e->height / (2.0f * PL_PI * PL_PI * s);
    /* END SOLUTION */
    /* STUB: return (float)PL_TODO_FALSE("8.3", "env_pdf"); */
}

/* BEGIN SOLUTION */
/* The interval i of a CDF of n intervals with cdf[i] <= u < cdf[i + 1]: never an empty one. */
static int find_interval(const float *cdf, int n, float u)
{
    int lo = 0, hi = n;
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (cdf[mid] <= u) lo = mid;
        else hi = mid;
    }
    return lo;
}
/* END SOLUTION */

/* === PART 8 | TASK 8.4 | env_sample_importance ==========================================
 * The environment light sampled in proportion to its brightness (handout/part8.md, 8.4).
 * In:  e, d (task 8.2's tables); u in [0,1)^2, uniform.
 * Out: the row y with marginal_cdf[y] <= u.y < marginal_cdf[y + 1], then the column x with the
 *      same property in row y's conditional CDF for u.x, each found by binary search (O(log n));
 *      the point within the texel where each number fell within its step, as angles
 *      theta = (y + fy) pi / height, phi = (x + fx) 2 pi / width; *wi = envmap_direction(theta,
 *      phi); *pdf = env_pdf(e, d, *wi); returns the texel's radiance.
 * Must: the histogram of the directions matches env_pdf (chi-square); the mean of L cos / pdf
 *       equals task 8.1's (the same light), with far less noise on a map with a sun.
 * Test: make test-part8
 * ====================================================================================== */
rgb env_sample_importance(const envmap *e, const env_distribution *d, vec2 u, vec3 *wi, float *pdf)
{
    /* BEGIN SOLUTION */
    int y = find_interval(d->marginal_cdf, e->height, u.y);
    const float *row = d->conditional_cdf + (size_t)y * (e->width + 1);
    int x = find_interval(row, e->width, u.x);
    float py = d->marginal_cdf[y + 1] - d->marginal_cdf[y], px = row[x + 1] - row[x];
    /* Where each number fell within its step, reused as the position within the texel. */
    float fy = fminf((u.y - d->marginal_cdf[y]) / py, 0.99999994f), fx = fminf((u.x - row[x]) / px, 0.99999994f);
    float theta = ((float)y + fy) * PL_PI / (float)e->height, phi = ((float)x + fx) * 2.0f * PL_PI / (float)e->width;
    *wi = envmap_direction(theta, phi);
    float s = sinf(theta);
    *pdf = s > 0.0f ? px * py * (float)e->width * (float)e->height / (2.0f * PL_PI * PL_PI * s) : 0.0f;
    return envmap_texel(e, x, y);
    /* END SOLUTION */
    /* STUB: *wi = vec3_make(0.0f, 1.0f, 0.0f); *pdf = 1.0f; return PL_TODO_RGB("8.4", "env_sample_importance"); */
}
