// Inside the glTF shim (C++ only): the fit of a posed still (gltf_fit.cc).
#ifndef MK_GLTF_FIT_H
#define MK_GLTF_FIT_H

#include "scene/gltf/gltf_mesh.h"

#include <tiny_gltf.h>

// For o->pose: the fit mesh_fit_positions would give the model at the pose
// asked for, at its clip's key times (at most 32) and 15 steps between
// together, so that
// every still of a clip is fitted alike (fit->use_fit); nothing for a file
// without the clip. Each sample costs two loads of the geometry.
void gltf_clip_fit(const char *name, const tinygltf::Model &m, const struct gltf_options *o,
		   const GltfImages &images, GltfFit *fit);

#endif
