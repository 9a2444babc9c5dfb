/* COLLADA 1.4 scene loading (libxml2), including CS184's <technique profile="CGL"> extensions.
 * See ../shared/CS184_FORMAT.md for the dialect. Z_UP files are turned into pathlab's Y-up world
 * by (x, y, z) -> (-x, z, y), applied before every node transform, as CS184 does.
 * A malformed file is rejected with "path:line: <element>: what was expected" in diag; features
 * that are valid but unsupported load with one warning per feature. */
#ifndef PL_DAE_H
#define PL_DAE_H

#include <stddef.h>
#include "scene.h"
#include "status.h"

/* The largest scene file dae_load reads: CS184's biggest scenes are a few MB, a 1M-triangle
 * Blender export about 70 MB. Larger files are refused before a byte is read. */
#define DAE_MAX_FILE_BYTES ((size_t)256 << 20)

/* Loads path into *out (which it initialises). On failure *out is empty and nothing leaks. */
pl_status dae_load(const char *path, scene *out, pl_diag *diag);
/* The same from a buffer; name is used in messages. */
pl_status dae_load_memory(const char *xml, size_t len, const char *name, scene *out, pl_diag *diag);

#endif
