// The loader's passes over a parsed model, between tinygltf and the mesh
// builder in gltf.cc: extensions, compressed and sparse data made plain,
// and the pose (node matrices, morph weights, skins). Internal to the glTF
// shim (C++ only; nothing outside src/scene/gltf*.cc includes it). Each
// pass returns false with the reason in *err as "json.path: what was
// expected", and leaves the model readable by the plain accessor checks.
#ifndef MK_GLTF_EXT_H
#define MK_GLTF_EXT_H

#include <tiny_gltf.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace gltf_ext
{

struct Mat4 {
	double m[16]; // column-major, as glTF stores it
};

// The bytes tinygltf can parse, where it refuses what the spec allows: a
// copy with EXT_meshopt_compression's fallback buffers (which hold
// nothing) replaced by one zero byte, and primitive indices without a
// bufferView moved aside (Draco's, or all zeros: see make_dense); empty
// when the file needs no change. `all`: look even when the file names
// neither compression.
std::vector<unsigned char> tinygltf_compatible(const unsigned char *data, size_t size, bool all);

// Where tinygltf_compatible moves such indices: the primitive's extras.
extern const char *const moved_indices;

// Each buffer's URI as written (empty: none), for naming a missing one
// after tinygltf refused the file; false when the JSON cannot be read.
bool buffer_uris(const unsigned char *data, size_t size, std::vector<std::string> *uris, bool *glb);

// A URI's %XX escapes decoded, as tinygltf decodes them before it looks
// for the file.
std::string percent_decoded(const std::string &uri);

// What the file callbacks saw while tinygltf read the file: the model's
// folder, the first path refused and the first missing, and the rule.
struct FileFault {
	std::string dir, missing, refused;
	std::function<bool(const std::string &)> allowed; // a path inside dir?
};

// After tinygltf refused the file, the reason in one line: an unsupported
// required extension, a missing buffer by its URI as written, a GLB of
// another version, else tinygltf's own words.
std::string parse_fault(const FileFault &f, const tinygltf::Model &m, const unsigned char *data,
			size_t size, std::string err);

// Our words for what a user's file is, when tinygltf refused it (in
// gltf_words.cc): empty, a GLB cut short (declared and real lengths), glTF
// 1.0, a JSON syntax error with its line and column; empty when none of
// these is the fault.
std::string file_fault(const unsigned char *data, size_t size);
// "glTF 1.0 is not supported; re-export it as glTF 2.0"
extern const char *const gltf1_words;

// Names of the extensions in `names` that the loader does not support,
// joined by ", "; empty when it supports them all.
std::string unsupported(const std::vector<std::string> &names);

// Bytes from the file made safe for one journal line: control characters
// and bytes that are not UTF-8 become \xNN.
std::string escape(const std::string &s);

// Inline: read for every component of every vertex, a call each cost a
// 1M-triangle model's load 130M instructions.
inline size_t component_size(int type)
{
	switch (type) {
	case TINYGLTF_COMPONENT_TYPE_BYTE:
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
		return 1;
	case TINYGLTF_COMPONENT_TYPE_SHORT:
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
		return 2;
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
	case TINYGLTF_COMPONENT_TYPE_FLOAT:
		return 4;
	default:
		return 0;
	}
}

// One component as a number, normalized integers mapped to [0,1] or
// [-1,1] as the spec says.
inline double component_value(const unsigned char *p, int type, bool normalized)
{
	switch (type) {
	case TINYGLTF_COMPONENT_TYPE_FLOAT: {
		float f;
		std::memcpy(&f, p, 4);
		return f;
	}
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
		uint32_t u;
		std::memcpy(&u, p, 4);
		return u;
	}
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
		uint16_t u;
		std::memcpy(&u, p, 2);
		return normalized ? u / 65535.0 : u;
	}
	case TINYGLTF_COMPONENT_TYPE_SHORT: {
		int16_t s;
		std::memcpy(&s, p, 2);
		return normalized ? std::fmax(s / 32767.0, -1.0) : s;
	}
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
		return normalized ? *p / 255.0 : *p;
	case TINYGLTF_COMPONENT_TYPE_BYTE: {
		int8_t s = (int8_t)*p;
		return normalized ? std::fmax(s / 127.0, -1.0) : s;
	}
	default:
		return 0.0;
	}
}

const char *component_name(int component_type);

// Accessor `index` as count x components numbers: strided, sparse or
// without a bufferView (zeros), every offset checked.
bool read_accessor(const tinygltf::Model &m, int index, std::vector<double> *out, int *components,
		   std::string *err);

// Appends a buffer, bufferView and accessor holding `values`; returns the
// accessor's index.
int add_float_accessor(tinygltf::Model &m, const std::vector<double> &values, int type,
		       size_t count);

// The passes, in the order the loader runs them.
bool decode_meshopt(tinygltf::Model &m, std::string *err);
bool decode_draco(tinygltf::Model &m, std::string *err);
bool make_dense(tinygltf::Model &m, std::string *err);
// World matrices of every node; refuses a cycle, a node with two parents
// and a child index out of range, without recursion.
bool node_worlds(const tinygltf::Model &m, std::vector<Mat4> *worlds, std::vector<int> *parent,
		 std::string *err);
// The scene to show: `want` (an index or a scene's name), else the
// file's default, else the first; -1 when the file has none.
bool choose_scene(const tinygltf::Model &m, const char *want, const char *setting, int *scene,
		  std::string *err);

// What the passes before the builder found: every node's world matrix
// and parent.
struct Pose {
	std::vector<Mat4> worlds;
	std::vector<int> parent;
};

// Every pass above but the scene's choice, in order, on m (name for the
// journal's line on extensions it uses but does not need).
bool prepare(tinygltf::Model &m, const char *name, Pose *pose, std::string *err);

} // namespace gltf_ext

#endif
