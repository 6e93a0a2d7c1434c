/* glTF 2.0 (.gltf with external or data: buffers, and .glb) into the plain
 * mesh model, through tinygltf. The only C++ behind this header. */
#ifndef MK_GLTF_H
#define MK_GLTF_H

#include "scene/gltf/gltf_texture.h"
#include "scene/mesh/mesh.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Models larger than this are refused before parsing. */
#define GLTF_MAX_FILE (512u << 20)

/* Load every triangle primitive of the default scene, each with its node
 * transform, into one mesh fitted to the unit sphere. Every accessor is
 * bounds-checked here, whatever tinygltf checked. Returns 0, or a negative
 * errno code after logging one line naming the file and the fault. */
int gltf_load(const char *path, struct mesh *out);

/* The same, with every range's material in out->materials, and their textures named in
 * `textures` (enum gltf_texture bits) decoded by our
 * own image.c: embedded (bufferView, data: URI) or a file in the model's
 * folder or a subfolder of it, by the rule buffers follow. A texture that cannot be used is a
 * warning and stays empty; the model still loads. */
int gltf_load_textures(const char *path, unsigned textures, struct mesh *out);

/* The same with every option. */
int gltf_load_options(const char *path, const struct gltf_options *o, struct mesh *out);

/* The model file's bytes (at most GLTF_MAX_FILE, read as gltf_load does;
 * *data malloc'd, the caller frees it), or a negative errno code after one
 * line naming the file and the fault. */
int gltf_read(const char *path, uint8_t **data, size_t *size);
/* gltf_load_options of the bytes gltf_read gave: the caller that keys the
 * cache with them parses what it keyed, with the file read once. */
int gltf_load_bytes(const char *path, const uint8_t *data, size_t size,
		    const struct gltf_options *o, struct mesh *out);
/* gltf_load_bytes that frees *data (malloc'd, as gltf_read gives it) and
 * sets it NULL as soon as the parser holds its own copy, before the mesh
 * is built: a large model's file, parsed buffers and mesh are not held
 * all at once. On an error *data may still be there: the caller frees
 * it (free(NULL) too). */
int gltf_load_bytes_owned(const char *path, uint8_t **data, size_t size,
			  const struct gltf_options *o, struct mesh *out);

/* The same from memory (for the fuzzer); external buffers resolve in dir. */
int gltf_load_memory(const char *name, const uint8_t *data, size_t size, const char *dir,
		     struct mesh *out);
int gltf_load_memory_textures(const char *name, const uint8_t *data, size_t size, const char *dir,
			      unsigned textures, struct mesh *out);
int gltf_load_memory_options(const char *name, const uint8_t *data, size_t size, const char *dir,
			     const struct gltf_options *o, struct mesh *out);

#ifdef __cplusplus
}
#endif

#endif
