// KHR_materials_variants: names at the root, mappings per primitive. A
// variant changes which material a range draws with; the materials of
// every variant are read with the default's (gltf_mesh.cc's
// gltf_read_materials decodes every slot), so a switch uploads nothing.
#include "scene/gltf/gltf_variants.h"
#include "util/log.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>

namespace
{

const char ext_name[] = "KHR_materials_variants";

const tinygltf::Value *extension(const tinygltf::ExtensionMap &e)
{
	auto it = e.find(ext_name);
	return it == e.end() ? nullptr : &it->second;
}

bool read_names(const tinygltf::Model &m, GltfVariants *out, std::string *err)
{
	const tinygltf::Value *e = extension(m.extensions);
	if (!e)
		return true;
	const std::string at = std::string("extensions.") + ext_name + ".variants";
	const tinygltf::Value &list = e->Get("variants");
	if (!list.IsArray()) {
		*err = at + ": expected an array of {\"name\": ...}";
		return false;
	}
	// Each variant costs an index per draw range (and per primitive while
	// read): a product has a handful; a file of thousands is a bomb.
	if (list.ArrayLen() > GLTF_MAX_VARIANTS) {
		*err = at + ": " + std::to_string(list.ArrayLen()) +
		       " variants, expected at most " + std::to_string(GLTF_MAX_VARIANTS);
		return false;
	}
	for (size_t v = 0; v < list.ArrayLen(); v++) {
		const tinygltf::Value &name = list.Get((int)v).Get("name");
		if (!name.IsString() || name.Get<std::string>().empty()) {
			*err = at + "[" + std::to_string(v) + "].name: expected a name (a string)";
			return false;
		}
		out->names.push_back(name.Get<std::string>());
	}
	return true;
}

bool read_index(const tinygltf::Value &v, size_t limit, int *out)
{
	if (!v.IsNumber() && !v.IsInt())
		return false;
	double d = v.GetNumberAsDouble();
	if (!(d >= 0 && d < (double)limit) || d != (double)(int)d)
		return false;
	*out = (int)d;
	return true;
}

// One mapping: its material for each variant it lists.
bool read_mapping(const tinygltf::Model &m, const tinygltf::Value &map, const std::string &at,
		  std::vector<int> *per_variant, std::string *err)
{
	int material;
	const tinygltf::Value &vars = map.Get("variants");
	if (!read_index(map.Get("material"), m.materials.size(), &material)) {
		*err = at + ".material: expected one of the file's " +
		       std::to_string(m.materials.size()) + " materials";
		return false;
	}
	for (size_t k = 0; vars.IsArray() && k < vars.ArrayLen(); k++) {
		int v;
		if (!read_index(vars.Get((int)k), per_variant->size(), &v)) {
			*err = at + ".variants[" + std::to_string(k) + "]: expected one of the " +
			       std::to_string(per_variant->size()) + " variants";
			return false;
		}
		(*per_variant)[(size_t)v] = material;
	}
	if (!vars.IsArray()) {
		*err = at + ".variants: expected an array of variant indices";
		return false;
	}
	return true;
}

bool read_primitive(const tinygltf::Model &m, const tinygltf::Primitive &p, const std::string &what,
		    std::vector<int> *per_variant, std::string *err)
{
	const tinygltf::Value *e = extension(p.extensions);
	if (!e)
		return true;
	const std::string at = what + ".extensions." + ext_name + ".mappings";
	const tinygltf::Value &maps = e->Get("mappings");
	if (!maps.IsArray()) {
		*err = at + ": expected an array of {\"material\", \"variants\"}";
		return false;
	}
	for (size_t i = 0; i < maps.ArrayLen(); i++)
		if (!read_mapping(m, maps.Get((int)i), at + "[" + std::to_string(i) + "]",
				  per_variant, err))
			return false;
	return true;
}

bool is_blend(const tinygltf::Model &m, int material)
{
	return material >= 0 && (size_t)material < m.materials.size() &&
	       m.materials[(size_t)material].alphaMode == "BLEND";
}

// Each part's materials: the default, then one per variant.
std::vector<int> signature(const GltfVariants &v, const GltfVariantPart &p)
{
	std::vector<int> sig(1, p.part.material);
	for (size_t k = 0; k < v.names.size(); k++) {
		int mapped = -2;
		if (p.mesh >= 0 && (size_t)p.mesh < v.map.size() &&
		    (size_t)p.primitive < v.map[(size_t)p.mesh].size())
			mapped = v.map[(size_t)p.mesh][(size_t)p.primitive][k];
		sig.push_back(mapped >= 0 ? mapped : p.part.material);
	}
	return sig;
}

size_t slot_of(std::vector<int> *slots, int material)
{
	size_t k = std::find(slots->begin(), slots->end(), material) - slots->begin();
	if (k == slots->size())
		slots->push_back(material);
	return k;
}

int set_names(const GltfVariants &v, struct mesh *out)
{
	out->variant_names = (char **)std::calloc(v.names.size(), sizeof(char *));
	out->variant_materials = (uint32_t *)std::calloc(v.names.size() * out->range_count + 1, 4);
	if (!out->variant_names || !out->variant_materials)
		return -ENOMEM;
	out->variant_count = (uint32_t)v.names.size();
	out->variant_ranges = out->range_count;
	for (size_t k = 0; k < v.names.size(); k++)
		if (!(out->variant_names[k] = strdup(v.names[k].c_str())))
			return -ENOMEM;
	return 0;
}

} // namespace

bool gltf_variants_read(const tinygltf::Model &m, GltfVariants *out, std::string *err)
{
	*out = GltfVariants();
	if (!read_names(m, out, err))
		return false;
	out->map.resize(m.meshes.size());
	for (size_t i = 0; i < m.meshes.size(); i++)
		for (size_t j = 0; j < m.meshes[i].primitives.size(); j++) {
			std::vector<int> per_variant(out->names.size(), -2);
			if (!read_primitive(m, m.meshes[i].primitives[j],
					    "meshes[" + std::to_string(i) + "].primitives[" +
						std::to_string(j) + "]",
					    &per_variant, err))
				return false;
			out->map[i].push_back(per_variant);
		}
	return true;
}

int gltf_variants_group(const tinygltf::Model &m, const std::vector<GltfVariantPart> &parts,
			const uint32_t *indices, struct mesh *out, std::vector<int> *slots_out,
			std::string *err)
{
	GltfVariants v;
	if (!gltf_variants_read(m, &v, err))
		return -EINVAL;
	std::vector<GltfPart> plain;
	for (const GltfVariantPart &p : parts)
		plain.push_back(p.part);
	if (v.names.empty())
		return gltf_group_ranges(m, plain, indices, out, slots_out);
	// Ranges by signature, in the order first drawn; a blended one per
	// part (ordered back to front as the model turns).
	std::vector<std::vector<int>> sigs;
	std::vector<std::vector<size_t>> members;
	for (size_t i = 0; i < parts.size(); i++) {
		if (!parts[i].part.index_count)
			continue;
		std::vector<int> sig = signature(v, parts[i]);
		bool blend =
		    std::any_of(sig.begin(), sig.end(), [&m](int k) { return is_blend(m, k); });
		size_t g =
		    blend ? sigs.size() : std::find(sigs.begin(), sigs.end(), sig) - sigs.begin();
		if (g == sigs.size()) {
			sigs.push_back(sig);
			members.emplace_back();
		}
		members[g].push_back(i);
	}
	// The defaults' materials first (as without variants), then those
	// only a variant uses.
	std::vector<int> slots;
	for (const std::vector<int> &sig : sigs)
		slot_of(&slots, sig[0]);
	for (const std::vector<int> &sig : sigs)
		for (size_t k = 1; k < sig.size(); k++)
			slot_of(&slots, sig[k]);
	if (mesh_alloc_ranges(out, (uint32_t)sigs.size(), (uint32_t)slots.size()) ||
	    set_names(v, out))
		return -ENOMEM;
	uint32_t at = 0;
	for (size_t g = 0; g < sigs.size(); g++) {
		out->ranges[g] = {at, 0, (uint32_t)slot_of(&slots, sigs[g][0]), {0, 0, 0}};
		for (size_t i : members[g]) {
			const GltfPart &p = parts[i].part;
			std::memcpy(out->indices + at, indices + p.first_index,
				    p.index_count * sizeof(uint32_t));
			at += p.index_count;
			out->ranges[g].index_count += p.index_count;
		}
		for (size_t k = 0; k < v.names.size(); k++)
			out->variant_materials[k * sigs.size() + g] =
			    (uint32_t)slot_of(&slots, sigs[g][k + 1]);
	}
	*slots_out = slots;
	mesh_range_centers(out);
	return 0;
}

void gltf_variants_colors(const tinygltf::Model &m, bool want_colors, const std::string &name,
			  struct mesh *out)
{
	bool color_0 = false, coloured = false;
	if (!out->variant_count || !want_colors || !out->material_count)
		return;
	for (const tinygltf::Mesh &mesh : m.meshes)
		for (const tinygltf::Primitive &p : mesh.primitives)
			color_0 |= p.attributes.count("COLOR_0") > 0;
	if (color_0) {
		log_warn("%s: its vertex colours (COLOR_0) keep the default materials' base colour "
			 "factors in every variant (their textures and alpha do change)",
			 name.c_str());
		return;
	}
	for (uint32_t k = 0; k < out->material_count; k++) {
		const struct mesh_material *g = &out->materials[k];
		coloured |=
		    g->has_base_map || g->base_alpha != 1.0f || g->alpha_mode != MESH_ALPHA_OPAQUE;
		for (int c = 0; c < 3; c++)
			coloured |= g->base_color[c] != 1.0f;
	}
	if (!coloured)
		return;
	std::free(out->colors);
	out->colors = nullptr;
	out->colors_by_material = true;
	out->has_colors = true;
	mesh_material_vertex_color(&out->materials[out->ranges[0].material], out->vertex_color);
}
