// Inside the glTF shim (C++ only, for gltf_mesh.cc): KHR_materials_variants
// read into the plain mesh (src/scene/mesh/mesh.h variant_*): the root's variant
// names, and for each primitive which material each variant draws it with.
// Its own file: the material reader (gltf_material.cc) stays as it was.
#ifndef MK_GLTF_VARIANTS_H
#define MK_GLTF_VARIANTS_H

#include "scene/gltf/gltf_material.h"
#include "scene/mesh/mesh.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

// More variants than this refuse the file (their table is one index per
// variant and draw range).
#define GLTF_MAX_VARIANTS 256

// A primitive as the builder appended it: its part, and where the file
// has it (meshes[mesh].primitives[primitive], the file's own indices).
struct GltfVariantPart {
	GltfPart part;
	int mesh, primitive;
};

// The file's variants: names[v], and for each primitive named by
// (mesh, primitive) its material in each variant (its default where no
// mapping names the variant).
struct GltfVariants {
	std::vector<std::string> names;
	// per mesh, per primitive, per variant: the material (-2: the default)
	std::vector<std::vector<std::vector<int>>> map;
};

// Reads and checks the extension: every name a string, every mapping's
// material and variant in range. false, with *err naming the field and
// what was expected, when the file is wrong. A file without it has no names.
bool gltf_variants_read(const tinygltf::Model &m, GltfVariants *out, std::string *err);

// gltf_group_ranges with variants: primitives are grouped only with those
// that draw with the same material in every variant, so that each range
// has one material per variant (out->variant_materials), and every
// material a variant uses is a slot (decoded and uploaded with the rest).
// Without variants, gltf_group_ranges itself. Returns 0, -ENOMEM, or
// -EINVAL with *err set.
int gltf_variants_group(const tinygltf::Model &m, const std::vector<GltfVariantPart> &parts,
			const uint32_t *indices, struct mesh *out, std::vector<int> *slots,
			std::string *err);

// After the colours are kept (gltf_keep_colors): a model with variants
// takes each range's base colour from its material (colors_by_material),
// so that a variant's baseColorFactor shows. One with COLOR_0 keeps its
// vertex colours (the default's factor), said once.
void gltf_variants_colors(const tinygltf::Model &m, bool want_colors, const std::string &name,
			  struct mesh *out);

#endif
