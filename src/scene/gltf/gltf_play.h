// Inside the glTF shim (C++ only): what live playback keeps beside the
// baked mesh (scene/anim_play.h), from the file's own primitives
// (gltf_play.cc).
#ifndef MK_GLTF_PLAY_H
#define MK_GLTF_PLAY_H

#include "scene/anim/anim_play.h"

#include <string>
#include <tiny_gltf.h>
#include <vector>

// A primitive as the builder appended it: the node showing it, the file's
// mesh and primitive, its vertices and indices in the mesh.
struct GltfPlayPart {
	int node, mesh, primitive;
	uint32_t first_vertex, vertex_count, first_index, index_count;
	bool has_normals;
	// Split at its faces for flat normals (gltf_flat.h): source[i] is the
	// primitive's vertex that vertex first_vertex + i copies; NULL: none.
	bool flat;
	const uint32_t *source;
};

// m: the file decoded and dense (gltf_ext::prepare), its skins and
// targets not applied; anim: its animations, read before a still's pose
// was written into its nodes (taken: freed with *out, or here);
// indices: the builder's. *out NULL and err saying why, when the model
// cannot play live (the still stands); an error is no failure of the
// load.
bool gltf_play_build(const tinygltf::Model &m, struct mesh_anim *anim,
		     const std::vector<GltfPlayPart> &parts, const std::vector<uint32_t> &indices,
		     const double center[3], double scale, struct anim_play **out,
		     std::string *err);

// The still's skinned and morphed parts posed by the same engine, once on
// the CPU: m is the file decoded and dense with its nodes at the still's
// pose (gltf_pose_nodes), its skins and targets not applied; positions
// (world, xyz a vertex) and normals (where the part has the file's) of
// each part that a skin or a weighed target moves are overwritten by
// anim_play_pose's at that pose. Parts that neither skin nor morph keep
// the builder's values (their node's world in doubles); the builder
// generates the normals of parts without them from the posed positions.
// false and err naming the field for a skin or target that cannot be read.
bool gltf_play_still(const tinygltf::Model &m, const std::vector<GltfPlayPart> &parts,
		     const std::vector<uint32_t> &indices, std::vector<double> *positions,
		     std::vector<float> *normals, std::string *err);

#endif
