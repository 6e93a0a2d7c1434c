// The passes before the mesh builder: the file's compressed and sparse
// data made plain, and every node's world matrix at the pose shown,
// never by recursion over the file's data (a hierarchy of any depth costs
// a loop, not the stack). Skins and morph targets are posed after the
// builder by live playback's engine (gltf_play_still).
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

// The passes in order: here, beside the last three, so that gltf_ext.cc
// (which they call) calls nothing back.
bool prepare(tinygltf::Model &m, const char *name, Pose *pose, std::string *err)
{
	std::string unused = unsupported(m.extensionsUsed);
	if (!unused.empty() && unsupported(m.extensionsRequired).empty())
		log_info("%s: ignoring extensions it uses but does not need: %s",
			 escape(name).c_str(), escape(unused).c_str());
	return decode_meshopt(m, err) && decode_draco(m, err) && make_dense(m, err) &&
	       node_worlds(m, &pose->worlds, &pose->parent, err);
}

} // namespace gltf_ext
