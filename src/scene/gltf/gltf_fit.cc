// A posed still fitted for its whole clip: the centre of the model's box
// at the pose asked for and at the clip's key times, and its farthest
// vertex from it over them, so that every still of one clip shares one
// framing. Each sample is posed by live playback's engine (anim_play_pose,
// built once) over the positions alone: the mesh is built once, not
// once a sample.
#include "scene/gltf/gltf_fit.h"
#include "scene/gltf/gltf_anim.h"
#include "scene/gltf/gltf_ext.h"
#include "util/log.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace
{

// Clip times that show the clip's extent: its key times (where LINEAR and
// STEP reach their extremes; at most 32, else 32 spread over it), and 16
// steps over the whole: a slerp sweeps an arc between its keys.
std::vector<double> sample_times(const struct mesh_anim *a, int clip, bool all)
{
	std::vector<double> t;
	double longest = 0;
	for (size_t k = 0; k < a->clip_count; k++) {
		if (!all && (int)k != clip)
			continue;
		const struct anim_clip &c = a->clips[k];
		longest = std::fmax(longest, c.duration);
		for (size_t s = 0; s < c.sampler_count; s++)
			t.insert(t.end(), c.samplers[s].input,
				 c.samplers[s].input + c.samplers[s].count);
	}
	std::sort(t.begin(), t.end());
	t.erase(std::unique(t.begin(), t.end()), t.end());
	if (t.size() > 32) {
		t.clear();
		for (int i = 0; i < 32; i++)
			t.push_back(longest * i / 31);
	}
	for (int i = 1; i < 16; i++)
		t.push_back(longest * i / 16);
	return t;
}

struct PoseFree {
	void operator()(struct anim_pose *p) const
	{
		anim_pose_free(p);
	}
};

// The engine at the fit's samples, and room for one pose's vertices.
struct Poser {
	struct anim_play *play;
	std::unique_ptr<struct anim_pose, PoseFree> pose;
	std::vector<float> positions, normals;
	std::vector<double> world; // mesh_box reads doubles
};

// The box of world (box), and with a centre its farthest vertex's squared
// distance from it (r2), taken into all's.
void take(const std::vector<double> &world, const double *center, double all[6], double *r2)
{
	double box[6], d2;
	mesh_box(world.data(), (uint32_t)(world.size() / 3), center, box, &d2);
	for (int k = 0; k < 3; k++) {
		all[k] = std::fmin(all[k], box[k]);
		all[3 + k] = std::fmax(all[3 + k], box[3 + k]);
	}
	*r2 = std::fmax(*r2, d2);
}

// Every pose of the clip: the still as baked, then each sample as clip
// time (once, speed 1: the clock leaves a time within the clip as it is).
// Without a centre, their box; with one, their farthest vertex from it.
void each_pose(Poser *s, const struct gltf_options *o, int clip, const std::vector<double> &still,
	       const std::vector<double> &times, const double *center, double box[6], double *r2)
{
	struct gltf_options at = *o;
	at.loop = ANIM_ONCE;
	at.speed = 1;
	*r2 = 0;
	for (int k = 0; k < 3; k++) {
		box[k] = INFINITY;
		box[3 + k] = -INFINITY;
	}
	take(still, center, box, r2);
	for (double t : times) {
		at.time = t;
		gltf_anim_pose(s->play->anim, &at, clip, s->pose.get());
		anim_play_pose(s->play, s->pose.get(), s->positions.data(), s->normals.data());
		s->world.assign(s->positions.begin(), s->positions.end());
		take(s->world, center, box, r2);
	}
}

} // namespace

bool gltf_clip_fit(struct anim_play *play, const struct gltf_options *o,
		   const std::vector<double> &still, GltfFit *fit)
{
	const struct mesh_anim *a = play->anim;
	std::string err;
	int clip;
	*fit = GltfFit();
	if (!o->pose || !gltf_anim_clips(a, o, &clip, &err))
		return false; // the build says what is wrong, once
	bool all = o->animation && !std::strcmp(o->animation, "all");
	if (clip < 0 && !all)
		return false;
	std::vector<double> times = sample_times(a, clip, all);
	Poser s = {play, {anim_pose_new(a), PoseFree()}, {}, {}, {}};
	if (!s.pose)
		throw std::bad_alloc();
	s.positions.resize((size_t)play->vertex_count * 3);
	s.normals.resize(s.positions.size());
	// As mesh_fit_positions fits one pose: the centre of the poses' box,
	// and their farthest vertex from it on the unit sphere (two passes).
	double box[6], r2;
	each_pose(&s, o, clip, still, times, nullptr, box, &r2);
	if (!(box[0] <= box[3]))
		return false;
	for (int k = 0; k < 3; k++)
		fit->center[k] = box[k] + (box[3 + k] - box[k]) / 2;
	each_pose(&s, o, clip, still, times, fit->center, box, &r2);
	fit->use_fit = true;
	fit->scale = r2 > 0 && std::isfinite(r2) ? 1 / std::sqrt(r2) : 1;
	return true;
}

namespace
{

struct PlayFree {
	void operator()(struct anim_play *p) const
	{
		anim_play_free(p);
	}
};
using Play = std::unique_ptr<struct anim_play, PlayFree>;

} // namespace

struct anim_play *gltf_fit_clip(const char *name, const tinygltf::Model &m, struct mesh_anim *anim,
				const std::vector<GltfPlayPart> &parts,
				const std::vector<uint32_t> &indices, const struct gltf_options *o,
				const std::vector<double> &still, GltfFit *fit)
{
	static const double origin[3] = {0, 0, 0};
	std::string err;
	struct anim_play *built = nullptr;
	gltf_play_build(m, anim, parts, indices, origin, 1, &built, &err);
	Play p(built);
	if (!p) {
		log_warn("%s: %s; %s", gltf_ext::escape(name).c_str(),
			 gltf_ext::escape(err.empty() ? "no animation to play" : err).c_str(),
			 o->play ? "it shows still" : "the still is fitted to its own pose");
		return nullptr;
	}
	if (!gltf_clip_fit(p.get(), o, still, fit) || !o->play)
		return nullptr;
	std::memcpy(p->center, fit->center, sizeof(p->center));
	p->scale = fit->scale;
	return p.release();
}
