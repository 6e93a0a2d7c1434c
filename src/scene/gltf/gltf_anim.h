// Inside the glTF shim (C++ only): a parsed model's animations into the
// plain struct mesh_anim of src/scene/anim/anim.h (gltf_anim.cc).
#ifndef MK_GLTF_ANIM_H
#define MK_GLTF_ANIM_H

#include "scene/anim/anim.h"
#include "scene/gltf/gltf_texture.h"

#include <string>
#include <tiny_gltf.h>

// *out: NULL for a file without animations, else its nodes and clips
// (free with mesh_anim_free). false, *out NULL and err naming the field and
// what was expected when an animation is malformed.
bool gltf_read_anim(const tinygltf::Model &m, struct mesh_anim **out, std::string *err);

// The nodes alone, as they stand in m (their rest pose: a still's, once
// gltf_pose_nodes wrote its clip's pose into them), without any clip: the
// rig that poses a still (gltf_play_still). false and err for a cycle
// of children or a node with two parents.
bool gltf_read_rig(const tinygltf::Model &m, struct mesh_anim **out, std::string *err);

// With o->pose, the clips o->animation names, at o->time, written into the
// nodes' translation, rotation, scale and weights (a is the model's, read
// by gltf_read_anim; NULL: nothing to pose). false, err naming the setting,
// for a clip the file lacks. *posed: true when a clip (or all) posed it.
bool gltf_pose_nodes(tinygltf::Model &m, const struct mesh_anim *a, const struct gltf_options *o,
		     std::string *err, bool *posed);

// The pose o asks for into p: the rest pose, then the clip gltf_anim_clips
// chose (clip; every clip for "all") at o->time as its clock plays it, at
// o->speed with o->loop. The still's pose and each of the fit's samples.
void gltf_anim_pose(const struct mesh_anim *a, const struct gltf_options *o, int clip,
		    struct anim_pose *p);

// gltf_read_anim and gltf_pose_nodes as the mesh builder runs them, before
// the passes that bake a still: a malformed animation is a warning (the
// still model loads); *o->anim, when asked for, takes the result.
bool gltf_anim_load(const char *name, tinygltf::Model &m, const struct gltf_options *o,
		    std::string *err, bool *posed);
// The clip o->animation names: *clip its index, -1 for off or all (or a
// file without clips); false and err naming the setting for one it lacks.
bool gltf_anim_clips(const struct mesh_anim *a, const struct gltf_options *o, int *clip,
		     std::string *err);

#endif
