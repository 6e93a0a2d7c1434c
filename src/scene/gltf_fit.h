// Inside the glTF shim (C++ only): the fit of a posed still (gltf_fit.cc).
#ifndef MK_GLTF_FIT_H
#define MK_GLTF_FIT_H

#include "scene/gltf_mesh.h"

#include <tiny_gltf.h>

// For o->pose: a box holding the model at the pose asked for and at each
// of its clip's key times (at most 32), so that every still of a clip is
// fitted alike (fit->use_box); nothing for a file without the clip.
// Each sample costs a load of the geometry.
void gltf_clip_fit(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
		   const GltfImages &images, GltfFit *fit);

#endif
