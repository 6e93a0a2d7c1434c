// glTF through tinygltf, with our own bounds checks on every accessor.
// tinygltf parses the JSON and the GLB container; nothing it hands back is
// trusted: indices into arrays, offsets, strides and index values are all
// checked here before a byte is read.
#include "scene/gltf.h"
#include "scene/gltf_material.h"
#include "util/log.h"

#include <tiny_gltf.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

namespace
{

struct Context {
	std::string dir; // the model's folder; external files must stay in it
	std::string refused;
	std::string missing;
};

// A buffer URI may name a file beside the model or below it, never an
// absolute path or one that climbs out with "..".
bool path_allowed(const Context &c, const std::string &path)
{
	std::string prefix = c.dir.empty() ? "" : c.dir + "/";
	if (path.compare(0, prefix.size(), prefix) != 0)
		return false;
	std::string rel = path.substr(prefix.size());
	if (rel.empty() || rel[0] == '/')
		return false;
	size_t start = 0;
	while (start <= rel.size()) {
		size_t end = rel.find('/', start);
		if (end == std::string::npos)
			end = rel.size();
		if (rel.compare(start, end - start, "..") == 0 && end - start == 2)
			return false;
		start = end + 1;
	}
	return true;
}

// tinygltf looks for a buffer in more than one folder; remember the first
// refused path and any allowed one that was missing, to say which it was.
bool fs_exists(const std::string &path, void *user)
{
	Context *c = static_cast<Context *>(user);
	size_t skip = c->dir.empty() ? 0 : c->dir.size() + 1;
	std::string shown = path.size() > skip ? path.substr(skip) : path;
	if (!path_allowed(*c, path)) {
		if (c->refused.empty())
			c->refused = shown;
		return false;
	}
	std::ifstream f(path, std::ios::binary);
	if (!f.good() && c->missing.empty())
		c->missing = shown;
	return f.good();
}

std::string fs_expand(const std::string &path, void *)
{
	return path; // no "~" or variables: a URI means what it says
}

bool read_file(const std::string &path, std::vector<unsigned char> *out, std::string *err)
{
	std::ifstream f(path, std::ios::binary | std::ios::ate);
	if (!f) {
		*err = "cannot open " + path + ": " + std::strerror(errno);
		return false;
	}
	std::streamoff size = f.tellg();
	if (size < 0 || (unsigned long long)size > GLTF_MAX_FILE) {
		*err = path + " is larger than the limit";
		return false;
	}
	out->resize((size_t)size);
	f.seekg(0);
	if (size > 0 && !f.read(reinterpret_cast<char *>(out->data()), size)) {
		*err = "read error in " + path;
		return false;
	}
	return true;
}

bool fs_read(std::vector<unsigned char> *out, std::string *err, const std::string &path, void *user)
{
	Context *c = static_cast<Context *>(user);
	if (!path_allowed(*c, path)) {
		*err = "URI leaves the model's folder: " + path;
		return false;
	}
	return read_file(path, out, err);
}

bool fs_write(std::string *err, const std::string &, const std::vector<unsigned char> &, void *)
{
	*err = "writing is not allowed";
	return false;
}

// tinygltf 2.9 (Debian 13) asks for a file's size before reading it, and
// takes no callbacks at all unless this one is given too; 2.7 has no such
// member.
[[maybe_unused]] bool fs_size(size_t *size, std::string *err, const std::string &path, void *user)
{
	Context *c = static_cast<Context *>(user);
	if (!path_allowed(*c, path)) {
		*err = "URI leaves the model's folder: " + path;
		return false;
	}
	std::ifstream f(path, std::ios::binary | std::ios::ate);
	std::streamoff n = f ? std::streamoff(f.tellg()) : std::streamoff(-1);
	if (n < 0) {
		*err = "cannot open " + path + ": " + std::strerror(errno);
		return false;
	}
	*size = (size_t)n;
	return true;
}

template <typename T, typename = void> struct HasFileSize : std::false_type {
};
template <typename T>
struct HasFileSize<T, std::void_t<decltype(&T::GetFileSizeInBytes)>> : std::true_type {
};

// Members by name: 2.9 added one before user_data, so a brace list that
// fits one version does not fit the other.
template <typename T> T fs_callbacks(Context *ctx)
{
	T fs{};
	fs.FileExists = fs_exists;
	fs.ExpandFilePath = fs_expand;
	fs.ReadWholeFile = fs_read;
	fs.WriteWholeFile = fs_write;
	if constexpr (HasFileSize<T>::value)
		fs.GetFileSizeInBytes = fs_size;
	fs.user_data = ctx;
	return fs;
}

// One primitive's vertices and indices, as appended to the builder.
struct Range {
	uint32_t first_vertex, vertex_count, first_index, index_count;
	bool has_normals, has_tangents;
};

struct Builder {
	std::string name;
	std::string error;
	std::vector<double> positions; // world space, before fitting
	std::vector<float> normals;
	std::vector<float> uvs;
	std::vector<float> tangents; // xyzw, kept only when every primitive has them
	std::vector<uint32_t> indices;
	std::vector<Range> ranges;
	bool any_uvs = false;
	int material = -1; // the first primitive's with one: the model's
	bool other_materials = false;
};

typedef double Mat4[16]; // column-major, as glTF stores it

void mat_mul(const Mat4 a, const Mat4 b, Mat4 out)
{
	Mat4 r;
	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			double s = 0;
			for (int k = 0; k < 4; k++)
				s += a[k * 4 + row] * b[c * 4 + k];
			r[c * 4 + row] = s;
		}
	std::memcpy(out, r, sizeof(r));
}

void node_matrix(const tinygltf::Node &n, Mat4 out)
{
	if (n.matrix.size() == 16) {
		for (int i = 0; i < 16; i++)
			out[i] = n.matrix[i];
		return;
	}
	double t[3] = {0, 0, 0}, s[3] = {1, 1, 1}, q[4] = {0, 0, 0, 1};
	for (size_t i = 0; i < 3 && n.translation.size() == 3; i++)
		t[i] = n.translation[i];
	for (size_t i = 0; i < 3 && n.scale.size() == 3; i++)
		s[i] = n.scale[i];
	for (size_t i = 0; i < 4 && n.rotation.size() == 4; i++)
		q[i] = n.rotation[i];
	double x = q[0], y = q[1], z = q[2], w = q[3];
	double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),	 2 * (x * z - w * y),
		       2 * (x * y - w * z),	1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
		       2 * (x * z + w * y),	2 * (y * z - w * x),	 1 - 2 * (x * x + y * y)};
	for (int c = 0; c < 3; c++) {
		for (int row = 0; row < 3; row++)
			out[c * 4 + row] = r[c * 3 + row] * s[c];
		out[c * 4 + 3] = 0;
	}
	out[12] = t[0];
	out[13] = t[1];
	out[14] = t[2];
	out[15] = 1;
}

// The normal matrix is the inverse transpose of the upper 3x3, which is
// its cofactor matrix over the determinant. Directions are normalised
// later, so only the determinant's sign is kept: a negative one mirrors
// the model, and then the winding must flip too.
double normal_matrix(const Mat4 m, double n[9])
{
	double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6],
	       i = m[10];
	double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
	// Cofactors C(row, col), stored column by column.
	double cof[9] = {e * i - f * h,	   -(b * i - c * h), b * f - c * e,
			 -(d * i - f * g), a * i - c * g,    -(a * f - c * d),
			 d * h - e * g,	   -(a * h - b * g), a * e - b * d};
	for (int k = 0; k < 9; k++)
		n[k] = det < 0 ? -cof[k] : cof[k];
	return det;
}

// A checked view of one accessor: where element i starts, and how to read
// its components. Built only after every offset has been proven in range.
struct View {
	const unsigned char *base = nullptr;
	size_t stride = 0;
	size_t count = 0;
	int components = 0;
	int component_type = 0;
	bool normalized = false;
};

size_t component_size(int type)
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

bool fail(Builder &b, const std::string &what, const std::string &msg)
{
	b.error = what + ": " + msg;
	return false;
}

// `types` lists the accepted component types, ending in 0.
bool check_accessor(Builder &b, const tinygltf::Model &m, int index, int type, const int *types,
		    const std::string &what, View *v)
{
	std::string w = what + " (accessor " + std::to_string(index) + ")";
	if (index < 0 || (size_t)index >= m.accessors.size())
		return fail(b, what, "accessor " + std::to_string(index) + " does not exist");
	const tinygltf::Accessor &a = m.accessors[(size_t)index];
	bool type_ok = false;
	for (const int *t = types; *t; t++)
		type_ok |= a.componentType == *t;
	if (a.type != type || !type_ok)
		return fail(b, w, "unexpected element type");
	if (a.sparse.isSparse)
		return fail(b, w, "sparse accessors are not supported");
	if (a.bufferView < 0 || (size_t)a.bufferView >= m.bufferViews.size())
		return fail(b, w, "bufferView " + std::to_string(a.bufferView) + " does not exist");
	const tinygltf::BufferView &bv = m.bufferViews[(size_t)a.bufferView];
	if (bv.buffer < 0 || (size_t)bv.buffer >= m.buffers.size())
		return fail(b, w, "buffer " + std::to_string(bv.buffer) + " does not exist");
	const std::vector<unsigned char> &buf = m.buffers[(size_t)bv.buffer].data;
	size_t elem =
	    component_size(a.componentType) * (size_t)tinygltf::GetNumComponentsInType(a.type);
	size_t stride = bv.byteStride ? bv.byteStride : elem;
	size_t view_end, last, end;
	if (a.count == 0)
		return fail(b, w, "count is 0");
	if (stride < elem)
		return fail(b, w,
			    "byteStride " + std::to_string(stride) + " is smaller than an element");
	if (__builtin_add_overflow(bv.byteOffset, bv.byteLength, &view_end) ||
	    view_end > buf.size())
		return fail(b, w,
			    "bufferView " + std::to_string(a.bufferView) +
				" runs past the end of its buffer (" + std::to_string(buf.size()) +
				" bytes)");
	if (__builtin_mul_overflow(stride, a.count - 1, &last) ||
	    __builtin_add_overflow(last, a.byteOffset, &last) ||
	    __builtin_add_overflow(last, elem, &end) || end > bv.byteLength)
		return fail(b, w,
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

double read_component(const View &v, size_t i, int c)
{
	const unsigned char *p =
	    v.base + i * v.stride + (size_t)c * component_size(v.component_type);
	switch (v.component_type) {
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
		return v.normalized ? u / 65535.0 : u;
	}
	case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
		return v.normalized ? *p / 255.0 : *p;
	default:
		return 0.0;
	}
}

const int float_only[] = {TINYGLTF_COMPONENT_TYPE_FLOAT, 0};
const int uv_types[] = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
			TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 0};
const int index_types[] = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
			   TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
			   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, 0};

// Triangle lists, strips and fans become one list; the mirrored flag and
// the strip's alternating order decide the winding.
bool append_triangles(Builder &b, const std::vector<uint32_t> &src, int mode, bool mirrored,
		      uint32_t first)
{
	size_t n = src.size();
	size_t tris = mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : (n >= 3 ? n - 2 : 0);
	for (size_t t = 0; t < tris; t++) {
		uint32_t i0, i1, i2;
		if (mode == TINYGLTF_MODE_TRIANGLES) {
			i0 = src[t * 3], i1 = src[t * 3 + 1], i2 = src[t * 3 + 2];
		} else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
			i0 = src[t], i1 = src[t + 1 + (t & 1)], i2 = src[t + 2 - (t & 1)];
		} else {
			i0 = src[0], i1 = src[t + 1], i2 = src[t + 2];
		}
		if (mirrored)
			std::swap(i1, i2);
		b.indices.push_back(first + i0);
		b.indices.push_back(first + i1);
		b.indices.push_back(first + i2);
	}
	return true;
}

bool read_indices(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		  size_t vertex_count, const std::string &what, std::vector<uint32_t> *out)
{
	if (p.indices < 0) {
		for (size_t i = 0; i < vertex_count; i++)
			out->push_back((uint32_t)i);
		return true;
	}
	View v;
	if (!check_accessor(b, m, p.indices, TINYGLTF_TYPE_SCALAR, index_types, what + " indices",
			    &v))
		return false;
	out->reserve(v.count);
	for (size_t i = 0; i < v.count; i++) {
		double idx = read_component(v, i, 0);
		if (idx >= (double)vertex_count)
			return fail(b,
				    what + " indices (accessor " + std::to_string(p.indices) + ")",
				    "index " + std::to_string((uint64_t)idx) + " at position " +
					std::to_string(i) + " is not below the vertex count " +
					std::to_string(vertex_count));
		out->push_back((uint32_t)idx);
	}
	return true;
}

// A tangent is a direction along the surface: it turns with the model
// matrix itself (not the normal matrix). A mirroring transform flips the
// bitangent cross(n, t) against the surface, so w flips with it. Length
// and orthogonality are restored later against the final normals.
void push_tangent(Builder &b, const View &tan, size_t i, const Mat4 world, double det)
{
	double t[3], w = read_component(tan, i, 3);
	for (int k = 0; k < 3; k++)
		t[k] = world[k] * read_component(tan, i, 0) +
		       world[4 + k] * read_component(tan, i, 1) +
		       world[8 + k] * read_component(tan, i, 2);
	for (int k = 0; k < 3; k++)
		b.tangents.push_back(std::isfinite(t[k]) ? (float)t[k] : 0.0f);
	b.tangents.push_back((w < 0) != (det < 0) ? -1.0f : 1.0f);
}

// A primitive's vertex attributes, checked: an absent one has count 0.
struct Attributes {
	View pos, nrm, uv, tan;
};

int find_attribute(const tinygltf::Primitive &p, const char *key)
{
	auto it = p.attributes.find(key);
	return it == p.attributes.end() ? -1 : it->second;
}

// An attribute the primitive may leave out: absent, or checked.
bool check_optional(Builder &b, const tinygltf::Model &m, int index, int type, const int *types,
		    const std::string &what, View *v)
{
	return index < 0 || check_accessor(b, m, index, type, types, what, v);
}

bool same_count(const View &v, size_t count)
{
	return v.count == 0 || v.count == count;
}

bool check_attributes(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		      const std::string &what, Attributes *a)
{
	int ipos = find_attribute(p, "POSITION"), inrm = find_attribute(p, "NORMAL"),
	    iuv = find_attribute(p, "TEXCOORD_0"), itan = find_attribute(p, "TANGENT");
	if (ipos < 0)
		return fail(b, what, "has no POSITION attribute");
	if (!check_accessor(b, m, ipos, TINYGLTF_TYPE_VEC3, float_only, what + " POSITION",
			    &a->pos) ||
	    !check_optional(b, m, inrm, TINYGLTF_TYPE_VEC3, float_only, what + " NORMAL",
			    &a->nrm) ||
	    !check_optional(b, m, iuv, TINYGLTF_TYPE_VEC2, uv_types, what + " TEXCOORD_0",
			    &a->uv) ||
	    !check_optional(b, m, itan, TINYGLTF_TYPE_VEC4, float_only, what + " TANGENT", &a->tan))
		return false;
	size_t n = a->pos.count;
	if (!same_count(a->nrm, n) || !same_count(a->uv, n) || !same_count(a->tan, n))
		return fail(b, what, "attributes differ in count from POSITION");
	if (b.positions.size() / 3 + n > 0x7fffffff)
		return fail(b, what, "too many vertices in the model");
	return true;
}

bool push_position(Builder &b, const View &pos, size_t i, const Mat4 world, const std::string &what)
{
	double x = read_component(pos, i, 0), y = read_component(pos, i, 1),
	       z = read_component(pos, i, 2);
	if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
		return fail(b, what + " POSITION",
			    "vertex " + std::to_string(i) + " is not a finite number");
	for (int k = 0; k < 3; k++)
		b.positions.push_back(world[k] * x + world[4 + k] * y + world[8 + k] * z +
				      world[12 + k]);
	return true;
}

// Through the normal matrix and normalised; +z where the model has no
// normals, or this one has no length.
void push_normal(Builder &b, const View *nrm, size_t i, const double nm[9])
{
	double n[3] = {0, 0, 1}, len = 0;
	if (nrm) {
		double a = read_component(*nrm, i, 0), c = read_component(*nrm, i, 1),
		       d = read_component(*nrm, i, 2);
		for (int k = 0; k < 3; k++)
			n[k] = nm[k] * a + nm[3 + k] * c + nm[6 + k] * d;
		len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	}
	for (int k = 0; k < 3; k++)
		b.normals.push_back(len > 0 && std::isfinite(len) ? (float)(n[k] / len)
								  : (float)(k == 2));
}

bool read_vertices(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		   const Mat4 world, const std::string &what, Range *r)
{
	Attributes a = {};
	if (!check_attributes(b, m, p, what, &a))
		return false;
	double nm[9];
	double det = normal_matrix(world, nm);
	r->has_normals = a.nrm.count > 0 && det != 0.0;
	r->has_tangents = a.tan.count > 0 && r->has_normals;
	for (size_t i = 0; i < a.pos.count; i++) {
		if (!push_position(b, a.pos, i, world, what))
			return false;
		push_normal(b, r->has_normals ? &a.nrm : nullptr, i, nm);
		for (int k = 0; k < 2; k++)
			b.uvs.push_back(a.uv.count ? (float)read_component(a.uv, i, k) : 0.0f);
		if (r->has_tangents)
			push_tangent(b, a.tan, i, world, det);
	}
	b.any_uvs |= a.uv.count > 0;
	r->vertex_count = (uint32_t)a.pos.count;
	return true;
}

bool add_primitive(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		   const Mat4 world, const std::string &what)
{
	if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
	    p.mode != TINYGLTF_MODE_TRIANGLE_FAN && p.mode != -1) {
		log_debug("%s: %s is not made of triangles, skipped", b.name.c_str(), what.c_str());
		return true;
	}
	Range r = {};
	if (p.material >= 0 && b.material < 0)
		b.material = p.material;
	else if (p.material != b.material)
		b.other_materials = true;
	r.first_vertex = (uint32_t)(b.positions.size() / 3);
	r.first_index = (uint32_t)b.indices.size();
	std::vector<uint32_t> idx;
	if (!read_vertices(b, m, p, world, what, &r) ||
	    !read_indices(b, m, p, r.vertex_count, what, &idx))
		return false;
	double nm[9];
	bool mirrored = normal_matrix(world, nm) < 0;
	append_triangles(b, idx, p.mode == -1 ? TINYGLTF_MODE_TRIANGLES : p.mode, mirrored,
			 r.first_vertex);
	r.index_count = (uint32_t)(b.indices.size() - r.first_index);
	b.ranges.push_back(r);
	return true;
}

bool add_node(Builder &b, const tinygltf::Model &m, int index, const Mat4 parent,
	      std::vector<char> &visiting)
{
	if (index < 0 || (size_t)index >= m.nodes.size())
		return fail(b, "scene", "node " + std::to_string(index) + " does not exist");
	if (visiting[(size_t)index])
		return fail(b, "node " + std::to_string(index), "is its own ancestor (a cycle)");
	const tinygltf::Node &n = m.nodes[(size_t)index];
	Mat4 local, world;
	node_matrix(n, local);
	mat_mul(parent, local, world);
	if (n.mesh >= 0) {
		if ((size_t)n.mesh >= m.meshes.size())
			return fail(b, "node " + std::to_string(index),
				    "mesh " + std::to_string(n.mesh) + " does not exist");
		const tinygltf::Mesh &mesh = m.meshes[(size_t)n.mesh];
		for (size_t i = 0; i < mesh.primitives.size(); i++)
			if (!add_primitive(b, m, mesh.primitives[i], world,
					   "mesh " + std::to_string(n.mesh) + " primitive " +
					       std::to_string(i)))
				return false;
	}
	visiting[(size_t)index] = 1;
	for (int child : n.children)
		if (!add_node(b, m, child, world, visiting))
			return false;
	visiting[(size_t)index] = 0;
	return true;
}

int finish_mesh(Builder &b, struct mesh *out)
{
	uint32_t nv = (uint32_t)(b.positions.size() / 3);
	if (b.indices.empty()) {
		b.error = "the default scene has no triangles to draw";
		return -EINVAL;
	}
	if (mesh_alloc(out, nv, (uint32_t)b.indices.size(), b.any_uvs))
		return -ENOMEM;
	mesh_fit_positions(b.positions.data(), nv, out->positions);
	std::memcpy(out->normals, b.normals.data(), b.normals.size() * sizeof(float));
	std::memcpy(out->indices, b.indices.data(), b.indices.size() * sizeof(uint32_t));
	if (b.any_uvs)
		std::memcpy(out->uvs, b.uvs.data(), b.uvs.size() * sizeof(float));
	bool all_tangents = true;
	for (const Range &r : b.ranges)
		all_tangents &= r.has_tangents;
	if (all_tangents && b.tangents.size() == (size_t)nv * 4) {
		if (mesh_alloc_tangents(out)) {
			mesh_release(out);
			return -ENOMEM;
		}
		std::memcpy(out->tangents, b.tangents.data(), b.tangents.size() * sizeof(float));
	}
	for (const Range &r : b.ranges)
		if (!r.has_normals &&
		    mesh_generate_normals(out->positions, out->indices + r.first_index,
					  r.index_count, r.first_vertex, r.vertex_count,
					  out->normals)) {
			mesh_release(out);
			return -ENOMEM;
		}
	return 0;
}

int build_mesh(const char *name, const tinygltf::Model &m, unsigned textures,
	       const GltfImages &images, struct mesh *out)
{
	Builder b;
	b.name = name;
	Mat4 identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
	std::vector<char> visiting(m.nodes.size(), 0);
	int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
	int ret;

	if (m.scenes.empty()) {
		b.error = "has no scene to show";
	} else if ((size_t)scene >= m.scenes.size()) {
		b.error = "default scene " + std::to_string(scene) + " does not exist";
	} else {
		for (int root : m.scenes[(size_t)scene].nodes)
			if (!add_node(b, m, root, identity, visiting))
				break;
	}
	ret = b.error.empty() ? finish_mesh(b, out) : -EINVAL;
	if (ret == -EINVAL && !b.error.empty())
		log_err("%s: %s", name, b.error.c_str());
	else if (ret == 0)
		log_info("%s: %u vertices, %u triangles", name, out->vertex_count,
			 out->index_count / 3);
	if (ret == 0 && b.other_materials)
		log_info("%s: primitives differ in material; the first one's is shown", name);
	if (ret == 0)
		gltf_read_material(m, b.material, textures, images, name, &out->material);
	return ret;
}

int load_memory(const char *name, const uint8_t *data, size_t size, const char *dir,
		unsigned textures, struct mesh *out)
{
	tinygltf::TinyGLTF loader;
	tinygltf::Model model;
	std::string err, warn;
	Context ctx;
	GltfImages images;
	ctx.dir = dir ? dir : "";
	images.keep = textures != 0;
	std::memset(out, 0, sizeof(*out));

	if (size > GLTF_MAX_FILE || size > 0xffffffffu) {
		log_err("%s: file is %zu bytes, expected at most %u", name, size, GLTF_MAX_FILE);
		return -EFBIG;
	}
	loader.SetFsCallbacks(fs_callbacks<tinygltf::FsCallbacks>(&ctx));
	// Images are decoded by our own libpng/libjpeg path, and only those a
	// feature asked for; never by the stb copy inside the library.
	loader.SetImageLoader(gltf_keep_image, &images);
	bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
	bool ok =
	    glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, (unsigned)size, ctx.dir)
		: loader.LoadASCIIFromString(&model, &err, &warn,
					     reinterpret_cast<const char *>(data), (unsigned)size,
					     ctx.dir);
	if (!ok) {
		if (!ctx.missing.empty())
			err = "buffer file \"" + ctx.missing + "\" does not exist beside the model";
		else if (!ctx.refused.empty())
			err = "buffer URI \"" + ctx.refused +
			      "\" is not a file beside the model (absolute paths and \"..\" "
			      "are refused)";
		else if (err.empty())
			err = "not a glTF 2.0 file";
		for (char &ch : err)
			if (ch == '\n')
				ch = ' ';
		while (!err.empty() && err.back() == ' ')
			err.pop_back();
		log_err("%s: %s", name, err.c_str());
		return -EINVAL;
	}
	return build_mesh(name, model, textures, images, out);
}

} // namespace

extern "C" int gltf_load_memory_textures(const char *name, const uint8_t *data, size_t size,
					 const char *dir, unsigned textures, struct mesh *out)
{
	// No exception may cross into C: a model too large for memory, or a
	// fault inside the parser, is one more error line.
	try {
		return load_memory(name, data, size, dir, textures, out);
	} catch (const std::exception &e) {
		log_err("%s: cannot load: %s", name, e.what());
	} catch (...) {
		log_err("%s: cannot load: unexpected fault in the glTF parser", name);
	}
	mesh_release(out);
	return -EINVAL;
}

extern "C" int gltf_load_memory(const char *name, const uint8_t *data, size_t size, const char *dir,
				struct mesh *out)
{
	return gltf_load_memory_textures(name, data, size, dir, 0, out);
}

extern "C" int gltf_load_textures(const char *path, unsigned textures, struct mesh *out)
{
	std::vector<unsigned char> bytes;
	std::string err;
	std::string dir = path;
	size_t slash = dir.rfind('/');
	dir = slash == std::string::npos ? "" : dir.substr(0, slash);

	std::memset(out, 0, sizeof(*out));
	if (!read_file(path, &bytes, &err)) {
		log_err("%s: %s", path, err.c_str());
		return -ENOENT;
	}
	return gltf_load_memory_textures(path, bytes.data(), bytes.size(), dir.c_str(), textures,
					 out);
}

extern "C" int gltf_load(const char *path, struct mesh *out)
{
	return gltf_load_textures(path, 0, out);
}
