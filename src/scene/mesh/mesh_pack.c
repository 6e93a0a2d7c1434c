#include "scene/mesh/mesh_pack.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const int components[MESH_ARRAYS] = {3, 3, 2, 4, 4, 2};
static const size_t component_bytes[] = {[MESH_FLOAT32] = 4, [MESH_SNORM16] = 2, [MESH_UNORM8] = 1};

int mesh_array_components(enum mesh_array a)
{
	return components[a];
}

enum mesh_component mesh_array_component(enum vertex_format f, enum mesh_array a)
{
	if (f != VERTEX_COMPACT || a == MESH_UVS || a == MESH_UV1)
		return MESH_FLOAT32;
	return a == MESH_COLORS ? MESH_UNORM8 : MESH_SNORM16;
}

bool mesh_array_int16(enum vertex_format f, enum mesh_array a)
{
	return mesh_array_component(f, a) == MESH_SNORM16;
}

size_t mesh_array_stride(enum vertex_format f, enum mesh_array a)
{
	return (size_t)components[a] * component_bytes[mesh_array_component(f, a)];
}

static int16_t snorm16(float v)
{
	float c = v < -1.0f ? -1.0f : v > 1.0f ? 1.0f : v;

	return (int16_t)lrintf(c * 32767.0f);
}

/* The fitted mesh is inside the unit sphere, so 1/32767 of its largest
 * coordinate is far below a pixel. */
static float position_scale(const struct mesh *m)
{
	float scale = 0.0f;

	for (size_t i = 0; i < (size_t)m->vertex_count * 3; i++)
		scale = fmaxf(scale, fabsf(m->positions[i]));
	return scale > 0.0f && isfinite(scale) ? scale : 1.0f;
}

static void to_unorm8(const float *src, size_t values, uint8_t *out)
{
	for (size_t i = 0; i < values; i++)
		out[i] = (uint8_t)lrintf(fminf(fmaxf(src[i], 0.0f), 1.0f) * 255.0f);
}

static void to_int16(const float *src, size_t values, float scale, int16_t *out)
{
	for (size_t i = 0; i < values; i++)
		out[i] = snorm16(src[i] * scale);
}

int mesh_pack(const struct mesh *m, enum vertex_format f, struct mesh_packed *out)
{
	const float *src[MESH_ARRAYS] = {m->positions, m->normals, m->uvs,
					 m->tangents,  m->colors,  m->uv1};
	size_t offset[MESH_ARRAYS], total = 0;
	char *block;

	memset(out, 0, sizeof(*out));
	out->format = f;
	out->vertex_count = m->vertex_count;
	out->index_count = m->index_count;
	out->indices = m->indices;
	out->position_scale = 1.0f;
	/* The ranges are copied: a packed mesh may outlive the mesh. */
	if (m->range_count) {
		out->owned_ranges = malloc(m->range_count * sizeof(*m->ranges));
		if (!out->owned_ranges)
			return -ENOMEM;
		memcpy(out->owned_ranges, m->ranges, m->range_count * sizeof(*m->ranges));
		out->ranges = out->owned_ranges;
		out->range_count = m->range_count;
	}
	if (f == VERTEX_FLOAT32) {
		for (int a = 0; a < MESH_ARRAYS; a++)
			out->arrays[a] = src[a];
		return 0;
	}
	for (int a = 0; a < MESH_ARRAYS; a++) {
		offset[a] = total;
		if (src[a])
			total += (m->vertex_count * mesh_array_stride(f, (enum mesh_array)a) + 3) &
				 ~(size_t)3;
	}
	/* The indices too: the packed mesh outlives the mesh. */
	block = malloc(total + (size_t)m->index_count * 4 + 1);
	if (!block) {
		mesh_packed_release(out);
		return -ENOMEM;
	}
	out->owned = block;
	memcpy(block + total, m->indices, (size_t)m->index_count * 4);
	out->indices = (const uint32_t *)(const void *)(block + total);
	out->position_scale = position_scale(m);
	for (int a = 0; a < MESH_ARRAYS; a++) {
		size_t values = (size_t)m->vertex_count * (size_t)components[a];

		if (!src[a])
			continue;
		out->arrays[a] = block + offset[a];
		if (a == MESH_UVS || a == MESH_UV1)
			memcpy(block + offset[a], src[a], values * sizeof(float));
		else if (a == MESH_COLORS)
			to_unorm8(src[a], values, (uint8_t *)(block + offset[a]));
		else
			to_int16(src[a], values, a ? 1.0f : 1.0f / out->position_scale,
				 (int16_t *)(void *)(block + offset[a]));
	}
	return 0;
}

void mesh_packed_release(struct mesh_packed *p)
{
	free(p->owned);
	free(p->owned_ranges);
	memset(p, 0, sizeof(*p));
}
