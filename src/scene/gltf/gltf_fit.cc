// A posed still fitted for its whole clip: the centre of the model's box
// at the pose asked for and at the clip's key times, and its farthest
// vertex from it over them, two loads of the geometry a pose, so that
// every still of one clip shares one framing.
#include "scene/gltf/gltf_fit.h"
#include "scene/gltf/gltf_anim.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// One pose's box (fit->measured), and with fit->has_center the squared
// distance of its farthest vertex from that centre (fit->radius2).
bool measure(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
	     const GltfImages &images, GltfFit *fit)
{
	tinygltf::Model copy = m;
	struct mesh mesh;
	struct gltf_options geometry = *o; // the pose alone: no clips kept, no maps
	geometry.anim = nullptr;
	geometry.play = nullptr;
	geometry.textures = 0;
	fit->measure = true;
	if (gltf_build_mesh(name, copy, &geometry, images, &mesh, fit))
		return false;
	mesh_release(&mesh);
	return true;
}

// Every pose of the clip: the pose asked for, then each sample as clip
// time (once, speed 1: the clock leaves a time within the clip as it is).
// Without a centre, their box; with one, their farthest vertex from it.
bool each_pose(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
	       const GltfImages &images, const std::vector<double> &times, GltfFit *all)
{
	struct gltf_options at = *o;
	at.loop = ANIM_ONCE;
	at.speed = 1;
	for (size_t i = 0; i <= times.size(); i++) {
		GltfFit one = {};
		one.has_center = all->has_center;
		std::memcpy(one.center, all->center, sizeof(one.center));
		if (i > 0)
			at.time = times[i - 1];
		if (!measure(name, m, i ? &at : o, images, &one))
			return false;
		for (int k = 0; k < 3; k++) {
			all->measured[k] = std::fmin(all->measured[k], one.measured[k]);
			all->measured[3 + k] = std::fmax(all->measured[3 + k], one.measured[3 + k]);
		}
		all->radius2 = std::fmax(all->radius2, one.radius2);
	}
	return true;
}

} // namespace

void gltf_clip_fit(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
		   const GltfImages &images, GltfFit *fit)
{
	struct mesh_anim *a = nullptr;
	std::string err;
	int clip;
	*fit = GltfFit();
	if (!o->pose || !gltf_read_anim(m, &a, &err) || !a || !gltf_anim_clips(a, o, &clip, &err)) {
		mesh_anim_free(a);
		return; // the build says what is wrong, once
	}
	bool all = o->animation && !std::strcmp(o->animation, "all");
	std::vector<double> times = sample_times(a, clip, all);
	mesh_anim_free(a);
	if (clip < 0 && !all)
		return;
	// As mesh_fit_positions fits one pose: the centre of the poses' box,
	// and their farthest vertex from it on the unit sphere (two passes).
	GltfFit over = {};
	for (int k = 0; k < 3; k++) {
		over.measured[k] = INFINITY;
		over.measured[3 + k] = -INFINITY;
	}
	if (!each_pose(name, m, o, images, times, &over) || !(over.measured[0] <= over.measured[3]))
		return;
	for (int k = 0; k < 3; k++)
		over.center[k] = over.measured[k] + (over.measured[3 + k] - over.measured[k]) / 2;
	over.has_center = true;
	if (!each_pose(name, m, o, images, times, &over))
		return;
	fit->use_fit = true;
	std::memcpy(fit->center, over.center, sizeof(fit->center));
	fit->scale =
	    over.radius2 > 0 && std::isfinite(over.radius2) ? 1 / std::sqrt(over.radius2) : 1;
}
