// tinygltf's parser compiled into the fuzzers, with their sanitizers and
// coverage: Debian's libtinygltf.so is not instrumented, so a fault in the
// JSON or GLB parsing would go unseen. The same header as the library's
// (libtinygltf-dev) with its implementation switched on.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

// Debian builds tinygltf without stb_image, and src/scene/gltf.cc installs its own
// image loader; the defaults that a TinyGLTF object still names when it is
// declared without TINYGLTF_NO_STB_IMAGE are never called.
namespace tinygltf
{
bool LoadImageData(Image *, const int, std::string *err, std::string *, int, int,
		   const unsigned char *, int, void *)
{
	if (err)
		*err += "no default image loader in the fuzzer build\n";
	return false;
}

#if MK_TINYGLTF_MINOR >= 9
// 2.9 hands the writer the file system and URI callbacks too.
bool WriteImageData(const std::string *, const std::string *, const Image *, bool,
		    const FsCallbacks *, const URICallbacks *, std::string *, void *)
{
	return false;
}
#else
bool WriteImageData(const std::string *, const std::string *, const Image *, bool, std::string *,
		    void *)
{
	return false;
}
#endif
} // namespace tinygltf
