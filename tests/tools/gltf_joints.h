/* Writes a GLB of a skinned capsule (the unit sphere stretched to y -2..2)
 * whose vertices are weighted over eight joints: JOINTS_0/WEIGHTS_0 hold
 * the first four of a chain along y, JOINTS_1/WEIGHTS_1 the last four,
 * each vertex's weights falling off with its distance to the joint (most
 * vertices weigh 5 to 8 of them). A clip of 2 s bends every joint but the
 * root about z, LINEAR (0, 15 degrees at 1 s, 0 at 2 s): the capsule
 * curls. Live playback's second joint set (src/scene/gltf_play.cc). */
#ifndef MK_GLTF_JOINTS_H
#define MK_GLTF_JOINTS_H

#include "scene/mesh.h"

/* The joints of the chain, and where joint k lies at bind (y). */
#define GLTF_JOINTS_COUNT 8
#define GLTF_JOINTS_Y(k)  (-2.0 + 0.5 * (k))

/* m: the unit sphere (normals set). 0, or -1 when the file cannot be
 * written. */
int gltf_write_joints8(const char *path, const struct mesh *m);

#endif
