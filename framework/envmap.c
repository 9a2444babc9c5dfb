/* Environment maps (envmap.h): reading one, and the latitude-longitude mapping. */
#include "envmap.h"
#include "exr.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- making and freeing ------------------------------------------------------------------------ */

static pl_status envmap_alloc(envmap *e, int width, int height, pl_diag *diag)
{
    memset(e, 0, sizeof *e);
    if (width < 1 || height < 1 || width > ENVMAP_MAX_SIDE || height > ENVMAP_MAX_SIDE ||
        (long)width * height > ENVMAP_MAX_TEXELS)
        return pl_fail(diag, PL_ERR_INVALID, "an environment map of %dx%d texels: expected 1 to %d a side and at "
                       "most %ld in all", width, height, ENVMAP_MAX_SIDE, ENVMAP_MAX_TEXELS);
    e->texels = malloc((size_t)width * height * sizeof *e->texels);
    if (!e->texels) return pl_fail(diag, PL_ERR_NOMEM, "out of memory for a %dx%d environment map", width, height);
    e->width = width, e->height = height;
    return PL_OK;
}

pl_status envmap_make_constant(envmap *e, int width, int height, rgb L)
{
    pl_status s = envmap_alloc(e, width, height, NULL);
    for (long k = 0; s == PL_OK && k < (long)width * height; k++) e->texels[k] = L;
    return s;
}

pl_status envmap_load(const char *path, envmap *e, pl_diag *diag)
{
    memset(e, 0, sizeof *e);
    exr_rgb_image img;
    pl_status s = exr_read_rgb(path, ENVMAP_MAX_SIDE, ENVMAP_MAX_TEXELS, &img, diag);
    if (s == PL_OK) s = envmap_alloc(e, img.width, img.height, diag);
    for (long k = 0; s == PL_OK && k < (long)img.width * img.height; k++)
        e->texels[k] = rgb_make(img.texels[3 * k], img.texels[3 * k + 1], img.texels[3 * k + 2]);
    if (s == PL_OK) snprintf(e->path, sizeof e->path, "%s", path);
    free(img.texels);
    return s;
}

void envmap_free(envmap *e)
{
    if (!e) return;
    free(e->texels);
    memset(e, 0, sizeof *e);
}

/* ---- the mapping ------------------------------------------------------------------------------- */

vec2 envmap_angles(vec3 d)
{
    float len = vec3_length(d);
    float y = len > 0.0f ? d.y / len : 1.0f;
    /* Rounding can take |y| a hair past 1, where acos is NaN. */
    float theta = acosf(fminf(1.0f, fmaxf(-1.0f, y)));
    return vec2_make(theta, atan2f(-d.z, d.x) + PL_PI);
}

vec3 envmap_direction(float theta, float phi)
{
    float s = sinf(theta);
    /* x = cos(phi - pi) sin(theta), z = -sin(phi - pi) sin(theta): CS184's, written without the shift. */
    return vec3_make(-cosf(phi) * s, cosf(theta), sinf(phi) * s);
}

rgb envmap_texel(const envmap *e, int x, int y) { return e->texels[(size_t)y * e->width + x]; }

vec2 envmap_texel_coords(const envmap *e, vec3 d)
{
    vec2 a = envmap_angles(d);
    return vec2_make(a.y * (0.5f / PL_PI) * (float)e->width, a.x / PL_PI * (float)e->height);
}

rgb envmap_radiance(const envmap *e, vec3 d)
{
    /* phi = 2 pi (d.z = -0 on the -x axis) and theta = pi land one past the last texel: clamped,
     * before the conversion to int, so that a NaN direction (a broken part's ray) reads texel 0
     * rather than converting NaN, which C leaves undefined. */
    vec2 c = envmap_texel_coords(e, d);
    float u = c.x, v = c.y;
    int x = u >= 0.0f && u < (float)e->width ? (int)u : u >= (float)e->width ? e->width - 1 : 0;
    int y = v >= 0.0f && v < (float)e->height ? (int)v : v >= (float)e->height ? e->height - 1 : 0;
    return envmap_texel(e, x, y);
}

/* ---- part 8's tables ------------------------------------------------------------------------- */

pl_status env_distribution_alloc(env_distribution *d, int width, int height)
{
    memset(d, 0, sizeof *d);
    d->marginal_cdf = calloc((size_t)height + 1, sizeof *d->marginal_cdf);
    d->conditional_cdf = calloc((size_t)height * ((size_t)width + 1), sizeof *d->conditional_cdf);
    if (!d->marginal_cdf || !d->conditional_cdf) {
        env_distribution_free(d);
        return PL_ERR_NOMEM;
    }
    d->width = width, d->height = height;
    return PL_OK;
}

void env_distribution_free(env_distribution *d)
{
    if (!d) return;
    free(d->marginal_cdf);
    free(d->conditional_cdf);
    memset(d, 0, sizeof *d);
}

/* Whether c, of n intervals (n + 1 entries), is a CDF; if not, why says what is wrong with it. */
static bool cdf_ok(const float *c, int n, const char *name, char *why, size_t size)
{
    if (c[0] != 0.0f) return snprintf(why, size, "%s: entry 0 is %g, expected 0", name, (double)c[0]), false;
    for (int i = 1; i <= n; i++)
        if (!isfinite(c[i]) || c[i] < c[i - 1])
            return snprintf(why, size, "%s: entry %d is %g, below entry %d's %g or not a number", name, i, (double)c[i],
                            i - 1, (double)c[i - 1]), false;
    if (fabsf(c[n] - 1.0f) > 1e-5f) return snprintf(why, size, "%s: entry %d, the last, is %g: expected 1", name, n, (double)c[n]), false;
    return true;
}

bool env_distribution_check(env_distribution *d, char *why, size_t size)
{
    d->valid = false;
    if (!cdf_ok(d->marginal_cdf, d->height, "marginal_cdf", why, size)) return false;
    for (int y = 0; y < d->height; y++) {
        char name[48];
        snprintf(name, sizeof name, "conditional_cdf row %d", y);
        /* A row the marginal never draws may hold anything finite in order; it must still be a CDF,
         * so that a sampler reading it cannot run off its end. */
        if (!cdf_ok(d->conditional_cdf + (size_t)y * (d->width + 1), d->width, name, why, size)) return false;
    }
    d->valid = true;
    return true;
}
