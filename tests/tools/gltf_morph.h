/* Writes a GLB whose mesh has two morph targets that move positions and
 * normals (the first swells the mesh along its normals, the second shears
 * it and turns its normals), and a clip of 2 s that keys their weights
 * LINEAR (0 0, 1 0.5, 0 1): live playback's morphs at any size (the bench's
 * 100k knot, the tests' sphere). nodes: 1, or 2 nodes showing the mesh
 * side by side, each with its own weights channel (one program cannot
 * hold two nodes' weights: the CPU path). */
#ifndef MK_GLTF_MORPH_H
#define MK_GLTF_MORPH_H

#include "scene/mesh/mesh.h"

/* 0, or -1 when the file cannot be written. */
int gltf_write_morph(const char *path, const struct mesh *m, int nodes);
/* A GLB of this JSON text and binary chunk (padded to 4 bytes): 0 or -1. */
int gltf_write_glb(const char *path, const char *text, size_t tlen, const void *bin, size_t blen);

#endif
