// Inside the glTF shim (C++ only): an accessor checked before a byte of it
// is read (its type, component type, bufferView, buffer, offset, stride
// and count all proven in range, overflow included), and its elements read
// through the checked view. Split from gltf_mesh.cc, which builds the mesh
// from such views.
#ifndef MK_GLTF_ACCESSOR_H
#define MK_GLTF_ACCESSOR_H

#include "scene/gltf/gltf_ext.h"

#include <tiny_gltf.h>

#include <cstring>
#include <string>

// A checked view of one accessor: where element i starts, and how to read
// its components. Built only after every offset has been proven in range.
struct GltfView {
	const unsigned char *base = nullptr;
	size_t stride = 0;
	size_t count = 0;
	int components = 0;
	int component_type = 0;
	bool normalized = false;
};

// Accessor `index` of `type` with one of `types` (ending in 0) as a view;
// false with *err = "what (accessors[i]): what is wrong, expected ...".
bool gltf_view_check(const tinygltf::Model &m, int index, int type, const int *types,
		     const std::string &what, GltfView *v, std::string *err);

// COLOR_0: vec3 or vec4, float or normalized unsigned byte or short.
bool gltf_view_color(const tinygltf::Model &m, int index, const std::string &what, GltfView *v,
		     std::string *err);

// KHR_mesh_quantization widens what an attribute may be stored as:
// positions and texture coordinates in any 8 or 16-bit integer
// (normalized or not), normals and tangents in normalized signed ones.
extern const int gltf_position_types[], gltf_direction_types[], gltf_index_types[];

// Float first and inline: nearly every exporter writes float attributes,
// and a 1M-triangle model reads some twelve million components.
inline double gltf_view_read(const GltfView &v, size_t i, int c)
{
	if (v.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
		float f;
		std::memcpy(&f, v.base + i * v.stride + (size_t)c * 4, 4);
		return f;
	}
	return gltf_ext::component_value(v.base + i * v.stride +
					     (size_t)c * gltf_ext::component_size(v.component_type),
					 v.component_type, v.normalized);
}

#endif
