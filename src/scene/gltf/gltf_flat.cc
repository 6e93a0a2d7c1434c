// A primitive without normals split at its faces (gltf_flat.h).
#include "scene/gltf/gltf_flat.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace
{

// The tail of attribute array v from vertex `first` on (width values a
// vertex) as one copy per index of idx[0..n) (relative to first). An array
// not kept for these vertices (shorter: a model of one colour) is left alone.
template <typename T>
void split_tail(std::vector<T> &v, size_t width, size_t first, const uint32_t *idx, size_t n)
{
	if (v.size() <= first * width)
		return;
	std::vector<T> tail(v.begin() + (std::ptrdiff_t)(first * width), v.end());
	v.resize(first * width);
	v.reserve(v.size() + n * width);
	for (size_t i = 0; i < n; i++)
		v.insert(v.end(), tail.begin() + (std::ptrdiff_t)(idx[i] * width),
			 tail.begin() + (std::ptrdiff_t)((idx[i] + 1) * width));
}

} // namespace

uint32_t gltf_split_faces(const GltfSplit &s, size_t first_vertex, size_t first_index)
{
	size_t n = s.indices->size() - first_index;
	uint32_t *idx = s.indices->data() + first_index;
	for (size_t i = 0; i < n; i++) {
		idx[i] -= (uint32_t)first_vertex;
		s.source->push_back(idx[i]);
	}
	split_tail(*s.positions, 3, first_vertex, idx, n);
	split_tail(*s.normals, 3, first_vertex, idx, n);
	split_tail(*s.uvs, 2, first_vertex, idx, n);
	split_tail(*s.colors, 4, first_vertex, idx, n);
	split_tail(*s.uv1, 2, first_vertex, idx, n);
	for (size_t i = 0; i < n; i++)
		idx[i] = (uint32_t)(first_vertex + i);
	return (uint32_t)n;
}

int gltf_tag_flat(struct mesh *out, uint32_t first_vertex, uint32_t vertex_count)
{
	if (!out->flat) {
		out->flat = (uint8_t *)std::calloc((size_t)out->vertex_count + 1, 1);
		out->flat_count = out->vertex_count;
	}
	if (!out->flat)
		return -ENOMEM;
	std::memset(out->flat + first_vertex, 1, vertex_count);
	return 0;
}

int gltf_range_normals(struct mesh *out, const uint32_t *idx, uint32_t index_count,
		       uint32_t first_vertex, uint32_t vertex_count, bool has_normals, bool flat)
{
	if (flat) {
		mesh_flat_normals(out->positions, idx, index_count, out->normals);
		return gltf_tag_flat(out, first_vertex, vertex_count);
	}
	if (!has_normals)
		return mesh_generate_normals(out->positions, idx, index_count, first_vertex,
					     vertex_count, out->normals);
	return 0;
}
