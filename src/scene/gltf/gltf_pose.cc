// The pose a model shows when nothing animates it: every node's world
// matrix, morph targets at their default weights, and skins bound to their
// joints. Computed once at load on the CPU, and never by recursion over
// the file's data: a hierarchy of any depth costs a loop, not the stack.
#include "scene/gltf/gltf_ext.h"
#include "util/log.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace gltf_ext
{

namespace
{

std::string node_path(size_t i)
{
	return "nodes[" + std::to_string(i) + "]";
}

void mat_mul(const Mat4 &a, const Mat4 &b, Mat4 *out)
{
	Mat4 r;
	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			double s = 0;
			for (int k = 0; k < 4; k++)
				s += a.m[k * 4 + row] * b.m[c * 4 + k];
			r.m[c * 4 + row] = s;
		}
	*out = r;
}

Mat4 node_matrix(const tinygltf::Node &n)
{
	Mat4 out;
	if (n.matrix.size() == 16) {
		for (int i = 0; i < 16; i++)
			out.m[i] = n.matrix[(size_t)i];
		return out;
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
			out.m[c * 4 + row] = r[c * 3 + row] * s[c];
		out.m[c * 4 + 3] = 0;
	}
	out.m[12] = t[0];
	out.m[13] = t[1];
	out.m[14] = t[2];
	out.m[15] = 1;
	return out;
}

bool find_parents(const tinygltf::Model &m, std::vector<int> *parent, std::string *err)
{
	parent->assign(m.nodes.size(), -1);
	for (size_t i = 0; i < m.nodes.size(); i++)
		for (size_t k = 0; k < m.nodes[i].children.size(); k++) {
			int c = m.nodes[i].children[k];
			std::string what = node_path(i) + ".children[" + std::to_string(k) + "]";
			if (c < 0 || (size_t)c >= m.nodes.size()) {
				*err = what + ": node " + std::to_string(c) + " does not exist";
				return false;
			}
			if ((*parent)[(size_t)c] >= 0) {
				*err = what + ": " + node_path((size_t)c) + " has two parents, " +
				       node_path((size_t)(*parent)[(size_t)c]) + " and " +
				       node_path(i) + " (expected a tree)";
				return false;
			}
			(*parent)[(size_t)c] = (int)i;
		}
	return true;
}

// The attribute `name` of a primitive as numbers (empty when absent).
bool attribute(const tinygltf::Model &m, const std::map<std::string, int> &attrs, const char *name,
	       const std::string &what, std::vector<double> *out, std::string *err)
{
	auto it = attrs.find(name);
	int n;
	out->clear();
	if (it == attrs.end())
		return true;
	if (!read_accessor(m, it->second, out, &n, err)) {
		*err = what + ".attributes." + name + " (" + *err + ")";
		return false;
	}
	return true;
}

bool morph_primitive(tinygltf::Model &m, tinygltf::Primitive &p, const std::vector<double> &w,
		     const std::string &what, std::string *err)
{
	for (const char *name : {"POSITION", "NORMAL"}) {
		std::vector<double> base, delta;
		if (!attribute(m, p.attributes, name, what, &base, err))
			return false;
		if (base.empty())
			continue;
		for (size_t t = 0; t < p.targets.size() && t < w.size(); t++) {
			std::string tw = what + ".targets[" + std::to_string(t) + "]";
			if (w[t] == 0.0)
				continue;
			if (!attribute(m, p.targets[t], name, tw, &delta, err))
				return false;
			if (delta.empty())
				continue;
			if (delta.size() != base.size()) {
				*err = tw + ".attributes." + name +
				       ": count differs from the primitive's";
				return false;
			}
			for (size_t i = 0; i < base.size(); i++)
				base[i] += w[t] * delta[i];
		}
		int type = m.accessors[(size_t)p.attributes[name]].type;
		if (type != TINYGLTF_TYPE_VEC3) {
			*err = what + ".attributes." + name + ": expected VEC3";
			return false;
		}
		p.attributes[name] = add_float_accessor(m, base, type, base.size() / 3);
	}
	return true;
}

struct Joints {
	std::vector<Mat4> matrices; // world(joint) x inverse bind matrix
};

bool joint_matrices(const tinygltf::Model &m, int skin, const std::vector<Mat4> &worlds,
		    const std::string &what, Joints *j, std::string *err)
{
	if (skin < 0 || (size_t)skin >= m.skins.size()) {
		*err = what + ".skin: skin " + std::to_string(skin) + " does not exist";
		return false;
	}
	const tinygltf::Skin &s = m.skins[(size_t)skin];
	std::string sw = "skins[" + std::to_string(skin) + "]";
	std::vector<double> ibm;
	int n = 16;
	if (s.inverseBindMatrices >= 0 && !read_accessor(m, s.inverseBindMatrices, &ibm, &n, err)) {
		*err = sw + ".inverseBindMatrices (" + *err + ")";
		return false;
	}
	if (s.inverseBindMatrices >= 0 && (n != 16 || ibm.size() < s.joints.size() * 16)) {
		*err = sw + ".inverseBindMatrices: expected a MAT4 per joint";
		return false;
	}
	for (size_t k = 0; k < s.joints.size(); k++) {
		int node = s.joints[k];
		if (node < 0 || (size_t)node >= worlds.size()) {
			*err = sw + ".joints[" + std::to_string(k) + "]: node " +
			       std::to_string(node) + " does not exist";
			return false;
		}
		Mat4 inv = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
		for (int c = 0; c < 16 && !ibm.empty(); c++)
			inv.m[c] = ibm[k * 16 + (size_t)c];
		Mat4 jm;
		mat_mul(worlds[(size_t)node], inv, &jm);
		j->matrices.push_back(jm);
	}
	return true;
}

// The blended matrix of vertex i over the JOINTS_n/WEIGHTS_n sets.
bool blend(const Joints &j, const std::vector<std::vector<double>> &joints,
	   const std::vector<std::vector<double>> &weights, size_t i, Mat4 *out)
{
	double total = 0;
	std::memset(out->m, 0, sizeof(out->m));
	for (size_t set = 0; set < joints.size(); set++)
		for (size_t k = 0; k < 4; k++) {
			double w = weights[set][i * 4 + k], jn = joints[set][i * 4 + k];
			if (w == 0.0)
				continue;
			if (!(jn >= 0 && jn < (double)j.matrices.size()))
				return false;
			for (int c = 0; c < 16; c++)
				out->m[c] += w * j.matrices[(size_t)jn].m[c];
			total += w;
		}
	if (total == 0.0) // unweighted: the vertex stays where it was bound
		*out = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
	else
		for (double &v : out->m)
			v /= total;
	return true;
}

bool skin_sets(const tinygltf::Model &m, const tinygltf::Primitive &p, const std::string &what,
	       size_t count, std::vector<std::vector<double>> *joints,
	       std::vector<std::vector<double>> *weights, std::string *err)
{
	for (const char *set : {"0", "1", "2"}) {
		std::vector<double> jv, wv;
		std::string jn = std::string("JOINTS_") + set, wn = std::string("WEIGHTS_") + set;
		if (!attribute(m, p.attributes, jn.c_str(), what, &jv, err) ||
		    !attribute(m, p.attributes, wn.c_str(), what, &wv, err))
			return false;
		if (jv.empty() && wv.empty())
			break;
		if (jv.size() != count * 4 || wv.size() != count * 4) {
			*err = what + ".attributes." + jn + ": expected " + jn + " and " + wn +
			       " as VEC4, one per vertex";
			return false;
		}
		joints->push_back(std::move(jv));
		weights->push_back(std::move(wv));
	}
	return true;
}

bool skin_primitive(tinygltf::Model &m, tinygltf::Primitive &p, const Joints &j,
		    const std::string &what, std::string *err)
{
	std::vector<double> pos, nrm;
	std::vector<std::vector<double>> joints, weights;
	if (!attribute(m, p.attributes, "POSITION", what, &pos, err) ||
	    !attribute(m, p.attributes, "NORMAL", what, &nrm, err))
		return false;
	size_t count = pos.size() / 3;
	if (pos.empty() || !skin_sets(m, p, what, count, &joints, &weights, err))
		return err->empty();
	if (joints.empty())
		return true; // not skinned: drawn at the skeleton's root
	for (size_t i = 0; i < count; i++) {
		Mat4 b;
		if (!blend(j, joints, weights, i, &b)) {
			*err = what + ".attributes.JOINTS_0: vertex " + std::to_string(i) +
			       " names a joint the skin does not have";
			return false;
		}
		double v[3] = {pos[i * 3], pos[i * 3 + 1], pos[i * 3 + 2]};
		for (int k = 0; k < 3; k++)
			pos[i * 3 + (size_t)k] =
			    b.m[k] * v[0] + b.m[4 + k] * v[1] + b.m[8 + k] * v[2] + b.m[12 + k];
		if (nrm.size() != pos.size())
			continue;
		// Bind poses are rigid in practice: the blended 3x3 turns the
		// normal, and the builder normalises it.
		double n[3] = {nrm[i * 3], nrm[i * 3 + 1], nrm[i * 3 + 2]};
		for (int k = 0; k < 3; k++)
			nrm[i * 3 + (size_t)k] =
			    b.m[k] * n[0] + b.m[4 + k] * n[1] + b.m[8 + k] * n[2];
	}
	p.attributes["POSITION"] = add_float_accessor(m, pos, TINYGLTF_TYPE_VEC3, count);
	if (nrm.size() == pos.size())
		p.attributes["NORMAL"] = add_float_accessor(m, nrm, TINYGLTF_TYPE_VEC3, count);
	return true;
}

} // namespace

bool node_worlds(const tinygltf::Model &m, std::vector<Mat4> *worlds, std::vector<int> *parent,
		 std::string *err)
{
	if (!find_parents(m, parent, err))
		return false;
	worlds->assign(m.nodes.size(), Mat4());
	std::vector<char> done(m.nodes.size(), 0);
	std::vector<size_t> stack;
	for (size_t i = 0; i < m.nodes.size(); i++)
		if ((*parent)[i] < 0)
			stack.push_back(i);
	while (!stack.empty()) {
		size_t i = stack.back();
		stack.pop_back();
		Mat4 local = node_matrix(m.nodes[i]);
		if ((*parent)[i] < 0)
			(*worlds)[i] = local;
		else
			mat_mul((*worlds)[(size_t)(*parent)[i]], local, &(*worlds)[i]);
		done[i] = 1;
		for (int c : m.nodes[i].children)
			stack.push_back((size_t)c);
	}
	// With one parent each, a node no root reaches lies on a cycle.
	for (size_t i = 0; i < m.nodes.size(); i++)
		if (!done[i]) {
			*err = node_path(i) + ": is its own ancestor (a cycle of children)";
			return false;
		}
	return true;
}

bool choose_scene(const tinygltf::Model &m, const char *want, const char *setting, int *scene,
		  std::string *err)
{
	*scene = m.scenes.empty() ? -1 : m.defaultScene >= 0 ? m.defaultScene : 0;
	if (want && *want) {
		char *end;
		long i = std::strtol(want, &end, 10);
		*scene = -2;
		for (size_t k = 0; k < m.scenes.size() && *scene == -2; k++)
			if (m.scenes[k].name == want || (!*end && i == (long)k))
				*scene = (int)k;
		if (*scene == -2) {
			std::string names;
			for (const tinygltf::Scene &s : m.scenes)
				if (!s.name.empty())
					names += (names.empty() ? ": \"" : ", \"") +
						 gltf_ext::escape(s.name) + "\"";
			*err = "scenes: no scene \"" + gltf_ext::escape(want) + "\"" +
			       (setting ? " (" + std::string(setting) + ")" : "") +
			       ", expected an index below " + std::to_string(m.scenes.size()) +
			       " or a scene's name" + names;
			return false;
		}
	}
	if (*scene >= (int)m.scenes.size()) {
		*err = "scene: " + std::to_string(*scene) + " does not exist, expected below " +
		       std::to_string(m.scenes.size());
		return false;
	}
	return true;
}

bool apply_morphs(tinygltf::Model &m, std::string *err)
{
	// A node's own weights override its mesh's defaults; the first node
	// that has them decides for a mesh shared by several.
	std::vector<std::vector<double>> weights(m.meshes.size());
	for (size_t i = 0; i < m.meshes.size(); i++)
		weights[i] = m.meshes[i].weights;
	for (const tinygltf::Node &n : m.nodes)
		if (n.mesh >= 0 && (size_t)n.mesh < m.meshes.size() && !n.weights.empty())
			weights[(size_t)n.mesh] = n.weights;
	for (size_t mi = 0; mi < m.meshes.size(); mi++) {
		bool any = false;
		for (double w : weights[mi])
			any |= w != 0.0;
		for (size_t pi = 0; any && pi < m.meshes[mi].primitives.size(); pi++) {
			std::string what = "meshes[" + std::to_string(mi) + "].primitives[" +
					   std::to_string(pi) + "]";
			if (!morph_primitive(m, m.meshes[mi].primitives[pi], weights[mi], what,
					     err))
				return false;
		}
	}
	return true;
}

bool apply_skins(tinygltf::Model &m, const std::vector<Mat4> &worlds, std::vector<int> *mesh_source,
		 std::string *err)
{
	mesh_source->clear();
	for (size_t i = 0; i < m.meshes.size(); i++)
		mesh_source->push_back((int)i);
	for (size_t i = 0; i < m.nodes.size(); i++) {
		if (m.nodes[i].skin < 0 || m.nodes[i].mesh < 0 ||
		    (size_t)m.nodes[i].mesh >= m.meshes.size())
			continue;
		Joints j;
		if (!joint_matrices(m, m.nodes[i].skin, worlds, node_path(i), &j, err))
			return false;
		// Each skinned node gets its own copy of the mesh: another node
		// may show the same mesh with another skin, or none.
		size_t mi = (size_t)m.nodes[i].mesh;
		tinygltf::Mesh copy = m.meshes[mi];
		for (size_t pi = 0; pi < copy.primitives.size(); pi++) {
			std::string what = "meshes[" + std::to_string(mi) + "].primitives[" +
					   std::to_string(pi) + "]";
			if (!skin_primitive(m, copy.primitives[pi], j, what, err))
				return false;
		}
		m.meshes.push_back(std::move(copy));
		mesh_source->push_back((int)mi);
		m.nodes[i].mesh = (int)m.meshes.size() - 1;
	}
	return true;
}

// The passes in order: here, beside the last three, so that gltf_ext.cc
// (which they call) calls nothing back.
bool prepare(tinygltf::Model &m, const char *name, Pose *pose, std::string *err)
{
	std::string unused = unsupported(m.extensionsUsed);
	if (!unused.empty() && unsupported(m.extensionsRequired).empty())
		log_info("%s: ignoring extensions it uses but does not need: %s",
			 escape(name).c_str(), escape(unused).c_str());
	if (!decode_meshopt(m, err) || !decode_draco(m, err) || !make_dense(m, err) ||
	    !node_worlds(m, &pose->worlds, &pose->parent, err) || !apply_morphs(m, err))
		return false;
	return apply_skins(m, pose->worlds, &pose->mesh_source, err);
}

} // namespace gltf_ext
