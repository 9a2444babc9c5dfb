/* Test machinery: not part of any assignment.
 * Small scenes built in code whose answers are known on paper, plus the plumbing to render them
 * (a scene, its linear-scan accelerator, options and render context in one struct). Every scene
 * here puts an area light AND a coincident emissive quad wherever it has an emitter, as the CS184
 * Cornell boxes do: light sampling sees the light, hemisphere and bounce rays see the quad. */
#ifndef PL_TINY_SCENES_H
#define PL_TINY_SCENES_H

#include <stdint.h>
#include "../../framework/render.h"

/* A scene with everything a render needs. Init after filling s and o; the struct must not move
 * afterwards (ctx points into it). */
typedef struct {
    scene s;
    accel a;
    options o;
    render_ctx ctx;
} tiny_world;

/* Zeroes w and sets default options (options_default, 1 thread, seed 0). */
void tiny_world_begin(tiny_world *w);
/* Builds the accelerator (linear scan: a part's tests never depend on part 2) and the context. */
pl_status tiny_world_finish(tiny_world *w);
/* Re-reads w->o into the context (after changing options). */
void tiny_world_refresh(tiny_world *w);
void tiny_world_free(tiny_world *w);
/* A world on the heap (it is large, and must not move), begun; NULL without memory. */
tiny_world *tiny_world_new(void);
/* Frees a world from tiny_world_new. NULL-safe. */
void tiny_world_destroy(tiny_world *w);
/* cmocka teardown for a group whose setup put a tiny_world_new world in *state. */
int tiny_world_teardown(void **state);

/* ---- building blocks ----------------------------------------------------------------------- */
/* A parallelogram of two triangles centred at c with full edges ea, eb, its face normal turned
 * towards `facing` (ea x eb or its opposite). Returns false without memory. */
bool tiny_add_quad(scene *s, vec3 c, vec3 ea, vec3 eb, vec3 facing, int mat);
/* An emitter: the CGL area light and the coincident emissive quad (albedo 0), emitting towards
 * `facing`. */
bool tiny_add_emitter(scene *s, vec3 c, vec3 ea, vec3 eb, vec3 facing, rgb Le);

/* ---- analytic scenes ----------------------------------------------------------------------- */
/* A diffuse floor (y = 0, 40 x 40 m, albedo rho) under a uniform rectangular emitter of radiance
 * Le facing down, centred at (0, height, 0) with half-sides half_x (along x) and half_z. */
bool tiny_scene_emitter_over_plane(scene *s, float rho, float Le, float half_x, float half_z, float height);
/* The radiance the floor of that scene reflects at (px, 0, pz) by direct light alone:
 * rho * Le * F, with F the form factor from the floor point to the rectangle (closed form). */
double tiny_emitter_over_plane_direct(double rho, double Le, double half_x, double half_z, double height,
                                      double px, double pz);
/* Form factor from a point to a parallel rectangle at distance h with a corner straight above the
 * point and sides x, y: F = 1/(2 pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))],
 * X = x/h, Y = y/h. */
double tiny_corner_form_factor(double x, double y, double h);

/* A diffuse floor (albedo rho) under a point light of intensity I at (0, height, 0) with COLLADA
 * attenuation att[3] (NULL: none). */
bool tiny_scene_point_over_plane(scene *s, float rho, float I, float height, const float *att);
/* Its reflected radiance at (px, 0, pz): rho / pi * I / (c + l d + q d^2) * cos / d^2. */
double tiny_point_over_plane_direct(double rho, double I, double height, const float *att, double px, double pz);

/* The furnace: the inside of the cube [-1, 1]^3, every face diffuse with albedo rho and emitting
 * Le inwards (each face an area light too). Radiance anywhere inside, in any direction: the k-th
 * bounce alone is rho^k Le, bounces 0..m together Le (1 - rho^(m+1)) / (1 - rho), and the full
 * solution Le / (1 - rho). The camera sits at the centre. */
bool tiny_scene_furnace(scene *s, float rho, float Le);

/* A Cornell box: floor, ceiling, back, red left and green right walls of [-1, 1] x [0, 2] x [-1, 1]
 * (open at +z), a 1.0 x 0.8 ceiling light of radiance 5, a box and a sphere; camera at (0, 1, 3.5). */
bool tiny_scene_cornell(scene *s);

/* For adaptive sampling: a camera at the origin looking down -z with hfov 90 degrees at an
 * emissive wall z = -1 (render it with -m 0 at width 32). The left half of the image sees flat
 * grey (Le = 1); the right half sees vertical stripes alternately red (1,0,0) and green (0,1,0),
 * four stripes to a pixel, so a jittered sample is red or green with probability 1/2 each. */
bool tiny_scene_stripes(scene *s);

/* Moves every triangle, sphere and light of s by t (a scene far from the origin, where floats are
 * coarse and a ray from the raw hit point hits its own surface). Before tiny_world_finish: the
 * accel keeps what it derives from each triangle's place (tri_frame, spawn.h). */
void tiny_scene_translate(scene *s, vec3 t);

/* Moves h->p by `fraction` (0..1) of its error bound across the surface, to the side the ray r
 * did not come from: a point within h->p_err that part 1 and the framework may give (on every
 * axis when the surface faces along an axis, as the tests' do). A ray that leaves through spawn.h
 * still clears the surface; one from the raw point hits it. */
void tiny_hit_push_behind(const ray *r, hit *h, float fraction);

/* ---- estimating -------------------------------------------------------------------------- */
/* A hit on the floor (y = 0) at (x, z), seen from straight above. False if the floor is not there. */
bool tiny_floor_hit(const render_ctx *ctx, float x, float z, ray *r, hit *h);

#endif
