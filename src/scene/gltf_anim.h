// Inside the glTF shim (C++ only): a parsed model's animations into the
// plain struct mesh_anim of src/scene/anim.h (gltf_anim.cc).
#ifndef MK_GLTF_ANIM_H
#define MK_GLTF_ANIM_H

#include "scene/anim.h"

#include <string>
#include <tiny_gltf.h>

// *out: NULL for a file without animations, else its nodes and clips
// (free with mesh_anim_free). false, *out NULL and err naming the field and
// what was expected when an animation is malformed.
bool gltf_read_anim(const tinygltf::Model &m, struct mesh_anim **out, std::string *err);

#endif
