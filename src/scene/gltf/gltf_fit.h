// Inside the glTF shim (C++ only): the fit of a posed still (gltf_fit.cc).
#ifndef MK_GLTF_FIT_H
#define MK_GLTF_FIT_H

#include "scene/anim/anim_play.h"
#include "scene/gltf/gltf_play.h"
#include "scene/gltf/gltf_texture.h"

#include <vector>

// A posed still fitted for its whole clip, so that stills of one clip
// share one framing: use_fit places positions at (world - center) * scale
// instead of the pose's own fit (mesh_fit_positions).
struct GltfFit {
	bool use_fit;
	double center[3], scale;
};

// For o->pose: the fit mesh_fit_positions would give the model at the pose
// asked for (still: its world positions as baked, xyz a vertex), at its
// clip's key times (at most 32) and 15 steps between together, so that
// every still of a clip is fitted alike (fit->use_fit). play poses each
// sample on the CPU; it must be built at centre 0 and scale 1 (world
// positions). false, and fit->use_fit false, for a file without the clip
// (or animation off): the still is fitted alone.
bool gltf_clip_fit(struct anim_play *play, const struct gltf_options *o,
		   const std::vector<double> &still, GltfFit *fit);

// The fit above with live playback's engine built once (gltf_play_build:
// m prepared, anim read before the still's pose was written into it,
// taken) for the builder's parts and indices; the engine returned, fitted
// alike, when o->play asks for it (else NULL). An engine that cannot be
// built is a warning naming the file (name) and why: the still is fitted
// to its own pose, and shows still.
struct anim_play *gltf_fit_clip(const char *name, const tinygltf::Model &m, struct mesh_anim *anim,
				const std::vector<GltfPlayPart> &parts,
				const std::vector<uint32_t> &indices, const struct gltf_options *o,
				const std::vector<double> &still, GltfFit *fit);

#endif
