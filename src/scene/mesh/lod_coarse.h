/* A coarse stand-in for a large model: what the live kiosk shows while
 * the model's level of detail (lod.h) is still being prepared, so that a
 * scan of a million triangles is on the screen in a fraction of a second
 * rather than after its whole simplification (content/content_coarse.c).
 * Never drawn in a still, never cached. */
#ifndef MK_LOD_COARSE_H
#define MK_LOD_COARSE_H

#include "scene/mesh/mesh.h"

/* The fewest triangles a range keeps, however small its share: a part
 * of the model stays a shape, not a hole. */
#define LOD_COARSE_RANGE_MIN 16

/* m cut down to about `triangles` in all into out (out is overwritten):
 * meshoptimizer's sloppy simplifier (no quality bound, linear in the
 * model's size: its cost is fixed per triangle, not by the error it
 * meets) on each range alone, each keeping its material and a share of
 * the count by its size, at least LOD_COARSE_RANGE_MIN; then only the
 * vertices the result uses, each with all its attributes, and the
 * materials' factors (no image: the renderer draws the maps from the
 * resolved material). Variant tables and the flat-split flags are not
 * carried. Returns 0, -EINVAL for a model with nothing to cut (no
 * triangle, or variants), or -ENOMEM (out is then empty). */
int lod_coarse_mesh(const struct mesh *m, uint32_t triangles, struct mesh *out);

#endif
