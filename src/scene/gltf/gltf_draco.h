/* KHR_draco_mesh_compression: one compressed primitive decoded by Debian's
 * libdraco, behind a C interface so that nothing of Draco's C++ leaks into
 * the loader's other files. */
#ifndef MK_GLTF_DRACO_H
#define MK_GLTF_DRACO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

struct gltf_draco;

/* Decodes a Draco mesh; NULL with the reason in err when it is not one. */
struct gltf_draco *gltf_draco_new(const uint8_t *data, size_t size, char *err, size_t err_size);
void gltf_draco_free(struct gltf_draco *d);

uint32_t gltf_draco_vertex_count(const struct gltf_draco *d);
uint32_t gltf_draco_index_count(const struct gltf_draco *d); /* three per face */
/* Writes index_count indices, each below vertex_count. */
void gltf_draco_indices(const struct gltf_draco *d, uint32_t *out);
/* Writes vertex_count x components floats of the attribute with this
 * unique id (normalized integers become 0..1 or -1..1). Returns 0, or -1
 * when the mesh has no such attribute or it has fewer components. */
int gltf_draco_attribute(const struct gltf_draco *d, int unique_id, int components, float *out);

#ifdef __cplusplus
}
#endif

#endif
