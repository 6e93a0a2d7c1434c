// What live playback keeps beside the baked mesh, read from the file's own
// primitives: each part's positions and normals before any pose, its
// joint sets (JOINTS_0 and WEIGHTS_0, JOINTS_1 and WEIGHTS_1...), its morph targets' deltas, and
// each skin's joints and inverse bind matrices.
#include "scene/gltf/gltf_play.h"
#include "scene/gltf/gltf_anim.h"
#include "scene/gltf/gltf_ext.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <memory>
#include <new>

namespace
{

struct PlayFree {
	void operator()(struct anim_play *p) const
	{
		anim_play_free(p);
	}
};
using Play = std::unique_ptr<struct anim_play, PlayFree>;

template <typename T> T *alloc(size_t n)
{
	T *p = (T *)std::calloc(n ? n : 1, sizeof(T));
	if (!p)
		throw std::bad_alloc();
	return p;
}

// Attribute `name` of attrs (empty when absent).
bool attribute(const tinygltf::Model &m, const std::map<std::string, int> &attrs, const char *name,
	       std::vector<double> *out, std::string *err)
{
	int n;
	auto it = attrs.find(name);
	out->clear();
	if (it == attrs.end())
		return true;
	if (gltf_ext::read_accessor(m, it->second, out, &n, err))
		return true;
	*err = std::string(name) + " (" + *err + ")";
	return false;
}

void put(const std::vector<double> &v, size_t at, float *out)
{
	for (size_t i = 0; i < v.size(); i++)
		out[at + i] = (float)v[i];
}

// A flat part's vertices are copies of the file's (gltf_flat.h): v (width
// values a file vertex) gathered to one value set per copy. Left as read
// when the part is not split or v is absent; false where a copy's vertex
// is past v (the builder checked the indices against POSITION).
bool gather(std::vector<double> *v, size_t width, const GltfPlayPart &g, std::string *err)
{
	if (!g.source || v->empty())
		return true;
	std::vector<double> out((size_t)g.vertex_count * width);
	for (size_t i = 0; i < g.vertex_count; i++) {
		if ((size_t)(g.source[i] + 1) * width > v->size()) {
			*err = "an attribute's count differs from POSITION";
			return false;
		}
		std::copy(v->begin() + (std::ptrdiff_t)(g.source[i] * width),
			  v->begin() + (std::ptrdiff_t)((g.source[i] + 1) * width),
			  out.begin() + (std::ptrdiff_t)(i * width));
	}
	v->swap(out);
	return true;
}

// The slot in p->skins of the file's skin, read the first time it is met.
bool skin_slot(const tinygltf::Model &m, int skin, struct anim_play *p, std::vector<int> *slots,
	       int *slot, std::string *err)
{
	if ((*slots)[(size_t)skin] >= 0) {
		*slot = (*slots)[(size_t)skin];
		return true;
	}
	const tinygltf::Skin &s = m.skins[(size_t)skin];
	struct anim_play_skin *out = &p->skins[p->skin_count];
	std::vector<double> ibm;
	int n = 16;
	std::string sw = "skins[" + std::to_string(skin) + "]";
	if (s.inverseBindMatrices >= 0 &&
	    (!gltf_ext::read_accessor(m, s.inverseBindMatrices, &ibm, &n, err) || n != 16 ||
	     ibm.size() < s.joints.size() * 16)) {
		*err = sw + ".inverseBindMatrices: expected a MAT4 per joint";
		return false;
	}
	out->joint_count = (uint32_t)s.joints.size();
	out->joints = alloc<int>(s.joints.size());
	out->inverse_bind = alloc<float>(s.joints.size() * 16);
	for (size_t k = 0; k < s.joints.size(); k++) {
		if (s.joints[k] < 0 || (size_t)s.joints[k] >= m.nodes.size()) {
			*err = sw + ".joints[" + std::to_string(k) + "]: node " +
			       std::to_string(s.joints[k]) + " does not exist";
			return false;
		}
		out->joints[k] = s.joints[k];
		for (size_t c = 0; c < 16; c++)
			out->inverse_bind[k * 16 + c] =
			    ibm.empty() ? (c % 5 == 0 ? 1.0f : 0.0f) : (float)ibm[k * 16 + c];
	}
	*slot = (*slots)[(size_t)skin] = (int)p->skin_count++;
	return true;
}

// The joint sets a primitive has, as the bake reads them (JOINTS_0 to
// JOINTS_2, up to the first it lacks).
uint32_t joint_sets(const tinygltf::Primitive &pr)
{
	uint32_t n = 0;
	while (n < 3 && pr.attributes.count("JOINTS_" + std::to_string(n)))
		n++;
	return n;
}

// Each joint set of a skinned part, JOINTS_n and WEIGHTS_n, into its
// place of the vertex's p->influences (those past its sets keep weight 0).
// A weighed joint the skin lacks is refused, as the bake always did.
bool skin_attributes(const tinygltf::Model &m, const tinygltf::Primitive &pr, const GltfPlayPart &g,
		     uint32_t joints, struct anim_play *p, std::string *err)
{
	const size_t stride = p->influences;
	if (!p->joints) {
		p->joints = alloc<uint16_t>((size_t)p->vertex_count * stride);
		p->weights = alloc<float>((size_t)p->vertex_count * stride);
	}
	for (uint32_t set = 0; set < joint_sets(pr); set++) {
		std::vector<double> j, w;
		std::string jn = "JOINTS_" + std::to_string(set),
			    wn = "WEIGHTS_" + std::to_string(set);
		if (!attribute(m, pr.attributes, jn.c_str(), &j, err) ||
		    !attribute(m, pr.attributes, wn.c_str(), &w, err) || !gather(&j, 4, g, err) ||
		    !gather(&w, 4, g, err))
			return false;
		if (j.size() != (size_t)g.vertex_count * 4 || w.size() != j.size()) {
			*err = jn + ": expected one VEC4 a vertex, with " + wn;
			return false;
		}
		for (size_t i = 0; i < j.size(); i++) {
			size_t at = (g.first_vertex + i / 4) * stride + set * 4 + i % 4;
			if (w[i] != 0.0 && !(j[i] >= 0 && j[i] < joints)) {
				*err = jn + ": vertex " + std::to_string(i / 4) + " names joint " +
				       std::to_string((long long)j[i]) +
				       ", expected one of the skin's " + std::to_string(joints);
				return false;
			}
			p->joints[at] = j[i] >= 0 && j[i] < 65535 ? (uint16_t)j[i] : 65535;
			p->weights[at] = (float)w[i];
		}
	}
	return true;
}

// A part without the file's normals generates them each pose: its targets'
// normal deltas are not read (glTF: they apply to given normals).
bool targets(const tinygltf::Model &m, const tinygltf::Primitive &pr, const GltfPlayPart &g,
	     struct anim_play_part *part, std::string *err)
{
	size_t count = (size_t)part->vertex_count * 3;
	part->target_count = (uint32_t)pr.targets.size();
	if (pr.targets.empty())
		return true;
	part->target_positions = alloc<float>(count * pr.targets.size());
	for (size_t t = 0; t < pr.targets.size(); t++) {
		std::vector<double> dp, dn;
		if (!attribute(m, pr.targets[t], "POSITION", &dp, err) ||
		    (g.has_normals && !attribute(m, pr.targets[t], "NORMAL", &dn, err)) ||
		    !gather(&dp, 3, g, err))
			return false;
		if ((!dp.empty() && dp.size() != count) || (!dn.empty() && dn.size() != count)) {
			*err = "targets[" + std::to_string(t) + "]: count differs from POSITION";
			return false;
		}
		put(dp, t * count, part->target_positions);
		if (!dn.empty() && !part->target_normals)
			part->target_normals = alloc<float>(count * pr.targets.size());
		if (!dn.empty())
			put(dn, t * count, part->target_normals);
	}
	return true;
}

bool fill_part(const tinygltf::Model &m, const GltfPlayPart &g,
	       const std::vector<uint32_t> &indices, struct anim_play *p, std::vector<int> *slots,
	       std::string *err)
{
	const tinygltf::Primitive &pr = m.meshes[(size_t)g.mesh].primitives[(size_t)g.primitive];
	struct anim_play_part *part = &p->parts[p->part_count++];
	std::vector<double> pos, nrm;
	part->node = g.node;
	part->skin = -1;
	int skin = m.nodes[(size_t)g.node].skin;
	// A skin the primitive does not use: drawn at the skeleton's root.
	part->at_root = skin >= 0 && !pr.attributes.count("JOINTS_0");
	part->first_vertex = g.first_vertex;
	part->vertex_count = g.vertex_count;
	part->has_normals = g.has_normals;
	part->flat = g.flat;
	if (!attribute(m, pr.attributes, "POSITION", &pos, err) ||
	    !attribute(m, pr.attributes, "NORMAL", &nrm, err) || !gather(&pos, 3, g, err))
		return false;
	if (pos.size() != (size_t)g.vertex_count * 3) {
		*err = "POSITION: count differs from the mesh built";
		return false;
	}
	put(pos, (size_t)g.first_vertex * 3, p->positions);
	if (g.has_normals && nrm.size() == pos.size())
		put(nrm, (size_t)g.first_vertex * 3, p->normals);
	if (!g.has_normals) {
		part->index_count = g.index_count;
		part->indices = alloc<uint32_t>(g.index_count);
		std::memcpy(part->indices, indices.data() + g.first_index,
			    (size_t)g.index_count * sizeof(uint32_t));
	}
	if (skin >= 0 && !part->at_root && (size_t)skin >= m.skins.size()) {
		*err = "nodes[" + std::to_string(g.node) + "].skin: skin " + std::to_string(skin) +
		       " does not exist, expected below " + std::to_string(m.skins.size());
		return false;
	}
	if (skin >= 0 && !part->at_root &&
	    (!skin_slot(m, skin, p, slots, &part->skin, err) ||
	     !skin_attributes(m, pr, g, p->skins[part->skin].joint_count, p, err)))
		return false;
	return targets(m, pr, g, part, err);
}

// p (its anim read) filled for the builder's parts from m, decoded and
// dense: each part's own vertices, skins and targets, and the scratch.
bool fill(const tinygltf::Model &m, const std::vector<GltfPlayPart> &parts,
	  const std::vector<uint32_t> &indices, const double center[3], double scale,
	  struct anim_play *p, std::string *err)
{
	for (const GltfPlayPart &g : parts)
		p->vertex_count = std::max(p->vertex_count, g.first_vertex + g.vertex_count);
	std::memcpy(p->center, center, sizeof(p->center));
	p->scale = scale;
	p->positions = alloc<float>((size_t)p->vertex_count * 3);
	p->normals = alloc<float>((size_t)p->vertex_count * 3);
	p->parts = alloc<struct anim_play_part>(parts.size());
	p->skins = alloc<struct anim_play_skin>(m.skins.size());
	std::vector<int> slots(m.skins.size(), -1);
	// Four joints a vertex unless a part has more sets: a model without
	// JOINTS_1 keeps the arrays (and cost) it always had.
	p->influences = 4;
	for (const GltfPlayPart &g : parts)
		p->influences = std::max(
		    p->influences,
		    4 * joint_sets(m.meshes[(size_t)g.mesh].primitives[(size_t)g.primitive]));
	for (const GltfPlayPart &g : parts)
		if (!fill_part(m, g, indices, p, &slots, err)) {
			*err = "meshes[" + std::to_string(g.mesh) + "].primitives[" +
			       std::to_string(g.primitive) + "]: " + *err;
			return false;
		}
	if (anim_play_finish(p))
		throw std::bad_alloc();
	return true;
}

// Whether a part has targets and its node's weights (else its mesh's)
// weigh one of them.
bool weighed(const tinygltf::Model &m, const GltfPlayPart &g)
{
	const tinygltf::Node &n = m.nodes[(size_t)g.node];
	const std::vector<double> &w =
	    n.weights.empty() ? m.meshes[(size_t)g.mesh].weights : n.weights;
	bool any = false;
	for (double v : w)
		any |= v != 0.0;
	return any && !m.meshes[(size_t)g.mesh].primitives[(size_t)g.primitive].targets.empty();
}

// Whether the still takes a part's vertices from the engine: a skinned
// part, or one whose targets the pose weighs; any other stays as the
// builder placed it (its node's world in doubles).
bool moved(const struct anim_play *p, const struct anim_play_part &part)
{
	const struct anim_node &n = p->anim->nodes[part.node];
	bool weighed = false;
	for (size_t t = 0; t < part.target_count && t < n.weight_count; t++)
		weighed |= p->anim->rest_weights[n.weight_offset + t] != 0.0f;
	return part.skin >= 0 || weighed;
}

} // namespace

bool gltf_play_build(const tinygltf::Model &m, struct mesh_anim *anim,
		     const std::vector<GltfPlayPart> &parts, const std::vector<uint32_t> &indices,
		     const double center[3], double scale, struct anim_play **out, std::string *err)
{
	Play p(nullptr);
	*out = nullptr;
	try {
		p.reset(alloc<struct anim_play>(1));
	} catch (const std::bad_alloc &) {
		mesh_anim_free(anim);
		throw;
	}
	p->anim = anim;
	if (!fill(m, parts, indices, center, scale, p.get(), err))
		return false;
	*out = p.release();
	return true;
}

bool gltf_play_still(const tinygltf::Model &m, const std::vector<GltfPlayPart> &parts,
		     const std::vector<uint32_t> &indices, std::vector<double> *positions,
		     std::vector<float> *normals, std::string *err)
{
	static const double origin[3] = {0, 0, 0};
	bool any = false;
	for (const GltfPlayPart &g : parts)
		any |= m.nodes[(size_t)g.node].skin >= 0 || weighed(m, g);
	if (!any)
		return true; // nothing the engine would move: no cost
	Play p(alloc<struct anim_play>(1));
	if (!gltf_read_rig(m, &p->anim, err) || !fill(m, parts, indices, origin, 1, p.get(), err))
		return false;
	std::unique_ptr<struct anim_pose, void (*)(struct anim_pose *)> pose(anim_pose_new(p->anim),
									     anim_pose_free);
	std::vector<float> pos((size_t)p->vertex_count * 3), nrm(pos.size());
	if (!pose)
		throw std::bad_alloc();
	anim_play_pose(p.get(), pose.get(), pos.data(), nrm.data());
	for (uint32_t i = 0; i < p->part_count; i++) {
		const struct anim_play_part &part = p->parts[i];
		size_t at = (size_t)part.first_vertex * 3, n = (size_t)part.vertex_count * 3;
		if (!moved(p.get(), part))
			continue;
		std::copy(pos.begin() + (std::ptrdiff_t)at, pos.begin() + (std::ptrdiff_t)(at + n),
			  positions->begin() + (std::ptrdiff_t)at);
		if (part.has_normals)
			std::copy(nrm.begin() + (std::ptrdiff_t)at,
				  nrm.begin() + (std::ptrdiff_t)(at + n),
				  normals->begin() + (std::ptrdiff_t)at);
	}
	return true;
}
