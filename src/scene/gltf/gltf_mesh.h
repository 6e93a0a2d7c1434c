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
// A posed still is fitted for its whole clip (gltf_fit.h); o->play, when
// set, takes live playback's engine, built once here for that fit too.
int gltf_build_mesh(const char *name, tinygltf::Model &m, const struct gltf_options *o,
		    const GltfImages &images, struct mesh *out);

#endif
