// Extensions and the parts of the accessor spec that need a copy: meshopt
// and Draco decoding, sparse accessors and accessors without a bufferView.
// Every one becomes a plain buffer, bufferView and accessor, so that the
// builder in gltf.cc checks and reads one kind of data only.
#include "scene/gltf/gltf_ext.h"
#include "scene/gltf/gltf_features.h"
#include "util/log.h"
#include "scene/gltf/gltf_draco.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <type_traits>

namespace gltf_ext
{

// Set by gltf_files.cc's tinygltf_compatible, read by make_dense below.
const char *const moved_indices = "matcap_kiosk_indices";

namespace
{

// tinygltf 2.7 (Debian 12) keeps offsets and counts as int, 2.9 (Debian 13)
// as size_t: a negative one is possible only in the first.
template <typename T> bool negative(T v)
{
	if constexpr (std::is_signed_v<T>)
		return v < 0;
	else
		return false;
}

// Extensions refused with a reason beyond "not supported": what the
// operator would otherwise look for.
const char *refusal_reason(const std::string &name)
{
	if (name == "KHR_texture_basisu")
		return " (KTX2 textures: no KTX2 transcoder in Debian 12/13; expected PNG, JPEG or "
		       "WebP images)";
	return "";
}

std::string path_of(const char *array, size_t i)
{
	return std::string(array) + "[" + std::to_string(i) + "]";
}

int type_components(int type)
{
	int n = tinygltf::GetNumComponentsInType((uint32_t)type);
	return n > 0 ? n : 0;
}

// A checked span of a bufferView: count elements of elem bytes each,
// stride apart, starting offset bytes in.
bool view_span(const tinygltf::Model &m, int view, size_t offset, size_t elem, size_t stride,
	       size_t count, const std::string &what, const unsigned char **base, std::string *err)
{
	if (view < 0 || (size_t)view >= m.bufferViews.size()) {
		*err = what + ": bufferView " + std::to_string(view) + " does not exist";
		return false;
	}
	const tinygltf::BufferView &bv = m.bufferViews[(size_t)view];
	if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size()) {
		*err = path_of("bufferViews", (size_t)view) + ".buffer: buffer " +
		       std::to_string(bv.buffer) + " does not exist";
		return false;
	}
	const std::vector<unsigned char> &buf = m.buffers[(size_t)bv.buffer].data;
	size_t view_end, last, end;
	if (__builtin_add_overflow(bv.byteOffset, bv.byteLength, &view_end) ||
	    view_end > buf.size()) {
		*err = path_of("bufferViews", (size_t)view) +
		       ": runs past the end of its buffer (" + std::to_string(buf.size()) +
		       " bytes)";
		return false;
	}
	if (count > 0 && (__builtin_mul_overflow(stride, count - 1, &last) ||
			  __builtin_add_overflow(last, offset, &last) ||
			  __builtin_add_overflow(last, elem, &end) || end > bv.byteLength)) {
		*err = what + ": " + std::to_string(count) + " elements run past the end of " +
		       path_of("bufferViews", (size_t)view) + " (" + std::to_string(bv.byteLength) +
		       " bytes)";
		return false;
	}
	*base = buf.data() + bv.byteOffset + offset;
	return true;
}

bool read_sparse(const tinygltf::Model &m, const tinygltf::Accessor &a, const std::string &what,
		 int n, std::vector<double> *out, std::string *err)
{
	const auto &s = a.sparse;
	size_t isize = component_size(s.indices.componentType);
	size_t vsize = component_size(a.componentType) * (size_t)n;
	const unsigned char *ip, *vp;
	if (negative(s.count) || (size_t)s.count > a.count) {
		*err = what + ".sparse.count: " + std::to_string(s.count) +
		       ", expected at most the accessor's count " + std::to_string(a.count);
		return false;
	}
	if (isize == 0 || s.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
	    s.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
	    s.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) {
		*err = what + ".sparse.indices.componentType: expected UNSIGNED_BYTE, " +
		       "UNSIGNED_SHORT or UNSIGNED_INT";
		return false;
	}
	if (negative(s.indices.byteOffset) || negative(s.values.byteOffset) ||
	    !view_span(m, s.indices.bufferView, (size_t)s.indices.byteOffset, isize, isize,
		       (size_t)s.count, what + ".sparse.indices", &ip, err) ||
	    !view_span(m, s.values.bufferView, (size_t)s.values.byteOffset, vsize, vsize,
		       (size_t)s.count, what + ".sparse.values", &vp, err)) {
		if (err->empty())
			*err = what + ".sparse: negative byteOffset";
		return false;
	}
	for (size_t i = 0; i < (size_t)s.count; i++) {
		double idx = component_value(ip + i * isize, s.indices.componentType, false);
		if (idx < 0 || idx >= (double)a.count) {
			*err = what + ".sparse.indices: index " + std::to_string((uint64_t)idx) +
			       " at " + std::to_string(i) + ", expected below " +
			       std::to_string(a.count);
			return false;
		}
		for (int c = 0; c < n; c++)
			(*out)[(size_t)idx * (size_t)n + (size_t)c] = component_value(
			    vp + i * vsize + (size_t)c * component_size(a.componentType),
			    a.componentType, a.normalized);
	}
	return true;
}

} // namespace

const char *component_name(int type)
{
	switch (type) {
	case TINYGLTF_COMPONENT_TYPE_BYTE:
		return "BYTE";
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
		return "UNSIGNED_BYTE";
	case TINYGLTF_COMPONENT_TYPE_SHORT:
		return "SHORT";
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
		return "UNSIGNED_SHORT";
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
		return "UNSIGNED_INT";
	case TINYGLTF_COMPONENT_TYPE_FLOAT:
		return "FLOAT";
	default:
		return "an unknown component type";
	}
}

std::string unsupported(const std::vector<std::string> &names)
{
	std::string out;
	for (const std::string &n : names) {
		if (!gltf_extension_known(n.c_str()) && out.find(n) == std::string::npos)
			out += (out.empty() ? "" : ", ") + n + refusal_reason(n);
	}
	return out;
}

std::string escape(const std::string &s)
{
	std::string out;
	const unsigned char *p = reinterpret_cast<const unsigned char *>(s.data());
	size_t n = s.size(), i = 0;
	while (i < n) {
		unsigned char c = p[i];
		size_t len = c < 0x80	      ? 1
			     : (c >> 5) == 6  ? 2
			     : (c >> 4) == 14 ? 3
			     : (c >> 3) == 30 ? 4
					      : 0;
		bool ok = len > 0 && i + len <= n && !(len == 1 && (c < 0x20 || c == 0x7f));
		for (size_t k = 1; ok && k < len; k++)
			ok = (p[i + k] & 0xc0) == 0x80;
		// Overlong forms and surrogates are not UTF-8 either.
		if (ok && len == 2)
			ok = c >= 0xc2;
		if (ok && len == 3)
			ok = !(c == 0xe0 && p[i + 1] < 0xa0) && !(c == 0xed && p[i + 1] >= 0xa0);
		if (ok && len == 4)
			ok = c <= 0xf4 && !(c == 0xf0 && p[i + 1] < 0x90) &&
			     !(c == 0xf4 && p[i + 1] >= 0x90);
		if (!ok) {
			char hex[8];
			std::snprintf(hex, sizeof(hex), "\\x%02x", c);
			out += hex;
			i++;
			continue;
		}
		out.append(s, i, len);
		i += len;
	}
	return out;
}

bool read_accessor(const tinygltf::Model &m, int index, std::vector<double> *out, int *components,
		   std::string *err)
{
	std::string what = path_of("accessors", (size_t)index);
	if (index < 0 || (size_t)index >= m.accessors.size()) {
		*err = "accessor " + std::to_string(index) + " does not exist";
		return false;
	}
	const tinygltf::Accessor &a = m.accessors[(size_t)index];
	int n = type_components(a.type);
	size_t csize = component_size(a.componentType), elem = csize * (size_t)n;
	if (n == 0 || csize == 0) {
		*err = what + ": unknown type or componentType";
		return false;
	}
	if (a.count > (1u << 28) / (size_t)n) {
		*err = what + ".count: " + std::to_string(a.count) + " is too many";
		return false;
	}
	out->assign(a.count * (size_t)n, 0.0);
	*components = n;
	if (a.bufferView >= 0) {
		const unsigned char *base;
		size_t stride = m.bufferViews.size() > (size_t)a.bufferView &&
					m.bufferViews[(size_t)a.bufferView].byteStride
				    ? m.bufferViews[(size_t)a.bufferView].byteStride
				    : elem;
		if (!view_span(m, a.bufferView, a.byteOffset, elem, stride, a.count, what, &base,
			       err))
			return false;
		for (size_t i = 0; i < a.count; i++)
			for (int c = 0; c < n; c++)
				(*out)[i * (size_t)n + (size_t)c] =
				    component_value(base + i * stride + (size_t)c * csize,
						    a.componentType, a.normalized);
	}
	return !a.sparse.isSparse || read_sparse(m, a, what, n, out, err);
}

int add_float_accessor(tinygltf::Model &m, const std::vector<double> &values, int type,
		       size_t count)
{
	tinygltf::Buffer buf;
	buf.data.resize(values.size() * 4);
	for (size_t i = 0; i < values.size(); i++) {
		float f = (float)values[i];
		std::memcpy(buf.data.data() + i * 4, &f, 4);
	}
	tinygltf::BufferView bv;
	bv.buffer = (int)m.buffers.size();
	bv.byteOffset = 0;
	bv.byteLength = buf.data.size();
	bv.byteStride = 0;
	m.buffers.push_back(std::move(buf));
	tinygltf::Accessor a;
	a.bufferView = (int)m.bufferViews.size();
	a.byteOffset = 0;
	a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
	a.normalized = false;
	a.count = count;
	a.type = type;
	a.sparse.isSparse = false;
	m.bufferViews.push_back(bv);
	m.accessors.push_back(a);
	return (int)m.accessors.size() - 1;
}

namespace
{

int value_int(const tinygltf::Value &o, const char *key, int fallback)
{
	const tinygltf::Value &v = o.Get(key);
	return v.IsNumber() ? v.GetNumberAsInt() : fallback;
}

std::string value_string(const tinygltf::Value &o, const char *key, const char *fallback)
{
	const tinygltf::Value &v = o.Get(key);
	return v.IsString() ? v.Get<std::string>() : fallback;
}

bool meshopt_filter(const std::string &filter, unsigned char *data, size_t count, size_t stride)
{
	if (filter == "NONE")
		return true;
	if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
		meshopt_decodeFilterOct(data, count, stride);
	else if (filter == "QUATERNION" && stride == 8)
		meshopt_decodeFilterQuat(data, count, stride);
	else if (filter == "EXPONENTIAL" && stride % 4 == 0)
		meshopt_decodeFilterExp(data, count, stride);
	else
		return false;
	return true;
}

// One compressed bufferView into a new buffer of its own.
bool meshopt_view(tinygltf::Model &m, size_t i, const tinygltf::Value &e, std::string *err)
{
	std::string what = path_of("bufferViews", i) + ".extensions.EXT_meshopt_compression";
	int buffer = value_int(e, "buffer", -1), length = value_int(e, "byteLength", -1);
	int offset = value_int(e, "byteOffset", 0), stride = value_int(e, "byteStride", -1);
	int count = value_int(e, "count", -1);
	std::string mode = value_string(e, "mode", ""), filter = value_string(e, "filter", "NONE");
	size_t end;
	if (buffer < 0 || (size_t)buffer >= m.buffers.size() || length < 0 || offset < 0 ||
	    __builtin_add_overflow((size_t)offset, (size_t)length, &end) ||
	    end > m.buffers[(size_t)buffer].data.size()) {
		*err = what + ": buffer, byteOffset and byteLength must lie inside a buffer";
		return false;
	}
	if (stride <= 0 || stride > 256 || count < 0 ||
	    (size_t)count > (256u << 20) / (size_t)stride) {
		*err = what + ": byteStride " + std::to_string(stride) + " or count " +
		       std::to_string(count) + " out of range";
		return false;
	}
	std::vector<unsigned char> out((size_t)count * (size_t)stride);
	const unsigned char *src = m.buffers[(size_t)buffer].data.data() + offset;
	int rc = -1;
	if (mode == "ATTRIBUTES" && stride % 4 == 0)
		rc = meshopt_decodeVertexBuffer(out.data(), (size_t)count, (size_t)stride, src,
						(size_t)length);
	else if (mode == "TRIANGLES" && (stride == 2 || stride == 4) && count % 3 == 0)
		rc = meshopt_decodeIndexBuffer(out.data(), (size_t)count, (size_t)stride, src,
					       (size_t)length);
	else if (mode == "INDICES" && (stride == 2 || stride == 4))
		rc = meshopt_decodeIndexSequence(out.data(), (size_t)count, (size_t)stride, src,
						 (size_t)length);
	else {
		*err = what + ": mode \"" + mode + "\" with byteStride " + std::to_string(stride) +
		       ", expected ATTRIBUTES, TRIANGLES or INDICES with a stride they allow";
		return false;
	}
	if (rc != 0) {
		*err = what + ": the compressed data is corrupt (meshopt decoder error " +
		       std::to_string(rc) + ")";
		return false;
	}
	if (!meshopt_filter(filter, out.data(), (size_t)count, (size_t)stride)) {
		*err = what + ".filter: \"" + filter + "\" with byteStride " +
		       std::to_string(stride) +
		       ", expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL";
		return false;
	}
	tinygltf::Buffer decoded;
	decoded.data = std::move(out);
	tinygltf::BufferView &bv = m.bufferViews[i];
	bv.buffer = (int)m.buffers.size();
	bv.byteOffset = 0;
	bv.byteLength = decoded.data.size();
	bv.byteStride = mode == "ATTRIBUTES" ? (size_t)stride : 0;
	m.buffers.push_back(std::move(decoded));
	return true;
}

// The Draco attributes a primitive names, decoded into float accessors.
bool draco_attributes(tinygltf::Model &m, tinygltf::Primitive &p, const gltf_draco *d,
		      const tinygltf::Value &attrs, const std::string &what, std::string *err)
{
	size_t nv = gltf_draco_vertex_count(d);
	for (const std::string &name : attrs.Keys()) {
		auto it = p.attributes.find(name);
		int id = attrs.Get(name).IsNumber() ? attrs.Get(name).GetNumberAsInt() : -1;
		if (it == p.attributes.end() || it->second < 0 ||
		    (size_t)it->second >= m.accessors.size()) {
			*err = what + ".attributes." + name + ": expected the primitive to have " +
			       "this attribute's accessor";
			return false;
		}
		int type = m.accessors[(size_t)it->second].type, n = type_components(type);
		std::vector<float> f(nv * (size_t)(n ? n : 1));
		if (n == 0 || gltf_draco_attribute(d, id, n, f.data()) != 0) {
			*err = what + ".attributes." + name + ": Draco attribute " +
			       std::to_string(id) + " is missing or has too few components";
			return false;
		}
		it->second =
		    add_float_accessor(m, std::vector<double>(f.begin(), f.end()), type, nv);
	}
	return true;
}

bool draco_primitive(tinygltf::Model &m, size_t mi, size_t pi, std::string *err)
{
	std::string what = path_of("meshes", mi) + ".primitives[" + std::to_string(pi) +
			   "].extensions.KHR_draco_mesh_compression";
	const tinygltf::Value e =
	    m.meshes[mi].primitives[pi].extensions.at("KHR_draco_mesh_compression");
	int view = value_int(e, "bufferView", -1);
	const unsigned char *bytes;
	if (view < 0 || (size_t)view >= m.bufferViews.size() || !e.Get("attributes").IsObject()) {
		*err = what + ": expected a bufferView and attributes";
		return false;
	}
	size_t length = m.bufferViews[(size_t)view].byteLength;
	if (!view_span(m, view, 0, length, length, 1, what, &bytes, err))
		return false;
	char msg[160];
	std::unique_ptr<gltf_draco, void (*)(gltf_draco *)> d(
	    gltf_draco_new(bytes, length, msg, sizeof(msg)), gltf_draco_free);
	if (!d) {
		*err = what + ": " + msg;
		return false;
	}
	tinygltf::Primitive &p = m.meshes[mi].primitives[pi];
	if (!draco_attributes(m, p, d.get(), e.Get("attributes"), what, err))
		return false;
	std::vector<uint32_t> idx(gltf_draco_index_count(d.get()));
	gltf_draco_indices(d.get(), idx.data());
	tinygltf::Buffer buf;
	buf.data.resize(idx.size() * 4);
	std::memcpy(buf.data.data(), idx.data(), buf.data.size());
	tinygltf::BufferView bv;
	bv.buffer = (int)m.buffers.size();
	bv.byteLength = buf.data.size();
	m.buffers.push_back(std::move(buf));
	tinygltf::Accessor a;
	a.bufferView = (int)m.bufferViews.size();
	a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
	a.count = idx.size();
	a.type = TINYGLTF_TYPE_SCALAR;
	a.sparse.isSparse = false;
	m.bufferViews.push_back(bv);
	m.accessors.push_back(a);
	p.indices = (int)m.accessors.size() - 1;
	p.mode = TINYGLTF_MODE_TRIANGLES;
	return true;
}

// An accessor a primitive reads that needs a plain copy.
bool needs_copy(const tinygltf::Model &m, int index)
{
	return index >= 0 && (size_t)index < m.accessors.size() &&
	       (m.accessors[(size_t)index].bufferView < 0 ||
		m.accessors[(size_t)index].sparse.isSparse);
}

bool dense_copy(tinygltf::Model &m, int *index, bool indices, const std::string &what,
		std::string *err)
{
	std::vector<double> v;
	int n;
	if (!read_accessor(m, *index, &v, &n, err)) {
		*err = what + " (" + *err + ")";
		return false;
	}
	const tinygltf::Accessor a = m.accessors[(size_t)*index];
	if (a.count == 0) {
		*err = what + " (" + path_of("accessors", (size_t)*index) + "): count is 0";
		return false;
	}
	*index = add_float_accessor(m, v, a.type, a.count);
	if (indices) {
		// Indices stay integers: a float holds them exactly only to 2^24.
		tinygltf::Buffer &buf = m.buffers.back();
		for (size_t i = 0; i < v.size(); i++) {
			uint32_t u =
			    v[i] >= 0 && v[i] < 4294967296.0 ? (uint32_t)v[i] : 0xffffffffu;
			std::memcpy(buf.data.data() + i * 4, &u, 4);
		}
		m.accessors.back().componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
	}
	return true;
}

} // namespace

bool decode_meshopt(tinygltf::Model &m, std::string *err)
{
	for (size_t i = 0; i < m.bufferViews.size(); i++) {
		auto it = m.bufferViews[i].extensions.find("EXT_meshopt_compression");
		if (it == m.bufferViews[i].extensions.end())
			continue;
		const tinygltf::Value e = it->second;
		if (!e.IsObject()) {
			*err = path_of("bufferViews", i) +
			       ".extensions.EXT_meshopt_compression: expected an object";
			return false;
		}
		if (!meshopt_view(m, i, e, err))
			return false;
	}
	return true;
}

bool decode_draco(tinygltf::Model &m, std::string *err)
{
	for (size_t mi = 0; mi < m.meshes.size(); mi++)
		for (size_t pi = 0; pi < m.meshes[mi].primitives.size(); pi++)
			if (m.meshes[mi].primitives[pi].extensions.count(
				"KHR_draco_mesh_compression") &&
			    !draco_primitive(m, mi, pi, err))
				return false;
	return true;
}

bool make_dense(tinygltf::Model &m, std::string *err)
{
	for (size_t mi = 0; mi < m.meshes.size(); mi++)
		for (size_t pi = 0; pi < m.meshes[mi].primitives.size(); pi++) {
			tinygltf::Primitive &p = m.meshes[mi].primitives[pi];
			std::string what =
			    path_of("meshes", mi) + ".primitives[" + std::to_string(pi) + "]";
			const tinygltf::Value &moved =
			    p.extras.IsObject() ? p.extras.Get(moved_indices) : p.extras;
			if (p.indices < 0 && moved.IsNumber())
				p.indices = moved.GetNumberAsInt();
			for (auto &attr : p.attributes)
				if (needs_copy(m, attr.second) &&
				    !dense_copy(m, &attr.second, false,
						what + ".attributes." + attr.first, err))
					return false;
			if (needs_copy(m, p.indices) &&
			    !dense_copy(m, &p.indices, true, what + ".indices", err))
				return false;
		}
	return true;
}

} // namespace gltf_ext
