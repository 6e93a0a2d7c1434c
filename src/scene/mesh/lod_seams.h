/* The level of detail's pass over welded seams (lod.c's
 * simplify_seamless tries it where seams stop meshoptimizer short). */
#ifndef MK_LOD_SEAMS_H
#define MK_LOD_SEAMS_H

#include "scene/mesh/mesh.h"

#include <stdbool.h>
#include <stddef.h>

/* When seams stop meshoptimizer 0.18 short of the count (split normals
 * and UV islands lock most of a real model), simplify the surface over
 * its positions and uvs (creases welded, UV seams kept), or its
 * positions alone (UV islands welded too: a texture may then stretch
 * across a seam), then give each corner back the attributes of its side.
 * out: room for m's index count.
 * Returns the index count, 0 when it cannot do better. */
size_t lod_simplify_welded(const struct mesh *m, bool by_uv, double wanted, double target,
			   unsigned options, unsigned *out, float *error);

#endif
