#include "scene/mesh/lod_coarse.h"

#include <errno.h>
#include <float.h>
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>

/* Each range's share of `triangles`, by its size, sloppily simplified into
 * idx; the ranges of out follow (a mesh without ranges is one, whole).
 * Returns the index count. */
static size_t simplify_ranges(const struct mesh *m, uint32_t triangles, unsigned *idx,
			      struct mesh_range *ranges)
{
	struct mesh_range whole = {.first_index = 0, .index_count = m->index_count};
	uint32_t count = m->range_count ? m->range_count : 1;
	size_t at = 0;

	for (uint32_t r = 0; r < count; r++) {
		const struct mesh_range *in = m->range_count ? &m->ranges[r] : &whole;
		double share = (double)triangles * in->index_count / m->index_count;
		size_t target =
		    3 * (size_t)(share > LOD_COARSE_RANGE_MIN ? share : LOD_COARSE_RANGE_MIN);
		size_t n = in->index_count;

		/* No error bound (FLT_MAX): the count alone decides. */
		if (target < n)
			n = meshopt_simplifySloppy(idx + at, m->indices + in->first_index,
						   in->index_count, m->positions, m->vertex_count,
						   3 * sizeof(float), target, FLT_MAX, NULL);
		else
			memcpy(idx + at, m->indices + in->first_index, n * sizeof(unsigned));
		ranges[r] = *in;
		ranges[r].first_index = (uint32_t)at;
		ranges[r].index_count = (uint32_t)n;
		at += n;
	}
	return at;
}

/* The attribute arrays of out, from m's vertices that remap keeps. */
static int copy_streams(const struct mesh *m, const unsigned *remap, struct mesh *out)
{
	const float *from[6] = {m->positions, m->normals, m->uvs, m->tangents, m->colors, m->uv1};
	float **to[6] = {&out->positions, &out->normals, &out->uvs,
			 &out->tangents,  &out->colors,	 &out->uv1};
	const size_t width[6] = {3, 3, 2, 4, 4, 2};

	for (int s = 0; s < 6; s++) {
		if (!from[s])
			continue;
		if (!*to[s] && !(*to[s] = malloc(out->vertex_count * width[s] * sizeof(float) + 1)))
			return -ENOMEM;
		meshopt_remapVertexBuffer(*to[s], from[s], m->vertex_count,
					  width[s] * sizeof(float), remap);
	}
	return 0;
}

/* idx (n indices into m) as out's own, compact vertices. */
static int compact(const struct mesh *m, const unsigned *idx, size_t n, struct mesh *out)
{
	unsigned *remap = malloc((size_t)m->vertex_count * sizeof(unsigned) + 1);
	size_t unique =
	    remap ? meshopt_optimizeVertexFetchRemap(remap, idx, n, m->vertex_count) : 0;
	int ret = remap ? mesh_alloc(out, (uint32_t)unique, (uint32_t)n, m->uvs != NULL) : -ENOMEM;

	if (!ret)
		ret = copy_streams(m, remap, out);
	if (!ret)
		meshopt_remapIndexBuffer(out->indices, idx, n, remap);
	free(remap);
	return ret;
}

/* What out says beside its arrays: m's materials' factors and colours. */
static int copy_facts(const struct mesh *m, struct mesh *out)
{
	out->colors_by_material = m->colors_by_material;
	return mesh_copy_factors(out, m);
}

int lod_coarse_mesh(const struct mesh *m, uint32_t triangles, struct mesh *out)
{
	unsigned *idx = NULL;
	struct mesh_range *ranges = NULL;
	size_t n;
	int ret = -EINVAL;

	memset(out, 0, sizeof(*out));
	if (!m->index_count || m->variant_count)
		goto out;
	ret = -ENOMEM;
	/* Each range may keep its floor above its share: at most all of m. */
	idx = malloc((size_t)m->index_count * sizeof(unsigned) + 1);
	ranges = calloc(m->range_count ? m->range_count : 1, sizeof(*ranges));
	if (!idx || !ranges)
		goto out;
	n = simplify_ranges(m, triangles, idx, ranges);
	ret = compact(m, idx, n, out);
	if (!ret)
		ret = copy_facts(m, out);
	if (ret)
		goto out;
	/* None in m: none in out either (the whole mesh is one draw). */
	if (m->range_count) {
		out->ranges = ranges;
		out->range_count = m->range_count;
		ranges = NULL;
		mesh_range_centers(out);
	}
out:
	if (ret)
		mesh_release(out);
	free(ranges);
	free(idx);
	return ret;
}
