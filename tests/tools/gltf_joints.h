/* Writes a GLB of a skinned capsule (the unit sphere stretched to y -2..2)
 * whose vertices are weighted over a chain of 4 * sets joints along y:
 * JOINTS_0/WEIGHTS_0 hold the first four, JOINTS_1/WEIGHTS_1 the next
 * four, JOINTS_2/WEIGHTS_2 (sets 3) the last four, each vertex's weights
 * falling off with its distance to the joint (with two sets most vertices
 * weigh 5 to 8 of them). A clip of 2 s bends every joint but the root
 * about z, LINEAR (0, 15 degrees at 1 s, 0 at 2 s): the capsule curls.
 * Live playback's joint sets past the first (src/scene/gltf_play.cc). */
#ifndef MK_GLTF_JOINTS_H
#define MK_GLTF_JOINTS_H

#include "scene/mesh/mesh.h"

/* The joint sets a file may have (JOINTS_0 to JOINTS_2, as the bake reads
 * them), the chain's joints at most, and where joint k of n lies at bind
 * (y; 0.5 apart for eight). */
#define GLTF_JOINTS_SETS    3
#define GLTF_JOINTS_MAX	    (4 * GLTF_JOINTS_SETS)
#define GLTF_JOINTS_Y(k, n) (-2.0 + 4.0 * (k) / (n))

/* m: the unit sphere (normals set); sets: 1 to GLTF_JOINTS_SETS. 0, or
 * -1 when the file cannot be written. */
int gltf_write_joints(const char *path, const struct mesh *m, int sets);

#endif
