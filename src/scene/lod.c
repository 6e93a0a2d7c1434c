#include "scene/lod.h"
#include "util/log.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>

/* meshoptimizer's advice: accept 5% more vertex-cache misses for less
 * overdraw. */
#define OVERDRAW_THRESHOLD 1.05f

double lod_model_error(double pixels, int width, int height)
{
	return pixels / sphere_fit_pixels_per_unit(width, height);
}

static double surface_area(const struct mesh *m)
{
	double area = 0.0;

	for (uint32_t t = 0; t + 2 < m->index_count; t += 3) {
		const float *a = m->positions + (size_t)m->indices[t] * 3;
		const float *b = m->positions + (size_t)m->indices[t + 1] * 3;
		const float *c = m->positions + (size_t)m->indices[t + 2] * 3;
		double e1[3], e2[3], x, y, z;

		for (int k = 0; k < 3; k++)
			e1[k] = (double)b[k] - a[k], e2[k] = (double)c[k] - a[k];
		x = e1[1] * e2[2] - e1[2] * e2[1];
		y = e1[2] * e2[0] - e1[0] * e2[2];
		z = e1[0] * e2[1] - e1[1] * e2[0];
		area += 0.5 * sqrt(x * x + y * y + z * z);
	}
	return area;
}

double lod_triangles_wanted(const struct mesh *m, double pixels, int width, int height)
{
	double ppu = sphere_fit_pixels_per_unit(width, height);

	return pixels > 0.0 ? surface_area(m) * ppu * ppu / (2.0 * pixels * pixels) : INFINITY;
}

/* Each attribute array in the order vertex fetch wants, without the
 * vertices no triangle uses any more; all or nothing. */
static int remap_streams(struct mesh *m, const unsigned *remap, uint32_t unique)
{
	float **streams[4] = {&m->positions, &m->normals, &m->uvs, &m->tangents};
	const size_t width[4] = {3, 3, 2, 4};
	float *fresh[4] = {NULL, NULL, NULL, NULL};

	for (int s = 0; s < 4; s++) {
		if (!*streams[s])
			continue;
		fresh[s] = malloc(unique * width[s] * sizeof(float) + 1);
		if (!fresh[s]) {
			for (int k = 0; k < s; k++)
				free(fresh[k]);
			return -ENOMEM;
		}
	}
	for (int s = 0; s < 4; s++) {
		if (!fresh[s])
			continue;
		meshopt_remapVertexBuffer(fresh[s], *streams[s], m->vertex_count,
					  width[s] * sizeof(float), remap);
		free(*streams[s]);
		*streams[s] = fresh[s];
	}
	m->vertex_count = unique;
	return 0;
}

/* m's index buffer into out, simplified down to `wanted` triangles unless
 * the error would pass target (in model units) first; returns the new
 * index count.
 *
 * Seams (a UV seam, a normal crease, a mirror-split tangent: vertices
 * apart at one position) are meshoptimizer 0.18's own business: it
 * collapses a seam vertex only along the seam and both sides together,
 * and locks a position with more than two such vertices (a pole).
 * tests/unit/test_lod.c checks that a UV sphere stays closed and no
 * triangle spans its seam. */
static size_t simplify(const struct mesh *m, double wanted, double target, unsigned *out,
		       float *error)
{
	float scale = meshopt_simplifyScale(m->positions, m->vertex_count, 3 * sizeof(float));
	size_t n = 0;

	*error = 0.0f;
	/* scale 0: every vertex at one point, nothing to judge by */
	if (scale > 0.0f) {
		n = meshopt_simplify(out, m->indices, m->index_count, m->positions, m->vertex_count,
				     3 * sizeof(float), 3 * (size_t)wanted, (float)(target / scale),
				     0, error);
		*error *= scale;
	}
	/* A model smaller than the budget would vanish: it stays whole. */
	if (!n) {
		memcpy(out, m->indices, (size_t)m->index_count * sizeof(unsigned));
		n = m->index_count;
		*error = 0.0f;
	}
	return n;
}

/* Vertices equal in every attribute (a glTF exporter's duplicates) are
 * one: lossless, and gives the simplifier fewer false seams. */
static int weld_duplicates(struct mesh *m)
{
	struct meshopt_Stream streams[4] = {{m->positions, 12, 12}, {m->normals, 12, 12}};
	unsigned *remap = malloc((size_t)m->vertex_count * sizeof(unsigned) + 1);
	size_t count = 2, unique;
	int ret = -ENOMEM;

	if (!remap)
		return ret;
	if (m->uvs)
		streams[count++] = (struct meshopt_Stream){m->uvs, 8, 8};
	if (m->tangents)
		streams[count++] = (struct meshopt_Stream){m->tangents, 16, 16};
	unique = meshopt_generateVertexRemapMulti(remap, m->indices, m->index_count,
						  m->vertex_count, streams, count);
	ret = 0;
	if (unique < m->vertex_count) {
		ret = remap_streams(m, remap, (uint32_t)unique);
		if (!ret)
			meshopt_remapIndexBuffer(m->indices, m->indices, m->index_count, remap);
	}
	free(remap);
	return ret;
}

int lod_prepare_mesh(struct mesh *m, double pixels, int width, int height,
		     struct lod_result *result)
{
	unsigned *idx = malloc((size_t)m->index_count * sizeof(unsigned) + 1);
	unsigned *remap = malloc((size_t)m->vertex_count * sizeof(unsigned) + 1);
	struct lod_result r = {.triangles_before = m->index_count / 3,
			       .vertices_before = m->vertex_count};
	size_t n = m->index_count;
	float error = 0.0f;
	int ret = -ENOMEM;

	if (!idx || !remap || weld_duplicates(m))
		goto out;
	n = m->index_count;
	r.wanted = lod_triangles_wanted(m, pixels, width, height);
	if (r.wanted < n / 3)
		n = simplify(m, r.wanted, lod_model_error(pixels, width, height), idx, &error);
	else
		memcpy(idx, m->indices, n * sizeof(unsigned));
	meshopt_optimizeVertexCache(idx, idx, n, m->vertex_count);
	meshopt_optimizeOverdraw(idx, idx, n, m->positions, m->vertex_count, 3 * sizeof(float),
				 OVERDRAW_THRESHOLD);
	ret = remap_streams(
	    m, remap, (uint32_t)meshopt_optimizeVertexFetchRemap(remap, idx, n, m->vertex_count));
	if (ret)
		goto out;
	/* n never exceeds the old count: the index array is reused. */
	meshopt_remapIndexBuffer(m->indices, idx, n, remap);
	m->index_count = (uint32_t)n;
out:
	r.triangles_after = m->index_count / 3;
	r.vertices_after = m->vertex_count;
	r.error = error;
	r.error_pixels = error * sphere_fit_pixels_per_unit(width, height);
	if (ret)
		log_err("lod: no memory to simplify %u triangles", r.triangles_before);
	else if (r.triangles_after < r.triangles_before)
		log_info(
		    "lod: %u -> %u triangles for %dx%d (%.0f of %.1f px wanted; error %.2f px)",
		    r.triangles_before, r.triangles_after, width, height, r.wanted, pixels,
		    r.error_pixels);
	if (result)
		*result = r;
	free(idx);
	free(remap);
	return ret;
}
