// The mesh builder of the glTF shim: the default scene's nodes walked in
// order, every triangle primitive's accessors checked (gltf_accessor.h:
// offsets and strides before a byte is read; index values here), and
// appended to one plain struct mesh. Split from gltf.cc, which reads and
// parses the file.
#include "scene/gltf/gltf_accessor.h"
#include "scene/gltf/gltf_ext.h"
#include "scene/gltf/gltf_material.h"
#include "scene/gltf/gltf_variants.h"
#include "scene/gltf/gltf_mesh.h"
#include "scene/gltf/gltf_anim.h"
#include "scene/gltf/gltf_fit.h"
#include "scene/gltf/gltf_play.h"
#include "scene/gltf/gltf_flat.h"
#include "util/log.h"
#include "util/math3d.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace
{

// One primitive's vertices and indices, as appended to the builder, and
// the glTF material it names (-1: none).
struct Range {
	uint32_t first_vertex, vertex_count, first_index, index_count;
	bool has_normals, has_tangents, flat; // flat: split at its faces (gltf_flat.h)
	size_t source_at;		      // its vertices' file vertex in Builder::source (flat)
	int material;
	int node, mesh, primitive; // the node showing it, the file's mesh and primitive
};

struct Builder {
	std::string name;
	std::string error;
	std::vector<double> positions; // world space, before fitting
	std::vector<float> normals;
	std::vector<float> uvs;
	std::vector<float> uv1;	     // only once an emissive map needs it: gltf_emissive_uv_set
	std::vector<float> tangents; // xyzw, kept only when every primitive has them
	std::vector<float> colors;   // rgba, linear (struct mesh colors), when they differ
	std::vector<uint32_t> indices;
	std::vector<Range> ranges;
	bool any_uvs = false;
	bool want_colors = false, any_colors = false;
	// While colors is empty: the one colour of every vertex so far
	// (mesh.vertex_color), so a model of one material costs no array.
	float uniform[4] = {1, 1, 1, 1};
	bool uniform_set = false;
	unsigned textures = 0;		      // enum gltf_texture: what is asked, for the UV set
	std::vector<int> slots;		      // the glTF material of each of out->materials
	size_t not_triangles = 0;	      // primitives of points or lines, left out
	int normals_mode = MESH_NORMALS_FILE; // [scene] normals
	std::vector<uint32_t> source;	      // each flat range's vertices' in the primitive
};

typedef double Mat4[16]; // column-major, as glTF stores it

// Room for `more` elements, at least doubling (as push_back would,
// without its copies on the way there).
template <typename T> void grow(std::vector<T> &v, size_t more)
{
	if (v.capacity() - v.size() < more)
		v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

bool fail(Builder &b, const std::string &what, const std::string &msg)
{
	b.error = what + ": " + msg;
	return false;
}

bool check_accessor(Builder &b, const tinygltf::Model &m, int index, int type, const int *types,
		    const std::string &what, GltfView *v)
{
	return gltf_view_check(m, index, type, types, what, v, &b.error);
}

bool check_color(Builder &b, const tinygltf::Model &m, int index, const std::string &what,
		 GltfView *v)
{
	return gltf_view_color(m, index, what, v, &b.error);
}

// Triangle lists, strips and fans become one list; the mirrored flag and
// the strip's alternating order decide the winding.
bool append_triangles(Builder &b, const std::vector<uint32_t> &src, int mode, bool mirrored,
		      uint32_t first)
{
	size_t n = src.size();
	size_t tris = mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : (n >= 3 ? n - 2 : 0);
	grow(b.indices, 3 * tris);
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
	GltfView v;
	if (!check_accessor(b, m, p.indices, TINYGLTF_TYPE_SCALAR, gltf_index_types,
			    what + ".indices", &v))
		return false;
	out->reserve(v.count);
	for (size_t i = 0; i < v.count; i++) {
		double idx = gltf_view_read(v, i, 0);
		if (idx >= (double)vertex_count)
			return fail(
			    b, what + ".indices (accessors[" + std::to_string(p.indices) + "])",
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
void push_tangent(Builder &b, const GltfView &tan, size_t i, const Mat4 world, double det)
{
	double t[3], w = gltf_view_read(tan, i, 3);
	for (int k = 0; k < 3; k++)
		t[k] = world[k] * gltf_view_read(tan, i, 0) +
		       world[4 + k] * gltf_view_read(tan, i, 1) +
		       world[8 + k] * gltf_view_read(tan, i, 2);
	for (int k = 0; k < 3; k++)
		b.tangents.push_back(std::isfinite(t[k]) ? (float)t[k] : 0.0f);
	b.tangents.push_back((w < 0) != (det < 0) ? -1.0f : 1.0f);
}

// A primitive's vertex attributes, checked: an absent one has count 0.
struct Attributes {
	GltfView pos, nrm, uv, tan, col, uv1;
};

int find_attribute(const tinygltf::Primitive &p, const char *key)
{
	auto it = p.attributes.find(key);
	return it == p.attributes.end() ? -1 : it->second;
}

// An attribute the primitive may leave out: absent, or checked.
bool check_optional(Builder &b, const tinygltf::Model &m, int index, int type, const int *types,
		    const std::string &what, GltfView *v)
{
	return index < 0 || check_accessor(b, m, index, type, types, what, v);
}

bool same_count(const GltfView &v, size_t count)
{
	return v.count == 0 || v.count == count;
}

bool check_attributes(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		      const std::string &what, Attributes *a)
{
	std::string uv = "TEXCOORD_" + std::to_string(gltf_uv_set(m, p.material, b.textures));
	int ipos = find_attribute(p, "POSITION"), inrm = find_attribute(p, "NORMAL"),
	    iuv = find_attribute(p, uv.c_str()), itan = find_attribute(p, "TANGENT");
	if (ipos < 0)
		return fail(b, what + ".attributes", "has no POSITION, expected one");
	std::string at = what + ".attributes.";
	if (!check_accessor(b, m, ipos, TINYGLTF_TYPE_VEC3, gltf_position_types, at + "POSITION",
			    &a->pos) ||
	    !check_optional(b, m, inrm, TINYGLTF_TYPE_VEC3, gltf_direction_types, at + "NORMAL",
			    &a->nrm) ||
	    !check_optional(b, m, iuv, TINYGLTF_TYPE_VEC2, gltf_position_types, at + uv, &a->uv) ||
	    !check_optional(b, m, itan, TINYGLTF_TYPE_VEC4, gltf_direction_types, at + "TANGENT",
			    &a->tan))
		return false;
	size_t n = a->pos.count;
	int set1 = gltf_emissive_uv_set(m, p.material, b.textures);
	std::string uv1 = "TEXCOORD_" + std::to_string(set1);
	if (set1 >= 0 && !check_optional(b, m, find_attribute(p, uv1.c_str()), TINYGLTF_TYPE_VEC2,
					 gltf_position_types, at + uv1, &a->uv1))
		return false;
	int icol = b.want_colors ? find_attribute(p, "COLOR_0") : -1;
	if (icol >= 0 && !check_color(b, m, icol, at + "COLOR_0", &a->col))
		return false;
	if (!same_count(a->nrm, n) || !same_count(a->uv, n) || !same_count(a->tan, n) ||
	    !same_count(a->col, n) || !same_count(a->uv1, n))
		return fail(b, what, "attributes differ in count from POSITION");
	if (b.positions.size() / 3 + n > 0x7fffffff)
		return fail(b, what, "too many vertices in the model");
	return true;
}

bool push_position(Builder &b, const GltfView &pos, size_t i, const Mat4 world,
		   const std::string &what)
{
	double x = gltf_view_read(pos, i, 0), y = gltf_view_read(pos, i, 1),
	       z = gltf_view_read(pos, i, 2);
	if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
		return fail(b, what + ".attributes.POSITION",
			    "vertex " + std::to_string(i) + " is not a finite number");
	for (int k = 0; k < 3; k++)
		b.positions.push_back(world[k] * x + world[4 + k] * y + world[8 + k] * z +
				      world[12 + k]);
	return true;
}

// Through the normal matrix and normalised; +z where the model has no
// normals, or this one has no length.
void push_normal(Builder &b, const GltfView *nrm, size_t i, const double nm[9])
{
	double n[3] = {0, 0, 1}, len = 0;
	if (nrm) {
		double a = gltf_view_read(*nrm, i, 0), c = gltf_view_read(*nrm, i, 1),
		       d = gltf_view_read(*nrm, i, 2);
		for (int k = 0; k < 3; k++)
			n[k] = nm[k] * a + nm[3 + k] * c + nm[6 + k] * d;
		len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	}
	for (int k = 0; k < 3; k++)
		b.normals.push_back(len > 0 && std::isfinite(len) ? (float)(n[k] / len)
								  : (float)(k == 2));
}

// Whether this primitive's vertices need a colour each: only once a
// primitive has COLOR_0 or another colour than those before it. Then the
// constant so far becomes the first vertices' colours.
bool colors_per_vertex(Builder &b, const float base[4], bool has_color_0, size_t vertices_before)
{
	bool same = true;
	if (!b.want_colors)
		return false;
	for (int k = 0; k < 4; k++)
		same &= !b.uniform_set || b.uniform[k] == base[k];
	if (b.colors.empty() && !has_color_0 && same) {
		std::copy(base, base + 4, b.uniform);
		b.uniform_set = true;
		return false;
	}
	if (b.colors.empty()) {
		b.colors.reserve(vertices_before * 4);
		for (size_t i = 0; b.uniform_set && i < vertices_before; i++)
			b.colors.insert(b.colors.end(), b.uniform, b.uniform + 4);
	}
	return true;
}

// Room for n more vertices in every array they are pushed to.
void make_room(Builder &b, size_t n, bool tangents, bool colors)
{
	grow(b.positions, 3 * n);
	grow(b.normals, 3 * n);
	grow(b.uvs, 2 * n);
	if (tangents)
		grow(b.tangents, 4 * n);
	if (colors)
		grow(b.colors, 4 * n);
}

// Second UVs: once a primitive has them, every vertex has them (or 0, 0).
void read_uv1(Builder &b, const GltfView &uv1, size_t before, size_t n)
{
	if (!uv1.count && b.uv1.empty())
		return;
	b.uv1.resize(before * 2, 0.0f);
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < 2; k++)
			b.uv1.push_back(uv1.count ? (float)gltf_view_read(uv1, i, k) : 0.0f);
}

bool read_vertices(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		   const Mat4 world, const std::string &what, Range *r)
{
	Attributes a = {};
	if (!check_attributes(b, m, p, what, &a))
		return false;
	double nm[9];
	// The normal matrix: the inverse transpose of the upper 3x3 (math3d.h).
	double det = mat4_normal_matrix(world, nm);
	float base[4];
	bool coloured = gltf_primitive_base(m, p.material, base);
	r->has_normals = a.nrm.count > 0 && det != 0.0 && b.normals_mode != MESH_NORMALS_FLAT;
	r->flat = !r->has_normals && b.normals_mode != MESH_NORMALS_SMOOTH;
	r->has_tangents = a.tan.count > 0 && r->has_normals;
	bool per_vertex = colors_per_vertex(b, base, a.col.count > 0, b.positions.size() / 3);
	make_room(b, a.pos.count, r->has_tangents, per_vertex);
	for (size_t i = 0; i < a.pos.count; i++) {
		if (!push_position(b, a.pos, i, world, what))
			return false;
		push_normal(b, r->has_normals ? &a.nrm : nullptr, i, nm);
		for (int k = 0; k < 2; k++)
			b.uvs.push_back(a.uv.count ? (float)gltf_view_read(a.uv, i, k) : 0.0f);
		if (r->has_tangents)
			push_tangent(b, a.tan, i, world, det);
		for (int k = 0; per_vertex && k < 4; k++) { // a float colour may leave [0, 1]
			double c = k < a.col.components ? gltf_view_read(a.col, i, k) : 1.0;
			b.colors.push_back(base[k] * (float)(c >= 0.0 ? std::fmin(c, 1.0) : 0.0));
		}
	}
	read_uv1(b, a.uv1, b.positions.size() / 3 - a.pos.count, a.pos.count);
	b.any_uvs |= a.uv.count > 0;
	b.any_colors |= a.col.count > 0 || coloured;
	r->vertex_count = (uint32_t)a.pos.count;
	return true;
}

bool add_primitive(Builder &b, const tinygltf::Model &m, const tinygltf::Primitive &p,
		   const Mat4 world, const std::string &what)
{
	if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
	    p.mode != TINYGLTF_MODE_TRIANGLE_FAN && p.mode != -1) {
		b.not_triangles++;
		return true;
	}
	Range r = {};
	r.material = p.material >= 0 && (size_t)p.material < m.materials.size() ? p.material : -1;
	r.first_vertex = (uint32_t)(b.positions.size() / 3);
	r.first_index = (uint32_t)b.indices.size();
	std::vector<uint32_t> idx;
	if (!read_vertices(b, m, p, world, what, &r) ||
	    !read_indices(b, m, p, r.vertex_count, what, &idx))
		return false;
	double nm[9];
	bool mirrored = mat4_normal_matrix(world, nm) < 0;
	append_triangles(b, idx, p.mode == -1 ? TINYGLTF_MODE_TRIANGLES : p.mode, mirrored,
			 r.first_vertex);
	r.source_at = b.source.size();
	if (r.flat)
		r.vertex_count = gltf_split_faces(
		    {&b.positions, &b.normals, &b.uvs, &b.colors, &b.uv1, &b.indices, &b.source},
		    r.first_vertex, r.first_index);
	r.index_count = (uint32_t)(b.indices.size() - r.first_index);
	b.ranges.push_back(r);
	return true;
}

typedef gltf_ext::Pose Pose;

bool add_mesh(Builder &b, const tinygltf::Model &m, size_t node, const Mat4 world)
{
	const tinygltf::Node &n = m.nodes[node];
	if ((size_t)n.mesh >= m.meshes.size())
		return fail(b, "nodes[" + std::to_string(node) + "].mesh",
			    "mesh " + std::to_string(n.mesh) + " does not exist");
	const tinygltf::Mesh &mesh = m.meshes[(size_t)n.mesh];
	int shown = n.mesh;
	for (size_t i = 0; i < mesh.primitives.size(); i++) {
		size_t before = b.ranges.size();
		if (!add_primitive(b, m, mesh.primitives[i], world,
				   "meshes[" + std::to_string(shown) + "].primitives[" +
				       std::to_string(i) + "]"))
			return false;
		if (b.ranges.size() > before) // for live playback (gltf_play.h)
			b.ranges.back().node = (int)node, b.ranges.back().mesh = shown,
			b.ranges.back().primitive = (int)i;
	}
	return true;
}

// Depth first and in the file's order, as the recursion before it was,
// over an explicit stack: the hierarchy's depth costs memory, not stack.
bool add_scene(Builder &b, const tinygltf::Model &m, const std::vector<int> &roots,
	       const std::string &what, const Pose &pose)
{
	static const Mat4 identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
	std::vector<size_t> stack;
	for (size_t k = roots.size(); k-- > 0;) {
		int r = roots[k];
		std::string w = what + ".nodes[" + std::to_string(k) + "]";
		if (r < 0 || (size_t)r >= m.nodes.size())
			return fail(b, w, "node " + std::to_string(r) + " does not exist");
		if (pose.parent[(size_t)r] >= 0)
			return fail(b, w,
				    "nodes[" + std::to_string(r) + "] is a child of nodes[" +
					std::to_string(pose.parent[(size_t)r]) +
					"], expected a root");
		stack.push_back((size_t)r);
	}
	while (!stack.empty()) {
		size_t i = stack.back();
		stack.pop_back();
		const tinygltf::Node &n = m.nodes[i];
		// A skinned node's mesh is placed as bound: the node's own
		// transform does not apply to it, as the spec says, and
		// gltf_play_still poses it.
		if (n.mesh >= 0 && !add_mesh(b, m, i, n.skin >= 0 ? identity : pose.worlds[i].m))
			return false;
		for (size_t k = n.children.size(); k-- > 0;)
			stack.push_back((size_t)n.children[k]);
	}
	return true;
}

bool has_extent(const std::vector<double> &p)
{
	for (size_t i = 3; i < p.size(); i++)
		if (p[i] != p[i % 3])
			return true;
	return false;
}

int finish_mesh(Builder &b, const tinygltf::Model &m, struct mesh *out, const GltfFit &fit)
{
	uint32_t nv = (uint32_t)(b.positions.size() / 3);
	if (b.indices.empty()) {
		b.error = b.not_triangles
			      ? "the scene has only points or lines, expected triangles"
			      : "the scene has no triangles to draw, expected at least one";
		return -EINVAL;
	}
	if (!has_extent(b.positions)) {
		b.error = "every POSITION is the same point, expected a model with an extent";
		return -EINVAL;
	}
	if (mesh_alloc(out, nv, (uint32_t)b.indices.size(), b.any_uvs))
		return -ENOMEM;
	if (fit.use_fit) {
		std::memcpy(out->fit, fit.center, sizeof(fit.center));
		out->fit[3] = fit.scale;
	} else {
		mesh_fit_of(b.positions.data(), nv, out->fit);
	}
	mesh_fit_to(b.positions.data(), nv, out->fit, out->fit[3], out->positions);
	std::memcpy(out->normals, b.normals.data(), b.normals.size() * sizeof(float));
	std::memcpy(out->indices, b.indices.data(), b.indices.size() * sizeof(uint32_t));
	std::vector<GltfVariantPart> parts;
	for (const Range &r : b.ranges)
		parts.push_back({{r.first_index, r.index_count, r.material}, r.mesh, r.primitive});
	int grouped = gltf_variants_group(m, parts, b.indices.data(), out, &b.slots, &b.error);
	if (grouped) {
		mesh_release(out);
		return grouped;
	}
	if (b.any_uvs)
		std::memcpy(out->uvs, b.uvs.data(), b.uvs.size() * sizeof(float));
	if (b.any_uvs && b.uv1.size() == (size_t)nv * 2 && mesh_alloc_uv1(out, b.uv1.data())) {
		mesh_release(out);
		return -ENOMEM;
	}
	if (b.any_colors && b.colors.size() == (size_t)nv * 4) {
		if (mesh_alloc_colors(out)) {
			mesh_release(out);
			return -ENOMEM;
		}
		std::memcpy(out->colors, b.colors.data(), b.colors.size() * sizeof(float));
	}
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
		if (gltf_range_normals(out, b.indices.data() + r.first_index, r.index_count,
				       r.first_vertex, r.vertex_count, r.has_normals, r.flat)) {
			mesh_release(out);
			return -ENOMEM;
		}
	return 0;
}

// Live playback's parts: the primitives as the builder appended them.
std::vector<GltfPlayPart> play_parts(const Builder &b)
{
	std::vector<GltfPlayPart> parts;
	for (const Range &r : b.ranges)
		parts.push_back({r.node, r.mesh, r.primitive, r.first_vertex, r.vertex_count,
				 r.first_index, r.index_count, r.has_normals, r.flat,
				 r.flat ? b.source.data() + r.source_at : nullptr});
	return parts;
}

// What the build says of the model it kept, and its materials.
void finish_materials(const Builder &b, tinygltf::Model &m, const struct gltf_options *o,
		      const GltfImages &images, struct mesh *out)
{
	std::string shown = gltf_ext::escape(b.name);
	log_info("%s: %u vertices, %u triangles", shown.c_str(), out->vertex_count,
		 out->index_count / 3);
	if (b.not_triangles)
		log_info("%s: %zu primitives of points or lines left out (only triangles show)",
			 shown.c_str(), b.not_triangles);
	gltf_read_materials(m, b.slots, b.name, b.any_uvs ? o->textures : 0, o->texture_memory,
			    images, out);
}

// The named nodes a hotspot may name (mesh.h, struct mesh_node): their
// world origins at the pose baked (a still's --time pose is in pose).
void keep_nodes(const tinygltf::Model &m, const Pose &pose, const std::string &shown,
		struct mesh *out)
{
	size_t left_out = 0;
	out->node_count = 0;
	for (size_t i = 0; i < m.nodes.size() && i < pose.worlds.size(); i++) {
		const std::string &name = m.nodes[i].name;
		if (name.empty())
			continue;
		if (out->node_count == MESH_NODES || !mesh_node_name_ok(name.c_str())) {
			left_out++;
			continue;
		}
		struct mesh_node *n = &out->nodes[out->node_count++];
		std::snprintf(n->name, sizeof(n->name), "%s", name.c_str());
		n->index = (uint32_t)i;
		for (int k = 0; k < 3; k++)
			n->origin[k] = pose.worlds[i].m[12 + k];
	}
	if (left_out)
		log_info("%s: %zu named nodes left out for hotspots (past the first %d, or not "
			 "printable UTF-8 shorter than %d bytes)",
			 shown.c_str(), left_out, MESH_NODES, MESH_NODE_NAME);
}

} // namespace

int gltf_build_mesh(const char *name, tinygltf::Model &m, const struct gltf_options *o,
		    const GltfImages &images, struct mesh *out)
{
	Builder b;
	Pose pose;
	GltfFit fit = {};
	std::unique_ptr<struct anim_play, void (*)(struct anim_play *)> play(nullptr,
									     anim_play_free);
	bool posed; // a clip posed it: fitted over that clip
	int scene, ret;
	b.name = name;
	b.want_colors = (o->textures & GLTF_TEXTURE_BASE_COLOR) != 0;
	b.textures = o->textures;
	b.normals_mode = o->normals;
	// The clips as the file has them, before a still's pose is written
	// into its nodes: the fit's and live playback's (a malformed one:
	// gltf_anim_load says so).
	std::unique_ptr<struct mesh_anim, void (*)(struct mesh_anim *)> clips(nullptr,
									      mesh_anim_free);
	std::string unused;
	struct mesh_anim *read = nullptr;
	if (o->play)
		*o->play = nullptr;
	if (o->pose && gltf_read_anim(m, &read, &unused))
		clips.reset(read);
	if (gltf_anim_load(name, m, o, &b.error, &posed) &&
	    gltf_ext::prepare(m, name, &pose, &b.error) &&
	    gltf_ext::choose_scene(m, o->scene, o->scene_setting, &scene, &b.error)) {
		std::vector<int> roots;
		if (scene >= 0)
			roots = m.scenes[(size_t)scene].nodes;
		else // no scene at all: every tree of nodes
			for (size_t i = 0; i < m.nodes.size(); i++)
				if (pose.parent[i] < 0)
					roots.push_back((int)i);
		add_scene(b, m, roots, "scenes[" + std::to_string(scene) + "]", pose);
	}
	std::vector<GltfPlayPart> parts = play_parts(b);
	if (b.error.empty()) // skins and morphs, by live playback's engine
		gltf_play_still(m, parts, b.indices, &b.positions, &b.normals, &b.error);
	if (b.error.empty() && clips && posed && !b.ranges.empty())
		play.reset(gltf_fit_clip(name, m, clips.release(), parts, b.indices, o, b.positions,
					 &fit));
	ret = b.error.empty() ? finish_mesh(b, m, out, fit) : -EINVAL;
	std::string shown = gltf_ext::escape(name);
	if (ret == -EINVAL && !b.error.empty())
		log_err("%s: %s", shown.c_str(), gltf_ext::escape(b.error).c_str());
	if (ret == 0)
		finish_materials(b, m, o, images, out);
	if (ret == 0)
		keep_nodes(m, pose, shown, out);
	if (ret == 0 && o->play)
		*o->play = play.release();
	gltf_keep_colors(out,
			 b.uniform_set && b.any_colors && b.colors.empty() ? b.uniform : nullptr);
	if (ret == 0)
		gltf_variants_colors(m, b.want_colors, shown, out);
	if (ret && o->anim) {
		mesh_anim_free(*o->anim);
		*o->anim = nullptr;
	}
	return ret;
}
