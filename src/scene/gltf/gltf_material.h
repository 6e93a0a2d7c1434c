// Inside the glTF shim (C++ only, for gltf.cc and gltf_mesh.cc): the model's
// material, its factors and the textures a scene asked for, into the plain
// mesh_material of src/scene/mesh/mesh.h. Split from gltf.cc to keep each file short.
#ifndef MK_GLTF_MATERIAL_H
#define MK_GLTF_MATERIAL_H

#include "scene/gltf/gltf_texture.h"
#include "scene/mesh/mesh.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

struct GltfFiles;

// Bytes of the images that tinygltf read from a URI (a file in the model's
// folder or below it, or a data: URI), by image index, kept by
// gltf_keep_image when a texture may be wanted. Images in a bufferView are
// read from the buffer, with our own bounds checks.
// What decoding made smaller, for the one journal line that says so.
struct GltfScaled {
	unsigned decoded = 0, scaled = 0, budget = 0; // budget: halved for the budget
	int from[2] = {0, 0}, to[2] = {0, 0};	      // the largest one scaled
};

struct GltfImages {
	bool keep = false;
	const struct GltfFiles *files = nullptr; // to say why a URI's file was not read
	std::vector<std::vector<unsigned char>> bytes;
	// How large a decoded texture may be (gltf_fit_textures), and what was
	// made smaller: decode state, set while the bytes above are read only.
	mutable struct image_fit fit = {0, 0};
	mutable GltfScaled scaled;
};

// tinygltf's image callback: decodes nothing, keeps URI images' bytes.
bool gltf_keep_image(tinygltf::Image *image, const int index, std::string *err, std::string *warn,
		     int req_width, int req_height, const unsigned char *bytes, int size,
		     void *user);

// A primitive's part of the base colour (struct mesh colors): rgb its
// material's baseColorFactor, a 1 (COLOR_0's alpha multiplies it).
// Returns whether the material colours the model at all (a factor or a
// base map).
bool gltf_primitive_base(const tinygltf::Model &m, int material, float rgba[4]);

// Colours that change nothing (white, every material opaque and without a
// base map decoded, which only a base colour program draws) are given
// back; mesh.has_colors says what is left.
// uniform: every vertex's colour when the mesh has no colour array (one
// colour for the whole model), or null.
void gltf_keep_colors(struct mesh *out, const float uniform[4]);

// Which TEXCOORD_n a primitive of this material loads as the mesh's UVs:
// the base map's (its texCoord, or its KHR_texture_transform's), when it
// is asked for and no other texture asked for needs TEXCOORD_0; else 0.
int gltf_uv_set(const tinygltf::Model &m, int material, unsigned textures);

// Which TEXCOORD_n a primitive of this material loads as the mesh's uv1:
// its emissive map's, when the map is drawn (a factor not black) and reads
// another set than gltf_uv_set's; else -1 (no second set: the common case,
// which costs nothing).
int gltf_emissive_uv_set(const tinygltf::Model &m, int material, unsigned textures);

// A primitive's triangles in the builder's index array, and its material
// (-1: none).
struct GltfPart {
	uint32_t first_index, index_count;
	int material;
};

// The primitives' triangles into out's indices, grouped by material in the
// order materials are first used: one range for every opaque or masked
// material (one draw each, however many primitives share it), one per
// primitive for a blended one (ordered back to front as the model turns).
// slots[k]: the glTF material of out->materials[k], for gltf_read_material.
// Returns 0 or -ENOMEM.
int gltf_group_ranges(const tinygltf::Model &m, const std::vector<GltfPart> &parts,
		      const uint32_t *indices, struct mesh *out, std::vector<int> *slots);

// Every range's material (slots[k] for out->materials[k]) with its own
// textures, each decoded once. textures: 0
// where the model has no UVs (no texture can be placed). Moved here from
// gltf_mesh.cc, which is at its length.
void gltf_read_materials(const tinygltf::Model &m, const std::vector<int> &slots,
			 const std::string &name, unsigned textures, size_t budget,
			 const GltfImages &images, struct mesh *out);

// Fill out from material `index` (-1: none). textures: enum gltf_texture
// bits asked for (they chose the UV set: gltf_uv_set); of those, decode
// the ones in `decode`. A texture that cannot be used is logged as a
// warning naming `name` and left empty.
void gltf_read_material(const tinygltf::Model &m, int index, unsigned textures, unsigned decode,
			const GltfImages &images, const std::string &name,
			struct mesh_material *out);

// Share `budget` bytes (0: none) among the maps the materials in `slots`
// decode of `textures`, each at most GLTF_TEXTURE_SIDE a side, into
// images.fit.
void gltf_fit_textures(const tinygltf::Model &m, const std::vector<int> &slots, unsigned textures,
		       size_t budget, const GltfImages &images);
// One line when textures were made smaller as they were decoded.
void gltf_say_scaled(const std::string &name, const GltfImages &images, size_t budget);

#endif
