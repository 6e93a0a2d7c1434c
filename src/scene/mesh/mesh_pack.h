/* The mesh as the GPU reads it: one array per attribute, in the vertex
 * format chosen, ready to upload as they are (from memory, or from a
 * mapped cache entry: src/scene/mesh/mesh_cache.h). */
#ifndef MK_MESH_PACK_H
#define MK_MESH_PACK_H

#include "scene/mesh/mesh.h"

#include <stddef.h>
#include <stdint.h>

/* float32 throughout, or compact: positions and unit vectors as
 * normalized int16 (half the memory; the UVs stay float, since a repeated
 * map's UVs leave [0, 1]), colours as normalized uint8 (as glTF's own
 * COLOR_0 may be). */
enum vertex_format { VERTEX_FLOAT32, VERTEX_COMPACT };

/* In the order of the shaders' attribute indices (render/shader.h).
 * MESH_UV1: the second UV set, float as the first (struct mesh uv1). */
enum mesh_array {
	MESH_POSITIONS,
	MESH_NORMALS,
	MESH_UVS,
	MESH_TANGENTS,
	MESH_COLORS,
	MESH_UV1,
	MESH_ARRAYS
};

/* How an array's components are stored. */
enum mesh_component { MESH_FLOAT32, MESH_SNORM16, MESH_UNORM8 };

struct mesh_packed {
	enum vertex_format format;
	uint32_t vertex_count, index_count;
	/* Compact positions are in units of this (the mesh's largest
	 * coordinate): the model-view scales them back. 1 for float32. */
	float position_scale;
	const void *arrays[MESH_ARRAYS]; /* NULL: the mesh has none */
	const uint32_t *indices;
	/* The mesh's draw ranges (struct mesh ranges); none: one range over
	 * every index with the default material (mesh_material_at). */
	uint32_t range_count;
	const struct mesh_range *ranges;
	void *owned; /* what mesh_packed_release frees; NULL: borrowed */
	void *owned_ranges;
};

/* Components per vertex of an array, and bytes per vertex in a format. */
int mesh_array_components(enum mesh_array a);
size_t mesh_array_stride(enum vertex_format f, enum mesh_array a);
/* Whether the array is stored as normalized int16 in that format. */
bool mesh_array_int16(enum vertex_format f, enum mesh_array a);
enum mesh_component mesh_array_component(enum vertex_format f, enum mesh_array a);

/* m in format f. float32 borrows m's arrays (m must outlive out); compact
 * converts them, and copies the indices, into one allocation of its own.
 * Returns 0 or -ENOMEM. */
int mesh_pack(const struct mesh *m, enum vertex_format f, struct mesh_packed *out);
void mesh_packed_release(struct mesh_packed *p);

#endif
