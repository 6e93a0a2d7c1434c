// A file's animations into the plain struct mesh_anim (scene/anim.h): the
// node hierarchy with each node's rest transform and morph weights, and
// every clip's samplers and channels, each checked against the spec's
// shapes so that playback trusts them.
#include "scene/gltf/gltf_anim.h"
#include "scene/gltf/gltf_ext.h"
#include "util/log.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace
{

using gltf_ext::read_accessor;

std::string anim_path(size_t a)
{
	return "animations[" + std::to_string(a) + "]";
}

// A node's morph target count: its mesh's first primitive's targets.
size_t target_count(const tinygltf::Model &m, const tinygltf::Node &n)
{
	if (n.mesh < 0 || (size_t)n.mesh >= m.meshes.size() ||
	    m.meshes[(size_t)n.mesh].primitives.empty())
		return 0;
	return m.meshes[(size_t)n.mesh].primitives[0].targets.size();
}

void rest_trs(const tinygltf::Node &n, struct anim_node *out)
{
	struct anim_trs *r = &out->rest;
	r->t[0] = r->t[1] = r->t[2] = 0;
	r->r[0] = r->r[1] = r->r[2] = 0;
	r->r[3] = 1;
	r->s[0] = r->s[1] = r->s[2] = 1;
	for (size_t i = 0; i < 3 && n.translation.size() == 3; i++)
		r->t[i] = (float)n.translation[i];
	for (size_t i = 0; i < 4 && n.rotation.size() == 4; i++)
		r->r[i] = (float)n.rotation[i];
	for (size_t i = 0; i < 3 && n.scale.size() == 3; i++)
		r->s[i] = (float)n.scale[i];
	out->has_matrix = n.matrix.size() == 16;
	for (size_t i = 0; out->has_matrix && i < 16; i++)
		out->matrix[i] = (float)n.matrix[i];
}

bool read_nodes(const tinygltf::Model &m, struct mesh_anim *a, std::string *err)
{
	size_t n = m.nodes.size();
	a->node_count = n;
	a->nodes = (struct anim_node *)std::calloc(n ? n : 1, sizeof(*a->nodes));
	a->order = (int *)std::calloc(n ? n : 1, sizeof(*a->order));
	if (!a->nodes || !a->order)
		throw std::bad_alloc();
	for (size_t i = 0; i < n; i++)
		a->nodes[i].parent = -1;
	for (size_t i = 0; i < n; i++)
		for (int c : m.nodes[i].children) {
			if (c < 0 || (size_t)c >= n || a->nodes[c].parent >= 0) {
				*err = "nodes[" + std::to_string(i) + "].children: node " +
				       std::to_string(c) + " missing or with two parents";
				return false;
			}
			a->nodes[c].parent = (int)i;
		}
	if (!anim_order(a->nodes, n, a->order)) {
		*err = "nodes: a cycle of children";
		return false;
	}
	for (size_t i = 0; i < n; i++) {
		rest_trs(m.nodes[i], &a->nodes[i]);
		a->nodes[i].weight_offset = a->weight_total;
		a->nodes[i].weight_count = target_count(m, m.nodes[i]);
		a->weight_total += a->nodes[i].weight_count;
	}
	a->rest_weights =
	    (float *)std::calloc(a->weight_total ? a->weight_total : 1, sizeof(float));
	if (!a->rest_weights)
		throw std::bad_alloc();
	for (size_t i = 0; i < n; i++) {
		const tinygltf::Node &node = m.nodes[i];
		const std::vector<double> &w =
		    !node.weights.empty() || node.mesh < 0 || (size_t)node.mesh >= m.meshes.size()
			? node.weights
			: m.meshes[(size_t)node.mesh].weights;
		for (size_t k = 0; k < w.size() && k < a->nodes[i].weight_count; k++)
			a->rest_weights[a->nodes[i].weight_offset + k] = (float)w[k];
	}
	return true;
}

float *floats(const std::vector<double> &v)
{
	float *f = (float *)std::malloc((v.empty() ? 1 : v.size()) * sizeof(float));
	if (!f)
		throw std::bad_alloc();
	for (size_t i = 0; i < v.size(); i++)
		f[i] = (float)v[i];
	return f;
}

bool read_sampler(const tinygltf::Model &m, const tinygltf::AnimationSampler &s,
		  const std::string &what, struct anim_sampler *out, std::string *err)
{
	std::vector<double> in, values;
	int comps = 0, out_comps = 0;
	if (s.interpolation == "STEP")
		out->interp = ANIM_STEP;
	else if (s.interpolation == "CUBICSPLINE")
		out->interp = ANIM_CUBICSPLINE;
	else if (s.interpolation == "LINEAR" || s.interpolation.empty())
		out->interp = ANIM_LINEAR;
	else {
		*err = what + ".interpolation: \"" + gltf_ext::escape(s.interpolation) +
		       "\", expected LINEAR, STEP or CUBICSPLINE";
		return false;
	}
	if (!read_accessor(m, s.input, &in, &comps, err)) {
		*err = what + ".input (" + *err + ")";
		return false;
	}
	if (!read_accessor(m, s.output, &values, &out_comps, err)) {
		*err = what + ".output (" + *err + ")";
		return false;
	}
	if (comps != 1) {
		*err = what + ".input: expected SCALAR times";
		return false;
	}
	out->count = in.size();
	out->input = floats(in);
	out->output = floats(values);
	// The width is the output's floats a key: checked against the
	// channel's path by the caller.
	size_t per = in.size() * (out->interp == ANIM_CUBICSPLINE ? 3 : 1);
	if (per == 0 || values.size() % per != 0) {
		*err = what + ".output: " + std::to_string(values.size()) +
		       " values, expected a whole number per key (" + std::to_string(in.size()) +
		       " keys" + (out->interp == ANIM_CUBICSPLINE ? ", three each" : "") + ")";
		return false;
	}
	out->width = (int)(values.size() / per);
	if (const char *bad = anim_sampler_check(out)) {
		*err = what + ": " + bad;
		return false;
	}
	return true;
}

bool read_channel(const tinygltf::Model &m, const struct mesh_anim *a,
		  const tinygltf::Animation &an, size_t k, const struct anim_clip *clip,
		  struct anim_channel *out, std::string *err)
{
	const tinygltf::AnimationChannel &c = an.channels[k];
	std::string what = ".channels[" + std::to_string(k) + "]";
	const std::string &p = c.target_path;
	out->node = c.target_node;
	out->sampler = c.sampler;
	out->path = p == "translation" ? ANIM_TRANSLATION
		    : p == "rotation"  ? ANIM_ROTATION
		    : p == "scale"     ? ANIM_SCALE
				       : ANIM_WEIGHTS;
	if (p != "translation" && p != "rotation" && p != "scale" && p != "weights") {
		*err = what + ".target.path: \"" + gltf_ext::escape(p) +
		       "\", expected translation, rotation, scale or weights";
		return false;
	}
	if (c.target_node < 0 || (size_t)c.target_node >= m.nodes.size()) {
		*err = what + ".target.node: node " + std::to_string(c.target_node) +
		       " does not exist";
		return false;
	}
	if (c.sampler < 0 || (size_t)c.sampler >= clip->sampler_count) {
		*err = what + ".sampler: sampler " + std::to_string(c.sampler) + " does not exist";
		return false;
	}
	size_t want = out->path == ANIM_ROTATION  ? 4
		      : out->path == ANIM_WEIGHTS ? a->nodes[c.target_node].weight_count
						  : 3;
	size_t width = (size_t)clip->samplers[c.sampler].width;
	if (width != want) {
		*err = what + ": " + std::to_string(width) + " values a key for " + p +
		       ", expected " + std::to_string(want);
		return false;
	}
	if (a->nodes[c.target_node].has_matrix && out->path != ANIM_WEIGHTS) {
		*err = what + ".target.node: node " + std::to_string(c.target_node) +
		       " has a matrix, expected translation, rotation and scale to animate";
		return false;
	}
	return true;
}

bool read_clip(const tinygltf::Model &m, const struct mesh_anim *a, size_t i,
	       struct anim_clip *clip, std::string *err)
{
	const tinygltf::Animation &an = m.animations[i];
	if (!an.name.empty() && !(clip->name = strdup(an.name.c_str())))
		throw std::bad_alloc();
	clip->samplers =
	    (struct anim_sampler *)std::calloc(an.samplers.size() + 1, sizeof(*clip->samplers));
	clip->channels =
	    (struct anim_channel *)std::calloc(an.channels.size() + 1, sizeof(*clip->channels));
	if (!clip->samplers || !clip->channels)
		throw std::bad_alloc();
	for (size_t s = 0; s < an.samplers.size(); s++) {
		clip->sampler_count = s + 1; // freed with the clip, whole or not
		if (!read_sampler(m, an.samplers[s],
				  anim_path(i) + ".samplers[" + std::to_string(s) + "]",
				  &clip->samplers[s], err))
			return false;
		const struct anim_sampler &sm = clip->samplers[s];
		clip->duration = std::fmax(clip->duration, (double)sm.input[sm.count - 1]);
	}
	for (size_t k = 0; k < an.channels.size(); k++) {
		if (an.channels[k].target_node < 0)
			continue; // no node: an extension's target, which we leave out
		if (!read_channel(m, a, an, k, clip, &clip->channels[clip->channel_count], err)) {
			*err = anim_path(i) + *err;
			return false;
		}
		clip->channel_count++;
	}
	return true;
}

} // namespace

bool gltf_read_anim(const tinygltf::Model &m, struct mesh_anim **out, std::string *err)
{
	*out = nullptr;
	if (m.animations.empty())
		return true;
	struct mesh_anim *a = (struct mesh_anim *)std::calloc(1, sizeof(*a));
	bool ok = a != nullptr;
	try {
		if (!ok)
			throw std::bad_alloc();
		ok = read_nodes(m, a, err);
		if (ok) {
			a->clips =
			    (struct anim_clip *)std::calloc(m.animations.size(), sizeof(*a->clips));
			if (!a->clips)
				throw std::bad_alloc();
		}
		for (size_t i = 0; ok && i < m.animations.size(); i++) {
			a->clip_count = i + 1;
			ok = read_clip(m, a, i, &a->clips[i], err);
		}
	} catch (const std::bad_alloc &) {
		*err = "animations: out of memory";
		ok = false;
	}
	if (!ok) {
		mesh_anim_free(a);
		return false;
	}
	*out = a;
	return true;
}

bool gltf_read_rig(const tinygltf::Model &m, struct mesh_anim **out, std::string *err)
{
	struct mesh_anim *a = (struct mesh_anim *)std::calloc(1, sizeof(*a));
	*out = nullptr;
	if (!a)
		throw std::bad_alloc();
	try {
		if (!read_nodes(m, a, err)) {
			mesh_anim_free(a);
			return false;
		}
	} catch (const std::bad_alloc &) {
		mesh_anim_free(a);
		throw;
	}
	*out = a;
	return true;
}

namespace
{

// The clip's pose at o->time, as its clock plays it.
void apply_clip(const struct mesh_anim *a, const struct anim_clip *clip,
		const struct gltf_options *o, struct anim_pose *p)
{
	struct anim_clock c;
	anim_clock_init(&c, clip->duration, (enum anim_loop)o->loop, o->speed);
	anim_clock_seek(&c, o->time);
	anim_pose_apply(a, clip, anim_clock_time(&c), p);
}

} // namespace

bool gltf_anim_clips(const struct mesh_anim *a, const struct gltf_options *o, int *clip,
		     std::string *err)
{
	const char *want = o->animation ? o->animation : "auto";
	*clip = anim_clip_find(a, want);
	if (*clip != -2)
		return true;
	std::string names;
	for (size_t k = 0; k < a->clip_count; k++)
		if (a->clips[k].name)
			names += (names.empty() ? ": \"" : ", \"") +
				 gltf_ext::escape(a->clips[k].name) + "\"";
	*err = "animations: no animation \"" + gltf_ext::escape(want) + "\"" +
	       (o->animation_setting ? " (" + std::string(o->animation_setting) + ")" : "") +
	       ", expected auto, off, all, an index below " + std::to_string(a->clip_count) +
	       " or an animation's name" + names;
	if (o->animation_optional)
		*clip = -1; // the rest pose; err says why
	return o->animation_optional;
}

void gltf_anim_pose(const struct mesh_anim *a, const struct gltf_options *o, int clip,
		    struct anim_pose *p)
{
	bool all = o->animation && !std::strcmp(o->animation, "all");
	anim_pose_rest(a, p);
	for (size_t k = 0; k < a->clip_count; k++)
		if (all || (int)k == clip)
			apply_clip(a, &a->clips[k], o, p);
}

bool gltf_pose_nodes(tinygltf::Model &m, const struct mesh_anim *a, const struct gltf_options *o,
		     std::string *err, bool *posed)
{
	int clip;
	*posed = false;
	if (!o->pose || !a)
		return true;
	if (!gltf_anim_clips(a, o, &clip, err))
		return false;
	bool all = o->animation && !std::strcmp(o->animation, "all");
	if (clip < 0 && !all)
		return true; // off: the rest pose
	struct anim_pose *p = anim_pose_new(a);
	if (!p)
		throw std::bad_alloc();
	gltf_anim_pose(a, o, clip, p);
	*posed = true;
	// Written back into the file's nodes, so that the passes that pose a
	// still (node worlds, morphs, skins) pose it at this time.
	for (size_t i = 0; i < a->node_count; i++) {
		tinygltf::Node &n = m.nodes[i];
		const struct anim_trs &l = p->local[i];
		if (!a->nodes[i].has_matrix) {
			n.translation.assign(l.t, l.t + 3);
			n.rotation.assign(l.r, l.r + 4);
			n.scale.assign(l.s, l.s + 3);
		}
		const float *w = p->weights + a->nodes[i].weight_offset;
		if (a->nodes[i].weight_count)
			n.weights.assign(w, w + a->nodes[i].weight_count);
	}
	anim_pose_free(p);
	return true;
}

bool gltf_anim_load(const char *name, tinygltf::Model &m, const struct gltf_options *o,
		    std::string *err, bool *posed)
{
	struct mesh_anim *a = nullptr;
	*posed = false;
	if (!o->anim && !o->pose)
		return true;
	if (!gltf_read_anim(m, &a, err)) {
		log_warn("%s: %s; the model shows still", gltf_ext::escape(name).c_str(),
			 gltf_ext::escape(*err).c_str());
		err->clear();
	}
	bool ok = gltf_pose_nodes(m, a, o, err, posed);
	if (ok && !err->empty()) { // a clip the file lacks, optional
		log_warn("%s: %s; it shows its rest pose", gltf_ext::escape(name).c_str(),
			 gltf_ext::escape(*err).c_str());
		err->clear();
	}
	if (o->anim && ok)
		*o->anim = a;
	else
		mesh_anim_free(a);
	return ok;
}
