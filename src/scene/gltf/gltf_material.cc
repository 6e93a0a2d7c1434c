// Each range's material for the optional features (src/scene/mesh/material.c): factors
// always, textures only when asked, decoded by src/util/image.c. As for
// buffers, nothing tinygltf hands back is trusted: every index, offset and
// length is checked here before a byte is read.
#include "scene/gltf/gltf_material.h"
#include "scene/gltf/gltf_ext.h"
#include "scene/gltf/gltf_fs.h"
#include "util/log.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <string>

namespace
{

double number(const tinygltf::Value &obj, const char *key, double fallback, double lo, double hi)
{
	if (!obj.IsObject() || !obj.Has(key))
		return fallback;
	const tinygltf::Value &v = obj.Get(key);
	if (!v.IsNumber() && !v.IsInt())
		return fallback;
	double x = v.GetNumberAsDouble();
	return std::isfinite(x) ? std::fmin(std::fmax(x, lo), hi) : fallback;
}

// A texture extension's image (EXT_texture_webp, KHR_texture_basisu), or -1.
int extension_source(const tinygltf::Texture &t, const char *ext)
{
	auto it = t.extensions.find(ext);
	if (it == t.extensions.end() || !it->second.IsObject() || !it->second.Has("source"))
		return -1;
	const tinygltf::Value &v = it->second.Get("source");
	return v.IsInt() || v.IsNumber() ? v.GetNumberAsInt() : -1;
}

// The images a texture may read, the file's choice first: its WebP
// (EXT_texture_webp), then `source`, the fallback for a viewer without
// WebP, tried when the WebP cannot be decoded. The count (0, 1 or 2) after
// saying why none is used.
int texture_images(const tinygltf::Model &m, int texture, int tex_coord, const std::string &name,
		   const char *what, int out[2])
{
	int n = 0;
	if (tex_coord != 0) {
		log_warn("%s: %s reads TEXCOORD_%d, and only TEXCOORD_0 is loaded: not used",
			 name.c_str(), what, tex_coord);
		return 0;
	}
	if (texture < 0 || (size_t)texture >= m.textures.size()) {
		log_warn("%s: %s: texture %d does not exist: not used", name.c_str(), what,
			 texture);
		return 0;
	}
	const tinygltf::Texture &t = m.textures[(size_t)texture];
	for (int source : {extension_source(t, "EXT_texture_webp"), t.source})
		if (source >= 0 && (size_t)source < m.images.size() && (n == 0 || out[0] != source))
			out[n++] = source;
	if (n == 0 && extension_source(t, "KHR_texture_basisu") >= 0)
		log_warn("%s: %s: texture %d is KTX2 only (KHR_texture_basisu): no KTX2 transcoder "
			 "in Debian 12/13, and no PNG, JPEG or WebP source: not used",
			 name.c_str(), what, texture);
	else if (n == 0)
		log_warn("%s: %s: texture %d has no PNG, JPEG or WebP image (source %d): not used",
			 name.c_str(), what, texture, t.source);
	return n;
}

bool image_bytes(const tinygltf::Model &m, int index, const GltfImages &images,
		 const unsigned char **data, size_t *size, std::string *why)
{
	const tinygltf::Image &img = m.images[(size_t)index];
	if (img.bufferView >= 0) {
		if ((size_t)img.bufferView >= m.bufferViews.size()) {
			*why = "bufferView " + std::to_string(img.bufferView) + " does not exist";
			return false;
		}
		const tinygltf::BufferView &bv = m.bufferViews[(size_t)img.bufferView];
		if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size()) {
			*why = "buffer " + std::to_string(bv.buffer) + " does not exist";
			return false;
		}
		const std::vector<unsigned char> &buf = m.buffers[(size_t)bv.buffer].data;
		size_t end;
		if (__builtin_add_overflow(bv.byteOffset, bv.byteLength, &end) ||
		    end > buf.size()) {
			*why = "bufferView " + std::to_string(img.bufferView) +
			       " runs past the end of its buffer (" + std::to_string(buf.size()) +
			       " bytes)";
			return false;
		}
		*data = buf.data() + bv.byteOffset;
		*size = bv.byteLength;
		return true;
	}
	if ((size_t)index < images.bytes.size() && !images.bytes[(size_t)index].empty()) {
		*data = images.bytes[(size_t)index].data();
		*size = images.bytes[(size_t)index].size();
		return true;
	}
	*why = img.uri.empty() ? "has no data"
			       : "\"" + img.uri + "\" " +
				     (images.files ? gltf_uri_fault(*images.files, img.uri)
						   : std::string("could not be read"));
	return false;
}

// Image `source` of a texture into out; false after saying why not.
bool read_image(const tinygltf::Model &m, int source, const GltfImages &images,
		const std::string &name, const char *what, struct image *out, int full[2],
		unsigned &decoded)
{
	const unsigned char *data = nullptr;
	size_t size = 0;
	std::string why;
	if (!image_bytes(m, source, images, &data, &size, &why)) {
		log_warn("%s: %s: image %d %s: not used", name.c_str(), what, source, why.c_str());
		return false;
	}
	std::string label = name + " " + what + " (image " + std::to_string(source) + ")";
	decoded++;
	return image_decode_fit(label.c_str(), data, size, &images.fit, out, &full[0], &full[1]) ==
	       0;
}

void read_texture(const tinygltf::Model &m, int texture, int tex_coord, const GltfImages &images,
		  const std::string &name, const char *what, struct image *out, unsigned &decoded)
{
	int sources[2];
	int n = texture_images(m, texture, tex_coord, name, what, sources);
	int full[2] = {0, 0};
	int i = 0;
	while (i < n && !read_image(m, sources[i], images, name, what, out, full, decoded)) {
		if (i + 1 < n)
			log_warn("%s: %s: image %d instead (the texture's source)", name.c_str(),
				 what, sources[i + 1]);
		i++;
	}
	if (i == n) {
		if (n)
			log_warn("%s: %s is not used", name.c_str(), what);
		return;
	}
	GltfScaled &s = images.scaled;
	s.decoded++;
	if (out->width == full[0] && out->height == full[1])
		return;
	s.scaled++;
	struct image_fit side = {images.fit.side, 0};
	int w, h;
	image_fit_shifts(full[0], full[1], &side, nullptr, nullptr, &w, &h);
	s.budget += out->width != w || out->height != h;
	if ((size_t)full[0] * (size_t)full[1] >= (size_t)s.from[0] * (size_t)s.from[1]) {
		s.from[0] = full[0], s.from[1] = full[1];
		s.to[0] = out->width, s.to[1] = out->height;
	}
}

void read_iridescence(const tinygltf::Material &mat, struct mesh_material *out, int *thickness,
		      int *thickness_coord)
{
	auto it = mat.extensions.find("KHR_materials_iridescence");
	if (it == mat.extensions.end() || !it->second.IsObject())
		return;
	const tinygltf::Value &v = it->second;
	out->iridescence = true;
	out->iridescence_factor = (float)number(v, "iridescenceFactor", 0.0, 0.0, 1.0);
	out->iridescence_ior = (float)number(v, "iridescenceIor", 1.3, 1.0, 5.0);
	out->thickness_min = (float)number(v, "iridescenceThicknessMinimum", 100.0, 0.0, 1e4);
	out->thickness_max = (float)number(v, "iridescenceThicknessMaximum", 400.0, 0.0, 1e4);
	const tinygltf::Value &t = v.Get("iridescenceThicknessTexture");
	if (t.IsObject() && t.Has("index")) {
		out->has_thickness_map = true;
		*thickness = (int)number(t, "index", -1, -1, 1e9);
		*thickness_coord = (int)number(t, "texCoord", 0, 0, 1e9);
	}
}

// Element k of a two-number array, kept finite and in a sane range.
double element(const tinygltf::Value &a, int k, double fallback)
{
	if (!a.IsArray() || a.ArrayLen() != 2)
		return fallback;
	const tinygltf::Value &v = a.Get(k);
	double x = v.IsNumber() || v.IsInt() ? v.GetNumberAsDouble() : fallback;
	return std::isfinite(x) ? std::fmin(std::fmax(x, -1e6), 1e6) : fallback;
}

// KHR_texture_transform (v, null: none) as the affine map of
// mesh_material.base_transform: translation x rotation x scale, the
// rotation counter-clockwise on the UVs (so the image turns clockwise), as
// the extension's example reads. Returns the texCoord it names, else
// `tex_coord`.
int transform_value(const tinygltf::Value *v, int tex_coord, float m[6])
{
	if (!v || !v->IsObject())
		return tex_coord;
	const tinygltf::Value &off = v->Get("offset"), &scale = v->Get("scale");
	double r = number(*v, "rotation", 0.0, -1e6, 1e6), o[2] = {0, 0}, s[2] = {1, 1};
	for (int k = 0; k < 2; k++) {
		o[k] = element(off, k, o[k]);
		s[k] = element(scale, k, s[k]);
	}
	m[0] = (float)(std::cos(r) * s[0]);
	m[1] = (float)(-std::sin(r) * s[0]);
	m[2] = (float)(std::sin(r) * s[1]);
	m[3] = (float)(std::cos(r) * s[1]);
	m[4] = (float)o[0];
	m[5] = (float)o[1];
	return (int)number(*v, "texCoord", tex_coord, 0, 1e9);
}

// A texture a material reads: its index (-1: none), the UV set it reads
// (after KHR_texture_transform's texCoord) and its transform.
struct TexRef {
	int index = -1, coord = 0;
	float m[6] = {1, 0, 0, 1, 0, 0};
};

TexRef texture_ref(const tinygltf::TextureInfo &t)
{
	TexRef r;
	auto it = t.extensions.find("KHR_texture_transform");
	r.index = t.index;
	r.coord =
	    transform_value(it == t.extensions.end() ? nullptr : &it->second, t.texCoord, r.m);
	return r;
}

// The same from a textureInfo an extension holds as plain JSON.
TexRef texture_ref(const tinygltf::Value &t)
{
	TexRef r;
	if (!t.IsObject() || !t.Has("index"))
		return r;
	r.index = (int)number(t, "index", -1, -1, 1e9);
	const tinygltf::Value &ext = t.Get("extensions");
	const tinygltf::Value *tt = ext.IsObject() && ext.Has("KHR_texture_transform")
					? &ext.Get("KHR_texture_transform")
					: nullptr;
	r.coord = transform_value(tt, (int)number(t, "texCoord", 0, 0, 1e9), r.m);
	return r;
}

// KHR_materials_pbrSpecularGlossiness, or null.
const tinygltf::Value *spec_gloss(const tinygltf::Material &mat)
{
	auto it = mat.extensions.find("KHR_materials_pbrSpecularGlossiness");
	return it != mat.extensions.end() && it->second.IsObject() ? &it->second : nullptr;
}

// The base colour texture: pbrMetallicRoughness's, or a spec-gloss
// material's diffuseTexture (its specular and glossiness are of no use to
// a matcap, which holds its own light: they are not read).
TexRef base_texture(const tinygltf::Material &mat)
{
	const tinygltf::Value *sg = spec_gloss(mat);
	return sg ? texture_ref(sg->Get("diffuseTexture"))
		  : texture_ref(mat.pbrMetallicRoughness.baseColorTexture);
}

// The base colour factor, rgba, each in [0, 1]: baseColorFactor, or a
// spec-gloss material's diffuseFactor. Returns whether one was given.
bool base_factor(const tinygltf::Material &mat, float rgba[4])
{
	const tinygltf::Value *sg = spec_gloss(mat);
	std::vector<double> f = mat.pbrMetallicRoughness.baseColorFactor;
	if (sg) {
		const tinygltf::Value &d = sg->Get("diffuseFactor");
		f.assign(4, 1.0);
		for (int k = 0; k < 4 && d.IsArray() && d.ArrayLen() == 4; k++)
			f[(size_t)k] = d.Get(k).IsNumber() || d.Get(k).IsInt()
					   ? d.Get(k).GetNumberAsDouble()
					   : 1.0;
	}
	for (size_t k = 0; k < 4 && f.size() == 4; k++)
		rgba[k] = std::isfinite(f[k]) ? (float)std::fmin(std::fmax(f[k], 0.0), 1.0) : 1.0f;
	return f.size() == 4;
}

// emissiveFactor x KHR_materials_emissive_strength, linear light; a
// strength may exceed 1 (a lamp): kept to 1000, as a sane bound.
void read_emission(const tinygltf::Material &mat, float out[3])
{
	double strength = 1.0;
	auto it = mat.extensions.find("KHR_materials_emissive_strength");
	if (it != mat.extensions.end())
		strength = number(it->second, "emissiveStrength", 1.0, 0.0, 1000.0);
	for (size_t k = 0; k < 3; k++) {
		double f = mat.emissiveFactor.size() == 3 ? mat.emissiveFactor[k] : 0.0;
		f = std::isfinite(f) ? std::fmin(std::fmax(f, 0.0), 1.0) : 0.0;
		out[k] = (float)(f * strength);
	}
}

// alphaMode, alphaCutoff and doubleSided; an unknown mode is opaque, as
// the spec's default, and said once per material.
void read_alpha(const tinygltf::Material &mat, const std::string &name, struct mesh_material *out)
{
	if (mat.alphaMode == "MASK")
		out->alpha_mode = MESH_ALPHA_MASK;
	else if (mat.alphaMode == "BLEND")
		out->alpha_mode = MESH_ALPHA_BLEND;
	else if (!mat.alphaMode.empty() && mat.alphaMode != "OPAQUE")
		log_warn("%s: material \"%s\": alphaMode \"%s\", expected OPAQUE, MASK or BLEND: "
			 "drawn opaque",
			 name.c_str(), mat.name.c_str(), mat.alphaMode.c_str());
	if (std::isfinite(mat.alphaCutoff))
		out->alpha_cutoff = (float)std::fmin(std::fmax(mat.alphaCutoff, 0.0), 1.0);
	out->double_sided = mat.doubleSided;
}

// The texture's sampler's wrapS and wrapT (none: repeat, glTF's default),
// and whether its minFilter reads one level only (NEAREST or LINEAR: no
// mipmaps, as the spec and three.js draw it; none or unset: mipmaps).
void read_wrap(const tinygltf::Model &m, int texture, int wrap[2], bool *no_mipmaps)
{
	if (texture < 0 || (size_t)texture >= m.textures.size())
		return;
	int sampler = m.textures[(size_t)texture].sampler;
	if (sampler < 0 || (size_t)sampler >= m.samplers.size())
		return;
	const tinygltf::Sampler &s = m.samplers[(size_t)sampler];
	const int mode[2] = {s.wrapS, s.wrapT};
	for (int k = 0; k < 2; k++)
		wrap[k] = mode[k] == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? MESH_WRAP_CLAMP
			  : mode[k] == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? MESH_WRAP_MIRROR
									     : MESH_WRAP_REPEAT;
	*no_mipmaps = s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
		      s.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR;
}

bool is_blend(const tinygltf::Model &m, int material)
{
	return material >= 0 && m.materials[(size_t)material].alphaMode == "BLEND";
}

// The maps material `index` has of `textures` (each is decoded once).
unsigned material_maps(const tinygltf::Model &m, int index, unsigned textures)
{
	if (index < 0 || (size_t)index >= m.materials.size())
		return 0;
	const tinygltf::Material &mat = m.materials[(size_t)index];
	auto it = mat.extensions.find("KHR_materials_iridescence");
	bool film = it != mat.extensions.end() && it->second.IsObject() &&
		    it->second.Has("iridescenceThicknessTexture");
	bool colour = (textures & GLTF_TEXTURE_BASE_COLOR) != 0;
	return (colour && base_texture(mat).index >= 0) +
	       (colour && mat.emissiveTexture.index >= 0) +
	       ((textures & GLTF_TEXTURE_NORMAL) && mat.normalTexture.index >= 0) +
	       ((textures & GLTF_TEXTURE_OCCLUSION) && mat.occlusionTexture.index >= 0) +
	       ((textures & GLTF_TEXTURE_THICKNESS) && film);
}

} // namespace

void gltf_fit_textures(const tinygltf::Model &m, const std::vector<int> &slots, unsigned textures,
		       size_t budget, const GltfImages &images)
{
	unsigned maps = 0;
	for (int slot : slots)
		maps += material_maps(m, slot, textures);
	images.fit.side = GLTF_TEXTURE_SIDE;
	images.fit.bytes = budget && maps ? budget / maps : 0;
	images.scaled = GltfScaled();
}

void gltf_say_scaled(const std::string &name, const GltfImages &images, size_t budget)
{
	const GltfScaled &s = images.scaled;
	if (!s.scaled)
		return;
	// Over the side a material map is drawn at: resampled as before,
	// only sooner. Over the budget: less detail than it would have had.
	std::string fit =
	    budget ? " and to [scene] texture_memory = " + std::to_string(budget >> 20) +
			 " MiB shared among them (" + std::to_string(s.budget) + " halved for it)"
		   : std::string();
	log_msg(s.budget ? LOG_WARN : LOG_INFO,
		"%s: %u of %u textures made smaller as they were decoded, to at most %d pixels a "
		"side (the most a material map is drawn at)%s: %dx%d to %dx%d",
		name.c_str(), s.scaled, s.decoded, GLTF_TEXTURE_SIDE, fit.c_str(), s.from[0],
		s.from[1], s.to[0], s.to[1]);
}

int gltf_group_ranges(const tinygltf::Model &m, const std::vector<GltfPart> &prims,
		      const uint32_t *indices, struct mesh *out, std::vector<int> *slots_out)
{
	std::vector<int> slots;
	std::vector<std::vector<size_t>> parts; // per slot: its primitives
	for (size_t i = 0; i < prims.size(); i++) {
		if (!prims[i].index_count)
			continue;
		size_t k = std::find(slots.begin(), slots.end(), prims[i].material) - slots.begin();
		if (k == slots.size()) {
			slots.push_back(prims[i].material);
			parts.emplace_back();
		}
		parts[k].push_back(i);
	}
	size_t count = 0;
	for (size_t k = 0; k < slots.size(); k++)
		count += is_blend(m, slots[k]) ? parts[k].size() : 1;
	if (mesh_alloc_ranges(out, (uint32_t)count, (uint32_t)slots.size()))
		return -ENOMEM;
	uint32_t at = 0, r = 0;
	for (size_t k = 0; k < slots.size(); k++)
		for (size_t j = 0; j < parts[k].size(); j++) {
			const GltfPart &p = prims[parts[k][j]];
			if (j == 0 || is_blend(m, slots[k]))
				out->ranges[r++] = {at, 0, (uint32_t)k, {0, 0, 0}};
			std::memcpy(out->indices + at, indices + p.first_index,
				    p.index_count * sizeof(uint32_t));
			at += p.index_count;
			out->ranges[r - 1].index_count += p.index_count;
		}
	*slots_out = slots;
	mesh_range_centers(out);
	return 0;
}

bool gltf_primitive_base(const tinygltf::Model &m, int material, float rgba[4])
{
	rgba[0] = rgba[1] = rgba[2] = rgba[3] = 1.0f;
	if (material < 0 || (size_t)material >= m.materials.size())
		return false;
	const tinygltf::Material &mat = m.materials[(size_t)material];
	float f[4] = {1.0f, 1.0f, 1.0f, 1.0f};
	bool coloured = false;
	if (base_factor(mat, f))
		for (size_t k = 0; k < 3; k++) {
			rgba[k] = f[k];
			coloured |= rgba[k] != 1.0f;
		}
	// A base map colours it too; whether a draw reads it is its range's
	// material's (mesh_material.has_base_map), not the colour's.
	return coloured || base_texture(mat).index >= 0;
}

void gltf_keep_colors(struct mesh *out, const float uniform[4])
{
	bool plain = true;
	for (uint32_t k = 0; k < out->material_count; k++)
		plain &= !out->materials[k].base_map.width &&
			 out->materials[k].base_alpha == 1.0f &&
			 out->materials[k].alpha_mode == MESH_ALPHA_OPAQUE;
	for (size_t i = 0; plain && out->colors && i < (size_t)out->vertex_count * 4; i++)
		plain = i % 4 == 3 || out->colors[i] == 1.0f;
	for (int k = 0; plain && !out->colors && uniform && k < 3; k++)
		plain = uniform[k] == 1.0f;
	if (plain) {
		std::free(out->colors);
		out->colors = nullptr;
	} else if (!out->colors && uniform) {
		std::copy(uniform, uniform + 4, out->vertex_color);
	}
	out->has_colors = !plain && (out->colors || uniform);
}

int gltf_uv_set(const tinygltf::Model &m, int material, unsigned textures)
{
	if (!(textures & GLTF_TEXTURE_BASE_COLOR) || material < 0 ||
	    (size_t)material >= m.materials.size())
		return 0;
	const tinygltf::Material &mat = m.materials[(size_t)material];
	TexRef base = base_texture(mat), glow = texture_ref(mat.emissiveTexture);
	// The base map's set, else the emissive map's: an emissive map on
	// another set than the base map's is carried as the mesh's uv1
	// (gltf_emissive_uv_set).
	int set = base.index >= 0 ? base.coord : glow.index >= 0 ? glow.coord : 0;
	// The detail map packs the others on the one UV set it reads.
	bool others = ((textures & GLTF_TEXTURE_NORMAL) && mat.normalTexture.index >= 0) ||
		      ((textures & GLTF_TEXTURE_OCCLUSION) && mat.occlusionTexture.index >= 0) ||
		      ((textures & GLTF_TEXTURE_THICKNESS) &&
		       mat.extensions.count("KHR_materials_iridescence"));
	return others || set < 0 || set > 7 ? 0 : set;
}

int gltf_emissive_uv_set(const tinygltf::Model &m, int material, unsigned textures)
{
	if (!(textures & GLTF_TEXTURE_BASE_COLOR) || material < 0 ||
	    (size_t)material >= m.materials.size())
		return -1;
	const tinygltf::Material &mat = m.materials[(size_t)material];
	TexRef glow = texture_ref(mat.emissiveTexture);
	float emissive[3];
	read_emission(mat, emissive);
	// A black factor leaves the map undecoded: no set is carried for it.
	bool glows = emissive[0] > 0.0f || emissive[1] > 0.0f || emissive[2] > 0.0f;
	if (glow.index < 0 || !glows || glow.coord < 0 || glow.coord > 7 ||
	    glow.coord == gltf_uv_set(m, material, textures))
		return -1;
	return glow.coord;
}

bool gltf_keep_image(tinygltf::Image *image, const int index, std::string *, std::string *, int,
		     int, const unsigned char *bytes, int size, void *user)
{
	GltfImages *g = static_cast<GltfImages *>(user);
	if (!g || !g->keep || image->bufferView >= 0 || index < 0 || size <= 0 || !bytes)
		return true;
	if ((size_t)index >= g->bytes.size())
		g->bytes.resize((size_t)index + 1);
	g->bytes[(size_t)index].assign(bytes, bytes + size);
	return true;
}

// The base colour's and emission's factors and maps (decoded when
// `decode`): each map's UV set is the mesh's when gltf_uv_set chose it, the
// emissive map's its uv1 when gltf_emissive_uv_set did.
static void read_colour(const tinygltf::Model &m, int index, unsigned textures, bool decode,
			const GltfImages &images, const std::string &name,
			struct mesh_material *out)
{
	const tinygltf::Material &mat = m.materials[(size_t)index];
	int set = gltf_uv_set(m, index, textures);
	int glow_set = gltf_emissive_uv_set(m, index, textures);
	float rgba[4] = {1.0f, 1.0f, 1.0f, 1.0f};

	if (base_factor(mat, rgba)) {
		std::copy(rgba, rgba + 3, out->base_color);
		out->base_alpha = rgba[3];
	}
	out->unlit = mat.extensions.count("KHR_materials_unlit") > 0;
	read_emission(mat, out->emissive);
	TexRef base = base_texture(mat), glow = texture_ref(mat.emissiveTexture);
	out->has_base_map = base.index >= 0;
	std::copy(base.m, base.m + 6, out->base_transform);
	read_wrap(m, base.index, out->base_wrap, &out->base_no_mipmaps);
	// An emissive map with a black factor adds nothing: not decoded.
	bool glows = out->emissive[0] > 0.0f || out->emissive[1] > 0.0f || out->emissive[2] > 0.0f;
	out->has_emissive_map = glow.index >= 0 && glows;
	out->emissive_uv1 = out->has_emissive_map && glow_set >= 0;
	std::copy(glow.m, glow.m + 6, out->emissive_transform);
	read_wrap(m, glow.index, out->emissive_wrap, &out->emissive_no_mipmaps);
	if (!decode)
		return;
	const char *base_name = spec_gloss(mat) ? "diffuseTexture" : "baseColorTexture";
	if (out->has_base_map)
		read_texture(m, base.index, base.coord == set ? 0 : base.coord, images, name,
			     base_name, &out->base_map, out->images_decoded);
	if (out->has_emissive_map)
		read_texture(m, glow.index, glow.coord == set || out->emissive_uv1 ? 0 : glow.coord,
			     images, name, "emissiveTexture", &out->emissive_map,
			     out->images_decoded);
}

void gltf_read_materials(const tinygltf::Model &m, const std::vector<int> &slots,
			 const std::string &name, unsigned textures, size_t budget,
			 const GltfImages &images, struct mesh *out)
{
	std::string shown = gltf_ext::escape(name);
	gltf_fit_textures(m, slots, textures, budget, images);
	for (size_t k = 0; k < slots.size(); k++)
		gltf_read_material(m, slots[k], textures, ~0u, images, name, &out->materials[k]);
	gltf_say_scaled(shown, images, budget);
	unsigned mapped = 0;
	for (uint32_t k = 0; k < out->material_count; k++)
		mapped += out->materials[k].base_map.width > 0;
	if (slots.size() > 1)
		log_info("%s: %zu materials (%u with a base map shown), %u draw ranges",
			 shown.c_str(), slots.size(), mapped, out->range_count);
}

void gltf_read_material(const tinygltf::Model &m, int index, unsigned textures, unsigned decode,
			const GltfImages &images, const std::string &name,
			struct mesh_material *out)
{
	if (index < 0 || (size_t)index >= m.materials.size())
		return;
	const tinygltf::Material &mat = m.materials[(size_t)index];
	int thickness = -1, thickness_coord = 0;

	out->present = true;
	read_alpha(mat, name, out);
	out->has_normal_map = mat.normalTexture.index >= 0;
	out->has_occlusion_map = mat.occlusionTexture.index >= 0;
	if (std::isfinite(mat.normalTexture.scale))
		out->normal_scale =
		    (float)std::fmin(std::fmax(mat.normalTexture.scale, -100.0), 100.0);
	if (std::isfinite(mat.occlusionTexture.strength))
		out->occlusion_strength =
		    (float)std::fmin(std::fmax(mat.occlusionTexture.strength, 0.0), 1.0);
	read_iridescence(mat, out, &thickness, &thickness_coord);
	read_colour(m, index, textures, (textures & decode & GLTF_TEXTURE_BASE_COLOR) != 0, images,
		    name, out);
	if ((textures & decode & GLTF_TEXTURE_NORMAL) && out->has_normal_map)
		read_texture(m, mat.normalTexture.index, mat.normalTexture.texCoord, images, name,
			     "normalTexture", &out->normal_map, out->images_decoded);
	if ((textures & decode & GLTF_TEXTURE_OCCLUSION) && out->has_occlusion_map)
		read_texture(m, mat.occlusionTexture.index, mat.occlusionTexture.texCoord, images,
			     name, "occlusionTexture", &out->occlusion_map, out->images_decoded);
	if ((textures & decode & GLTF_TEXTURE_THICKNESS) && out->has_thickness_map)
		read_texture(m, thickness, thickness_coord, images, name,
			     "iridescenceThicknessTexture", &out->thickness_map,
			     out->images_decoded);
	// For the bench; a model without a material decodes none and says nothing.
	log_debug("%s: %u images decoded", name.c_str(), out->images_decoded);
}
