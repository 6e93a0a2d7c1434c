// glTF through tinygltf: the file read and parsed (tinygltf parses the
// JSON and the GLB container), then handed to the mesh builder
// (gltf_mesh.cc), which trusts nothing tinygltf hands back.
#include "scene/gltf/gltf.h"
#include "scene/gltf/gltf_ext.h"
#include "scene/gltf/gltf_fs.h"
#include "scene/gltf/gltf_json_depth.h"
#include "scene/gltf/gltf_material.h"
#include "scene/gltf/gltf_mesh.h"
#include "util/file.h"
#include "util/log.h"

#include <tiny_gltf.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

bool parse(tinygltf::TinyGLTF &loader, tinygltf::Model *model, const uint8_t *data, size_t size,
	   const GltfFiles &ctx, bool all, std::string *err)
{
	std::string warn;
	std::vector<unsigned char> fixed = gltf_ext::tinygltf_compatible(data, size, all);
	if (!fixed.empty() && fixed.size() <= 0xffffffffu) {
		data = fixed.data();
		size = fixed.size();
	}
	err->clear();
	bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
	return glb ? loader.LoadBinaryFromMemory(model, err, &warn, data, (unsigned)size, ctx.dir)
		   : loader.LoadASCIIFromString(model, err, &warn,
						reinterpret_cast<const char *>(data),
						(unsigned)size, ctx.dir);
}

// Before any parser: tinygltf's, and nlohmann's in gltf_files.cc, recurse
// once per level of nesting (gltf_json_depth.h).
bool depth_within(const char *name, const uint8_t *data, size_t size)
{
	struct gltf_json_depth d;

	if (gltf_json_depth_file_within(data, size, GLTF_JSON_MAX_DEPTH, &d))
		return true;
	log_err("%s: JSON%s nested deeper than %u levels at byte %zu (line %zu%s); a glTF file "
		"needs far fewer, refused",
		gltf_ext::escape(name).c_str(), d.glb ? " chunk" : "", GLTF_JSON_MAX_DEPTH,
		d.offset, d.line, d.glb ? " of the chunk" : "");
	return false;
}

// owned: the caller's malloc'd bytes (data), freed here once the parser
// holds its own copy; NULL: the caller keeps them.
int load_memory(const char *name, const uint8_t *data, size_t size, const char *dir,
		const struct gltf_options *o, struct mesh *out, uint8_t **owned)
{
	tinygltf::TinyGLTF loader;
	tinygltf::Model model;
	std::string err;
	GltfFiles ctx;
	GltfImages images;
	ctx.dir = dir ? dir : "";
	ctx.max_size = GLTF_MAX_FILE;
	images.keep = o->textures != 0;
	images.files = &ctx;
	std::memset(out, 0, sizeof(*out));
	if (o->anim)
		*o->anim = nullptr;

	if (size > GLTF_MAX_FILE || size > 0xffffffffu) {
		log_err("%s: file is %zu bytes, expected at most %u",
			gltf_ext::escape(name).c_str(), size, GLTF_MAX_FILE);
		return -EFBIG;
	}
	if (!depth_within(name, data, size))
		return -EINVAL;
	loader.SetFsCallbacks(gltf_fs_callbacks(&ctx));
	// Images are decoded by our own libpng/libjpeg path, and only those a
	// feature asked for; never by the stb copy inside the library.
	loader.SetImageLoader(gltf_keep_image, &images);
	bool ok = parse(loader, &model, data, size, ctx, false, &err);
	// tinygltf refuses indices without a bufferView, which the spec
	// allows: look for them only in a file it refused.
	if (!ok && err.find("invalid bufferView") != std::string::npos)
		ok = parse(loader, &model, data, size, ctx, true, &err);
	std::string required = gltf_ext::unsupported(model.extensionsRequired);
	const std::string &version = model.asset.version;
	std::string ours = ok ? "" : gltf_ext::file_fault(data, size);
	if (ok && !version.empty() && version.compare(0, 2, "2.") != 0) {
		ok = false;
		err = version == "1" || version.compare(0, 2, "1.") == 0
			  ? std::string(gltf_ext::gltf1_words) + " (asset.version \"" + version +
				"\")"
			  : "asset.version \"" + version + "\", expected 2.0";
	} else if (!ours.empty()) {
		err = ours; // the parser's words would only repeat it, in its terms
	} else if (!ok || !required.empty()) {
		err = ok ? "extensionsRequired: " + required + " not supported"
			 : gltf_ext::parse_fault({ctx.dir, ctx.missing, ctx.refused,
						  [&ctx](const std::string &path) {
							  return gltf_path_allowed(ctx, path);
						  }},
						 model, data, size, err);
		ok = false;
	}
	if (!ok) {
		log_err("%s: %s", gltf_ext::escape(name).c_str(), gltf_ext::escape(err).c_str());
		return -EINVAL;
	}
	// Parsed: the model holds its buffers, the file's bytes serve nothing
	// more, and the mesh built next is as large (issue 34: a 1M-triangle
	// scan's 28 MB file, its parsed buffers and its mesh at once).
	if (owned) {
		std::free(*owned);
		*owned = nullptr;
	}
	return gltf_build_mesh(name, model, o, images, out);
}

} // namespace

namespace
{

int load_memory_caught(const char *name, const uint8_t *data, size_t size, const char *dir,
		       const struct gltf_options *o, struct mesh *out, uint8_t **owned)
{
	// No exception may cross into C: a model too large for memory, or a
	// fault inside the parser, is one more error line.
	try {
		return load_memory(name, data, size, dir, o, out, owned);
	} catch (const std::exception &e) {
		log_err("%s: cannot load: %s", name, e.what());
	} catch (...) {
		log_err("%s: cannot load: unexpected fault in the glTF parser", name);
	}
	mesh_release(out);
	return -EINVAL;
}

std::string folder_of(const char *path)
{
	std::string dir = path;
	size_t slash = dir.rfind('/');
	return slash == std::string::npos ? "" : dir.substr(0, slash);
}

} // namespace

extern "C" int gltf_load_memory_options(const char *name, const uint8_t *data, size_t size,
					const char *dir, const struct gltf_options *o,
					struct mesh *out)
{
	return load_memory_caught(name, data, size, dir, o, out, nullptr);
}

extern "C" int gltf_load_memory_textures(const char *name, const uint8_t *data, size_t size,
					 const char *dir, unsigned textures, struct mesh *out)
{
	struct gltf_options o = {};
	o.textures = textures;
	return gltf_load_memory_options(name, data, size, dir, &o, out);
}

extern "C" int gltf_load_memory(const char *name, const uint8_t *data, size_t size, const char *dir,
				struct mesh *out)
{
	return gltf_load_memory_textures(name, data, size, dir, 0, out);
}

// Read, not mapped (util/file.h), and not zero-filled first.
extern "C" int gltf_read(const char *path, uint8_t **data, size_t *size)
{
	int ret = file_read_all(path, GLTF_MAX_FILE, data, size);
	if (ret)
		log_err("%s: %s", gltf_ext::escape(path).c_str(),
			ret == -EFBIG ? "larger than the limit (512 MiB)"
			: file_refusal(ret)
			    ? file_refusal(ret)
			    : ("cannot open: " + std::string(std::strerror(-ret))).c_str());
	return ret;
}

extern "C" int gltf_load_bytes(const char *path, const uint8_t *data, size_t size,
			       const struct gltf_options *o, struct mesh *out)
{
	return gltf_load_memory_options(path, data, size, folder_of(path).c_str(), o, out);
}

extern "C" int gltf_load_bytes_owned(const char *path, uint8_t **data, size_t size,
				     const struct gltf_options *o, struct mesh *out)
{
	return load_memory_caught(path, *data, size, folder_of(path).c_str(), o, out, data);
}

extern "C" int gltf_load_options(const char *path, const struct gltf_options *o, struct mesh *out)
{
	uint8_t *data = nullptr;
	size_t size;
	std::memset(out, 0, sizeof(*out));
	int ret = gltf_read(path, &data, &size);
	if (!ret)
		ret = gltf_load_bytes(path, data, size, o, out);
	std::free(data);
	return ret;
}

extern "C" int gltf_load_textures(const char *path, unsigned textures, struct mesh *out)
{
	struct gltf_options o = {};
	o.textures = textures;
	return gltf_load_options(path, &o, out);
}

extern "C" int gltf_load(const char *path, struct mesh *out)
{
	return gltf_load_textures(path, 0, out);
}
