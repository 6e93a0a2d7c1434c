// tinygltf's file callbacks for the glTF loader (C++, internal to the glTF
// shim): external files only from the model's folder or below it.
#ifndef MK_GLTF_FS_H
#define MK_GLTF_FS_H

#include <tiny_gltf.h>

#include <string>
#include <vector>

// What the callbacks saw while tinygltf read the file.
struct GltfFiles {
	std::string dir; // the model's folder; external files must stay in it
	std::string refused;
	std::string missing;
	size_t max_size = 0; // the largest file read
};

// A URI may name a file beside the model or in a subfolder of its folder
// (textures/wood.png, as Blender and Sketchfab write them), never an
// absolute path or one that climbs out with "..".
bool gltf_path_allowed(const GltfFiles &files, const std::string &path);
// The whole file at path, refused when larger than max bytes.
bool gltf_read_file(const std::string &path, size_t max, std::vector<unsigned char> *out,
		    std::string *err);
// Why the file a URI (as written, %-encoded) names in files.dir could not be
// used, in words that follow it: "lies outside the model's folder ...", "is
// not in the model's folder", ...
std::string gltf_uri_fault(const GltfFiles &files, const std::string &uri);
// The callbacks, with files as their user data (kept by the caller).
tinygltf::FsCallbacks gltf_fs_callbacks(GltfFiles *files);

#endif
