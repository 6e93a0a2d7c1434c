// Inside the glTF shim (C++ only): a primitive without normals split at
// its faces, as glTF requires (flat normals): every triangle corner a
// vertex of its own, so that a face's normal is not averaged with its
// neighbours' (gltf_mesh.cc; live playback maps the copies back to the
// file's vertices with source, gltf_play.cc).
#ifndef MK_GLTF_FLAT_H
#define MK_GLTF_FLAT_H

#include "scene/mesh/mesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

// The builder's arrays a split rewrites (colors and uv1 may be empty or
// shorter: one colour, no second UV set yet).
struct GltfSplit {
	std::vector<double> *positions;
	std::vector<float> *normals, *uvs, *colors, *uv1;
	std::vector<uint32_t> *indices;
	std::vector<uint32_t> *source; // each copy's vertex in its primitive
};

// The primitive appended last (vertices from first_vertex on, indices from
// first_index on) as one vertex per index, in index order; its tangents are
// not kept (glTF ignores them without normals). Returns its vertex count.
uint32_t gltf_split_faces(const GltfSplit &s, size_t first_vertex, size_t first_index);

// out->flat set over the vertices of a split primitive (first_vertex,
// vertex_count), allocated at the first. Returns 0 or -ENOMEM.
int gltf_tag_flat(struct mesh *out, uint32_t first_vertex, uint32_t vertex_count);

// The normals of a primitive that lacks the file's (has_normals false):
// flat (split by gltf_split_faces) or averaged. Returns 0 or -ENOMEM.
int gltf_range_normals(struct mesh *out, const uint32_t *idx, uint32_t index_count,
		       uint32_t first_vertex, uint32_t vertex_count, bool has_normals, bool flat);

#endif
