// The accessor checks of gltf_accessor.h.
#include "scene/gltf/gltf_accessor.h"

#include <string>

const int gltf_position_types[] = {
    TINYGLTF_COMPONENT_TYPE_FLOAT,	    TINYGLTF_COMPONENT_TYPE_BYTE,
    TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,  TINYGLTF_COMPONENT_TYPE_SHORT,
    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 0};
const int gltf_direction_types[] = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
				    TINYGLTF_COMPONENT_TYPE_SHORT, 0};
const int gltf_index_types[] = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
				TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
				TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, 0};

namespace
{

std::string type_name(int type)
{
	switch (type) {
	case TINYGLTF_TYPE_SCALAR:
		return "SCALAR";
	case TINYGLTF_TYPE_VEC2:
		return "VEC2";
	case TINYGLTF_TYPE_VEC3:
		return "VEC3";
	case TINYGLTF_TYPE_VEC4:
		return "VEC4";
	default:
		return std::to_string(type);
	}
}

bool fail(std::string *err, const std::string &what, const std::string &msg)
{
	*err = what + ": " + msg;
	return false;
}

} // namespace

bool gltf_view_check(const tinygltf::Model &m, int index, int type, const int *types,
		     const std::string &what, GltfView *v, std::string *err)
{
	std::string w = what + " (accessors[" + std::to_string(index) + "])";
	if (index < 0 || (size_t)index >= m.accessors.size())
		return fail(err, what, "accessor " + std::to_string(index) + " does not exist");
	const tinygltf::Accessor &a = m.accessors[(size_t)index];
	bool type_ok = false;
	std::string expected;
	for (const int *t = types; *t; t++) {
		type_ok |= a.componentType == *t;
		expected +=
		    std::string(expected.empty() ? "" : ", ") + gltf_ext::component_name(*t);
	}
	if (a.type != type)
		return fail(err, w, "type " + type_name(a.type) + ", expected " + type_name(type));
	if (!type_ok)
		return fail(err, w,
			    std::string("componentType ") +
				gltf_ext::component_name(a.componentType) + ", expected " +
				expected);
	// Sparse accessors and those without a bufferView were made plain
	// before the builder runs (gltf_ext::make_dense).
	if (a.bufferView < 0 || (size_t)a.bufferView >= m.bufferViews.size())
		return fail(err, w,
			    "bufferView " + std::to_string(a.bufferView) + " does not exist");
	const tinygltf::BufferView &bv = m.bufferViews[(size_t)a.bufferView];
	if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size())
		return fail(err, w, "buffer " + std::to_string(bv.buffer) + " does not exist");
	const std::vector<unsigned char> &buf = m.buffers[(size_t)bv.buffer].data;
	size_t elem = gltf_ext::component_size(a.componentType) *
		      (size_t)tinygltf::GetNumComponentsInType(a.type);
	size_t stride = bv.byteStride ? bv.byteStride : elem;
	size_t view_end, last, end;
	if (a.count == 0)
		return fail(err, w, "count is 0");
	if (stride < elem)
		return fail(err, w,
			    "byteStride " + std::to_string(stride) + " is smaller than an element");
	if (__builtin_add_overflow(bv.byteOffset, bv.byteLength, &view_end) ||
	    view_end > buf.size())
		return fail(err, w,
			    "bufferView " + std::to_string(a.bufferView) +
				" runs past the end of its buffer (" + std::to_string(buf.size()) +
				" bytes)");
	if (__builtin_mul_overflow(stride, a.count - 1, &last) ||
	    __builtin_add_overflow(last, a.byteOffset, &last) ||
	    __builtin_add_overflow(last, elem, &end) || end > bv.byteLength)
		return fail(err, w,
			    "offset " + std::to_string(a.byteOffset) + " + stride " +
				std::to_string(stride) + " x count " + std::to_string(a.count) +
				" runs past the end of bufferView " + std::to_string(a.bufferView) +
				" (" + std::to_string(bv.byteLength) + " bytes)");
	v->base = buf.data() + bv.byteOffset + a.byteOffset;
	v->stride = stride;
	v->count = a.count;
	v->components = tinygltf::GetNumComponentsInType(a.type);
	v->component_type = a.componentType;
	v->normalized = a.normalized;
	return true;
}

bool gltf_view_color(const tinygltf::Model &m, int index, const std::string &what, GltfView *v,
		     std::string *err)
{
	static const int types[] = {TINYGLTF_COMPONENT_TYPE_FLOAT,
				    TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
				    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 0};
	bool vec4 = index < (int)m.accessors.size() && index >= 0 &&
		    m.accessors[(size_t)index].type == TINYGLTF_TYPE_VEC4;
	if (!gltf_view_check(m, index, vec4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, types, what,
			     v, err))
		return false;
	v->normalized = true; // the spec's only choice for integer colours
	return true;
}
