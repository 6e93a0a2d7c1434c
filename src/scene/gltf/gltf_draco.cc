// The Draco decoder behind gltf_draco.h. Draco reports faults through its
// Status; nothing it throws may cross into C, so every entry point catches.
#include "scene/gltf/gltf_draco.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <cstdio>
#include <memory>

struct gltf_draco {
	std::unique_ptr<draco::Mesh> mesh;
};

extern "C" struct gltf_draco *gltf_draco_new(const uint8_t *data, size_t size, char *err,
					     size_t err_size)
{
	try {
		draco::DecoderBuffer buffer;
		buffer.Init(reinterpret_cast<const char *>(data), size);
		draco::Decoder decoder;
		auto result = decoder.DecodeMeshFromBuffer(&buffer);
		if (!result.ok()) {
			std::snprintf(err, err_size, "not a Draco mesh (%s)",
				      result.status().error_msg());
			return nullptr;
		}
		gltf_draco *d = new gltf_draco;
		d->mesh = std::move(result).value();
		return d;
	} catch (const std::exception &e) {
		std::snprintf(err, err_size, "Draco decoder failed: %s", e.what());
	}
	return nullptr;
}

extern "C" void gltf_draco_free(struct gltf_draco *d)
{
	delete d;
}

extern "C" uint32_t gltf_draco_vertex_count(const struct gltf_draco *d)
{
	return d->mesh->num_points();
}

extern "C" uint32_t gltf_draco_index_count(const struct gltf_draco *d)
{
	return d->mesh->num_faces() * 3;
}

extern "C" void gltf_draco_indices(const struct gltf_draco *d, uint32_t *out)
{
	for (draco::FaceIndex f(0); f < d->mesh->num_faces(); ++f) {
		const draco::Mesh::Face &face = d->mesh->face(f);
		for (int k = 0; k < 3; k++)
			*out++ = face[k].value();
	}
}

extern "C" int gltf_draco_attribute(const struct gltf_draco *d, int unique_id, int components,
				    float *out)
{
	const draco::PointAttribute *a =
	    unique_id < 0 ? nullptr : d->mesh->GetAttributeByUniqueId((uint32_t)unique_id);
	if (!a || a->num_components() < components)
		return -1;
	for (draco::PointIndex p(0); p < d->mesh->num_points(); ++p)
		if (!a->ConvertValue<float>(a->mapped_index(p), (int8_t)components,
					    out + (size_t)p.value() * (size_t)components))
			return -1;
	return 0;
}
