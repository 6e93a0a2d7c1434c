// Inside the glTF shim (C++ only): a parsed model into the plain struct
// mesh of src/scene/mesh/mesh.h (gltf_mesh.cc).
#ifndef MK_GLTF_MESH_H
#define MK_GLTF_MESH_H

#include "scene/gltf/gltf_texture.h"
#include "scene/gltf/gltf_material.h"
#include "scene/mesh/mesh.h"

#include <tiny_gltf.h>

// The scene o asks for (o->scene, else the file's), every triangle
// primitive of it, into out, with the material's textures o asks for
// from images. Logs what it leaves out; an error names the file (name),
// the field and what was expected. Returns 0, -EINVAL or -ENOMEM.
// A posed still is fitted for its whole clip (so stills of one clip share
// one framing): use_fit places positions at (world - center) * scale
// instead of the pose's own fit; measure puts the pose's world box in
// measured, and with has_center its farthest vertex's squared distance
// from center in radius2 (and says nothing at info level). NULL: the
// pose's own fit.
struct GltfFit {
	bool use_fit, measure, has_center;
	double center[3], scale;
	double measured[6], radius2;
};

int gltf_build_mesh(const char *name, tinygltf::Model &m, const struct gltf_options *o,
		    const GltfImages &images, struct mesh *out, GltfFit *fit = nullptr);

#endif
