// A posed still fitted for its whole clip: the model's box at the pose
// asked for and at the clip's key times, each a load of the geometry, so
// that every still of one clip shares one framing.
#include "scene/gltf_fit.h"
#include "scene/gltf_anim.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace
{

// Clip times that show the clip's extent: its key times (where LINEAR and
// STEP reach their extremes), at most 32, else 32 spread over it.
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
	return t;
}

bool measure(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
	     const GltfImages &images, double box[6])
{
	tinygltf::Model copy = m;
	struct mesh mesh;
	struct gltf_options geometry = *o; // the pose alone: no clips kept, no maps
	geometry.anim = nullptr;
	geometry.textures = 0;
	GltfFit fit = {};
	fit.measure = true;
	if (gltf_build_mesh(name, copy, &geometry, images, &mesh, &fit))
		return false;
	mesh_release(&mesh);
	for (int k = 0; k < 3; k++) {
		box[k] = std::fmin(box[k], fit.measured[k]);
		box[3 + k] = std::fmax(box[3 + k], fit.measured[3 + k]);
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
	double box[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
	// The pose asked for, then each sample as clip time (once, speed 1:
	// the clock leaves a time within the clip as it is).
	bool ok = measure(name, m, o, images, box);
	struct gltf_options at = *o;
	at.loop = ANIM_ONCE;
	at.speed = 1;
	for (size_t i = 0; ok && i < times.size(); i++) {
		at.time = times[i];
		ok = measure(name, m, &at, images, box);
	}
	fit->use_box = ok && box[0] <= box[3];
	std::memcpy(fit->box, box, sizeof(box));
}
