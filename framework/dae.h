/* COLLADA 1.4 scene loading (libxml2), including CS184's <technique profile="CGL"> extensions.
 * scenes/README.md describes the dialect. Z_UP files are turned into pathlab's Y-up world
 * by (x, y, z) -> (-x, z, y), applied before every node transform, as CS184 does.
 * A malformed file is rejected with "path:line: <element>: what was expected" in diag; features
 * that are valid but unsupported load with one warning per feature.
 * The course's profile: a file that uses CS184's CGL extensions and whose <asset><contributor>
 * does not name pathlab (as the course's Blender exports do not, and pathlab's own scenes do) sets
 * scene.course_profile, and is framed by default as CS184's application frames it (camera.h).
 * Parts may not call: any function declared here (the grader refuses them). */
#ifndef PL_DAE_H
#define PL_DAE_H

#include <stddef.h>
#include "scene.h"
#include "status.h"

/* The largest scene file dae_load reads: CS184's biggest scenes are a few MB, a 1M-triangle
 * Blender export about 70 MB. Larger files are refused before a byte is read. */
#define DAE_MAX_FILE_BYTES ((size_t)256 << 20)

/* What one scene may ask for. A 32 KB file can ask for 10^8 triangles through <instance_node>
 * fan-out, so both are bounded before anything is allocated; the message names the element that
 * crossed the limit. A triangle costs about 80 bytes, its BVH share about 40: the default primitive
 * cap keeps a hostile scene near 300 MB; `--max-primitives N` raises it for a real big scene, and
 * `--max-instances N` the instance cap. */
typedef struct {
    long max_primitives;  /* triangles + spheres (2,000,000: ~150 MB of triangles) */
    long max_instances;   /* nodes visited, counting every <instance_node> expansion (1,000,000) */
} dae_limits;

#define DAE_DEFAULT_MAX_PRIMITIVES 2000000L
#define DAE_DEFAULT_MAX_INSTANCES 1000000L
dae_limits dae_limits_default(void);  /* the two defaults above */

/* Every vertex, sphere centre and radius must lie within +-DAE_MAX_COORD after its node
 * transforms: then every sum and product the BVH build forms of them (extents, centroids, surface
 * areas ~ (2e18)^2 * 6) stays finite in float, whose largest value is 3.4e38. */
#define DAE_MAX_COORD 1e18f

/* Loads path into *out (which it initialises). On failure *out is empty and nothing leaks. */
pl_status dae_load(const char *path, scene *out, pl_diag *diag);
/* The same from a buffer; name is used in messages. */
pl_status dae_load_memory(const char *xml, size_t len, const char *name, scene *out, pl_diag *diag);
/* Both with explicit limits (NULL: the defaults). */
pl_status dae_load_limited(const char *path, const dae_limits *limits, scene *out, pl_diag *diag);
pl_status dae_load_memory_limited(const char *xml, size_t len, const char *name, const dae_limits *limits,
                                  scene *out, pl_diag *diag);

#endif
