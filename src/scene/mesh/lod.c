#include "scene/mesh/lod.h"
#include "scene/mesh/lod_seams.h"
#include "scene/mesh/lod_split.h"
#include "util/log.h"
#include "util/math3d.h"

#include <errno.h>
#include <math.h>
#include <meshoptimizer.h>
#include <stdbool.h>
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
	float **streams[6] = {&m->positions, &m->normals, &m->uvs,
			      &m->tangents,  &m->colors,  &m->uv1};
	const size_t width[6] = {3, 3, 2, 4, 4, 2};
	float *fresh[6] = {NULL, NULL, NULL, NULL, NULL, NULL};

	for (int s = 0; s < 6; s++) {
		if (!*streams[s])
			continue;
		fresh[s] = malloc(unique * width[s] * sizeof(float) + 1);
		if (!fresh[s]) {
			for (int k = 0; k < s; k++)
				free(fresh[k]);
			return -ENOMEM;
		}
	}
	for (int s = 0; s < 6; s++) {
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
 * apart at one position) are meshoptimizer 0.18's own business here: it
 * collapses a seam vertex only along the seam and both sides together,
 * and locks a position with more than two such vertices (a pole). Where
 * that keeps far more than wanted, lod_simplify_welded takes over.
 * tests/unit/test_lod.c checks that a UV sphere stays closed and no
 * triangle spans its seam. */
static size_t simplify(const struct mesh *m, double wanted, double target, unsigned options,
		       unsigned *out, float *error)
{
	float scale = meshopt_simplifyScale(m->positions, m->vertex_count, 3 * sizeof(float));
	size_t n = 0;

	*error = 0.0f;
	/* scale 0: every vertex at one point, nothing to judge by */
	if (scale > 0.0f) {
		n = meshopt_simplify(out, m->indices, m->index_count, m->positions, m->vertex_count,
				     3 * sizeof(float), 3 * (size_t)wanted, (float)(target / scale),
				     options, error);
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

/* Seams may keep this much more than the count wanted before the
 * position-only pass is tried. */
#define SEAM_SLACK 1.25

/* The welded pass's result in idx when it has fewer triangles than the
 * n already there; returns the count kept. */
static size_t simplify_seamless(const struct mesh *m, double wanted, double target,
				unsigned options, unsigned *idx, size_t n, float *error)
{
	unsigned *out = malloc((size_t)m->index_count * sizeof(unsigned) + 1);

	for (int by_uv = 1; by_uv >= 0 && out && n / 3 > SEAM_SLACK * wanted; by_uv--) {
		float welded_error = 0.0f;
		size_t w =
		    lod_simplify_welded(m, by_uv, wanted, target, options, out, &welded_error);

		if (w > 0 && w < n) {
			memcpy(idx, out, w * sizeof(unsigned));
			n = w;
			*error = welded_error;
		}
	}
	free(out);
	return n;
}

/* Some of m's triangles as a mesh of its own: the vertices they use
 * (back[] maps them to m's), with what simplifying reads. */
static int part_mesh(const struct mesh *m, const unsigned *indices, uint32_t count, uint32_t *local,
		     struct mesh *sub, uint32_t **back)
{
	uint32_t nv = 0;
	int ret;

	for (uint32_t i = 0; i < count; i++)
		local[indices[i]] = UINT32_MAX;
	for (uint32_t i = 0; i < count; i++)
		if (local[indices[i]] == UINT32_MAX)
			local[indices[i]] = nv++;
	ret = mesh_alloc(sub, nv, count, m->uvs != NULL);
	*back = malloc((size_t)nv * sizeof(uint32_t) + 1);
	if (ret || !*back) {
		mesh_release(sub);
		free(*back);
		*back = NULL;
		return -ENOMEM;
	}
	for (uint32_t i = 0; i < count; i++) {
		uint32_t v = indices[i], l = local[v];

		sub->indices[i] = l;
		(*back)[l] = v;
		memcpy(sub->positions + (size_t)l * 3, m->positions + (size_t)v * 3, 12);
		memcpy(sub->normals + (size_t)l * 3, m->normals + (size_t)v * 3, 12);
		if (m->uvs)
			memcpy(sub->uvs + (size_t)l * 2, m->uvs + (size_t)v * 2, 8);
	}
	return 0;
}

/* Some of m's triangles (indices, count) simplified on their own to
 * `share` triangles unless the error would pass target first, their
 * border locked when options say so: into out (room for count), in m's
 * vertex numbers; *n the count kept, *error the estimate. local: room
 * for m's vertex count. out may be indices: the part is copied into a
 * mesh of its own before a result is written. */
static int simplify_part(const struct mesh *m, const unsigned *indices, uint32_t count,
			 double share, double target, unsigned options, uint32_t *local,
			 unsigned *out, size_t *n, float *error)
{
	struct mesh sub;
	uint32_t *back = NULL;
	size_t k = count;
	int ret = part_mesh(m, indices, count, local, &sub, &back);

	*error = 0.0f;
	if (ret)
		return ret;
	if (share < k / 3) {
		k = simplify(&sub, share, target, options, out, error);
		if (k / 3 > SEAM_SLACK * share)
			k = simplify_seamless(&sub, share, target, options, out, k, error);
	} else {
		memcpy(out, sub.indices, k * sizeof(unsigned));
	}
	for (size_t i = 0; i < k; i++)
		out[i] = back[out[i]];
	*n = k;
	free(back);
	mesh_release(&sub);
	return 0;
}

/* A cluster under this many triangles is not worth a thread: a smaller
 * model (or range) is simplified as before, whatever the thread count. */
#define CLUSTER_MIN_TRIANGLES 16384

/* A part over this many triangles is cut into clusters of at most about
 * this size whatever the thread count, for memory: meshoptimizer's
 * simplifier holds some 110 bytes a triangle of its input at once (edge
 * collapses, adjacency, quadrics), 110 MB for a 1M-triangle scan on top
 * of the mesh itself, where one cluster holds 7 MB (issue 34: a cold
 * start's peak). A part up to it is simplified as before. */
#define CLUSTER_MAX_TRIANGLES 65536
#define CLUSTERS_MAX	      256

/* The clusters do the bulk, the pass over them joined the rest: a
 * cluster is cut to 1.5 times its share of the count, but by at most 16
 * times, and to half the error budget. A locked border keeps a strip of
 * small triangles that a cluster cut to its exact share would pay for
 * with the error elsewhere, and that the seams' fallback (simplify_seamless)
 * would try to remove in vain; what is left of the budget and of the
 * count is the joined pass's, where those borders are free. */
#define CLUSTER_SLACK  1.5
#define CLUSTER_CUT    16.0
#define CLUSTER_BUDGET 0.5

/* The most triangles one simplifier call was given, in r: what its
 * memory follows. */
static void lod_result_part(struct lod_result *r, uint32_t triangles)
{
	if (r->largest_part < triangles)
		r->largest_part = triangles;
}

/* As many clusters as threads, and at least enough that none is over
 * CLUSTER_MAX_TRIANGLES; none under CLUSTER_MIN_TRIANGLES. */
static unsigned cluster_count(int threads, uint32_t index_count)
{
	uint32_t triangles = index_count / 3;
	uint32_t most = triangles / CLUSTER_MIN_TRIANGLES;
	uint32_t least = (triangles + CLUSTER_MAX_TRIANGLES - 1) / CLUSTER_MAX_TRIANGLES;
	uint32_t want = threads > LOD_THREADS_MAX ? LOD_THREADS_MAX : threads > 1 ? threads : 1;

	if (want < least)
		want = least;
	if (want > most)
		want = most;
	return want > CLUSTERS_MAX ? CLUSTERS_MAX : want > 1 ? want : 1;
}

/* One part's clusters, simplified side by side: cluster j is the j-th of
 * `clusters` equal runs of the ordered triangles, and writes its result
 * where its run begins in out. */
struct cluster_job {
	const struct mesh *m;
	const unsigned *order;
	uint32_t triangles;
	unsigned clusters;
	double share, target;
	unsigned *out;
	size_t n[CLUSTERS_MAX];
	float error[CLUSTERS_MAX];
	int ret[CLUSTERS_MAX];
};

static uint32_t cluster_first(const struct cluster_job *c, unsigned j)
{
	return (uint32_t)((uint64_t)c->triangles * j / c->clusters);
}

static void cluster_run(void *arg, unsigned j)
{
	struct cluster_job *c = arg;
	uint32_t first = cluster_first(c, j), count = cluster_first(c, j + 1) - first;
	uint32_t *local = malloc((size_t)c->m->vertex_count * sizeof(uint32_t) + 1);

	double goal = fmax(CLUSTER_SLACK * c->share * count / c->triangles, count / CLUSTER_CUT);

	/* Its border locked: where two clusters meet both keep the edge. */
	c->ret[j] = local ? simplify_part(c->m, c->order + (size_t)first * 3, count * 3, goal,
					  CLUSTER_BUDGET * c->target, meshopt_SimplifyLockBorder,
					  local, c->out + (size_t)first * 3, &c->n[j], &c->error[j])
			  : -ENOMEM;
	free(local);
}

/* simplify_part on `threads` threads: the part cut into spatial clusters
 * (lod_split_order), each simplified towards its share with its border
 * locked, then all of them together once more, the locked borders now
 * free (as options say), with what is left of the error budget: the two
 * passes' errors add up to at most target, as one pass's would. Deterministic for
 * a thread count: the clusters depend on it, not on which thread ran
 * which. */
static int simplify_clustered(const struct mesh *m, const unsigned *indices, uint32_t count,
			      double share, double target, unsigned options, int threads,
			      unsigned *out, size_t *n, float *error, struct lod_result *r)
{
	struct cluster_job *c = calloc(1, sizeof(*c));
	uint32_t *local = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	uint32_t joined = 0;
	float first_error = 0.0f, second_error = 0.0f;
	/* out holds the ordered triangles, each cluster's result in its own
	 * run, then the joined pass's, all in place (simplify_part): no copy
	 * of the part's indices more (12 MB for a 1M-triangle scan). */
	int ret = c && local ? lod_split_order(indices, count, m->positions, m->vertex_count, out)
			     : -ENOMEM;

	if (!ret) {
		*c = (struct cluster_job){.m = m,
					  .order = out,
					  .triangles = count / 3,
					  .clusters = cluster_count(threads, count),
					  .share = share,
					  .target = target,
					  .out = out};
		lod_pool_run(threads, c->clusters, cluster_run, c);
		r->clusters = r->clusters > c->clusters ? r->clusters : c->clusters;
		lod_result_part(r, (c->triangles + c->clusters - 1) / c->clusters);
	}
	for (unsigned j = 0; !ret && j < c->clusters; j++) {
		ret = c->ret[j];
		if (ret)
			break;
		memmove(out + joined, out + (size_t)cluster_first(c, j) * 3,
			c->n[j] * sizeof(unsigned));
		joined += (uint32_t)c->n[j];
		first_error = fmaxf(first_error, c->error[j]);
	}
	/* The clusters' result is the input now, in place. */
	if (!ret) {
		log_debug("lod: %u triangles as %u clusters on %d threads, %u joined", count / 3,
			  c->clusters, threads, joined / 3);
		lod_result_part(r, joined / 3);
		ret = simplify_part(m, out, joined, share, fmax(target - first_error, 0.0), options,
				    local, out, n, &second_error);
	}
	*error = first_error + second_error;
	free(c);
	free(local);
	return ret;
}

/* A model of several materials: each range simplified on its own to its
 * share of the count wanted, its border locked (meshopt_SimplifyLockBorder).
 * Where two parts meet, both keep every vertex of the edge between them,
 * so no crack opens there, and every triangle keeps its range's material.
 * idx gets the ranges one after the other; m's ranges are moved to fit.
 * A large range is cut further on threads (simplify_clustered). */
static int simplify_ranges(struct mesh *m, double wanted, double target, int threads, unsigned *idx,
			   size_t *n, float *error, struct lod_result *result)
{
	uint32_t *local = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	uint32_t at = 0;
	int ret = local ? 0 : -ENOMEM;

	*error = 0.0f;
	for (uint32_t r = 0; !ret && r < m->range_count; r++) {
		struct mesh_range *g = &m->ranges[r];
		double share = wanted * g->index_count / (double)m->index_count;
		size_t k = 0;
		float e = 0.0f;

		if (share < g->index_count / 3 && cluster_count(threads, g->index_count) > 1)
			ret = simplify_clustered(m, m->indices + g->first_index, g->index_count,
						 share, target, meshopt_SimplifyLockBorder, threads,
						 idx + at, &k, &e, result);
		else {
			lod_result_part(result, g->index_count / 3);
			ret = simplify_part(m, m->indices + g->first_index, g->index_count, share,
					    target, meshopt_SimplifyLockBorder, local, idx + at, &k,
					    &e);
		}
		if (ret)
			break;
		*error = fmaxf(*error, e);
		g->first_index = at;
		g->index_count = (uint32_t)k;
		at += (uint32_t)k;
	}
	free(local);
	*n = at;
	return ret;
}

/* The flat tag in the order of remap (weld_duplicates). */
static int remap_flat(struct mesh *m, const unsigned *remap, uint32_t unique)
{
	uint8_t *fresh;

	if (!m->flat)
		return 0;
	fresh = malloc((size_t)unique + 1);
	if (!fresh)
		return -ENOMEM;
	meshopt_remapVertexBuffer(fresh, m->flat, m->vertex_count, 1, remap);
	free(m->flat);
	m->flat = fresh;
	m->flat_count = unique;
	return 0;
}

/* Vertices equal in every attribute (a glTF exporter's duplicates) are
 * one: lossless, and gives the simplifier fewer false seams. */
static int weld_duplicates(struct mesh *m)
{
	struct meshopt_Stream streams[7] = {{m->positions, 12, 12}, {m->normals, 12, 12}};
	unsigned *remap = malloc((size_t)m->vertex_count * sizeof(unsigned) + 1);
	size_t count = 2, unique;
	int ret = -ENOMEM;

	if (!remap)
		return ret;
	if (m->uvs)
		streams[count++] = (struct meshopt_Stream){m->uvs, 8, 8};
	if (m->tangents)
		streams[count++] = (struct meshopt_Stream){m->tangents, 16, 16};
	if (m->colors)
		streams[count++] = (struct meshopt_Stream){m->colors, 16, 16};
	/* A split (flat) corner stays apart from a smooth one. */
	if (m->flat)
		streams[count++] = (struct meshopt_Stream){m->flat, 1, 1};
	if (m->uv1)
		streams[count++] = (struct meshopt_Stream){m->uv1, 8, 8};
	unique = meshopt_generateVertexRemapMulti(remap, m->indices, m->index_count,
						  m->vertex_count, streams, count);
	ret = 0;
	if (unique < m->vertex_count) {
		ret = remap_flat(m, remap, (uint32_t)unique);
		if (!ret)
			ret = remap_streams(m, remap, (uint32_t)unique);
		if (!ret)
			meshopt_remapIndexBuffer(m->indices, m->indices, m->index_count, remap);
	}
	free(remap);
	return ret;
}

/* m->flat over every vertex: those a step after the loader appended
 * (tangent.c's twins of a mirrored UV) are not flat; a tag that no longer
 * fits the vertices is dropped. */
static int flat_cover(struct mesh *m)
{
	uint8_t *f;

	if (m->flat && m->flat_count > m->vertex_count) {
		free(m->flat);
		m->flat = NULL;
	}
	if (!m->flat || m->flat_count == m->vertex_count)
		return 0;
	f = realloc(m->flat, (size_t)m->vertex_count + 1);
	if (!f)
		return -ENOMEM;
	memset(f + m->flat_count, 0, m->vertex_count - m->flat_count);
	m->flat = f;
	m->flat_count = m->vertex_count;
	return 0;
}

/* The flat tag after the level of detail: nothing reads it further (the
 * cache keeps the mesh as simplified). */
static void flat_drop(struct mesh *m)
{
	free(m->flat);
	m->flat = NULL;
	m->flat_count = 0;
}

/* Room for `extra` more vertices in every attribute array. */
static int grow_streams(struct mesh *m, uint32_t extra)
{
	float **streams[6] = {&m->positions, &m->normals, &m->uvs,
			      &m->tangents,  &m->colors,  &m->uv1};
	const size_t width[6] = {3, 3, 2, 4, 4, 2};

	for (int s = 0; s < 6; s++) {
		float *p = *streams[s] ? realloc(*streams[s], ((size_t)m->vertex_count + extra) *
								  width[s] * sizeof(float))
				       : NULL;

		if (*streams[s] && !p)
			return -ENOMEM;
		if (p)
			*streams[s] = p;
	}
	return 0;
}

/* A simplified triangle of flat corners spans faces that were many: its
 * corners took their normals from one of those (unweld_triangle), so it
 * would shade as a blend. Each corner off its new face's normal becomes a
 * vertex of its own with that normal: flat stays flat after simplifying.
 * remap grows with the vertices. */
static int keep_flat(struct mesh *m, unsigned *idx, size_t n, unsigned **remap)
{
	unsigned *more = realloc(*remap, ((size_t)m->vertex_count + n) * sizeof(unsigned) + 1);
	uint32_t added = 0;

	if (more)
		*remap = more;
	if (!more || grow_streams(m, (uint32_t)n))
		return -ENOMEM;
	for (size_t t = 0; t + 2 < n; t += 3) {
		unsigned *c = idx + t;
		float f[3];

		if (c[0] >= m->flat_count || c[1] >= m->flat_count || c[2] >= m->flat_count ||
		    !m->flat[c[0]] || !m->flat[c[1]] || !m->flat[c[2]])
			continue;
		mesh_face_normal(m->positions + (size_t)c[0] * 3, m->positions + (size_t)c[1] * 3,
				 m->positions + (size_t)c[2] * 3, f);
		for (int k = 0; k < 3; k++) {
			uint32_t v = m->vertex_count + added;

			if (!memcmp(m->normals + (size_t)c[k] * 3, f, sizeof(f)))
				continue;
			memcpy(m->positions + (size_t)v * 3, m->positions + (size_t)c[k] * 3, 12);
			memcpy(m->normals + (size_t)v * 3, f, 12);
			if (m->uvs)
				memcpy(m->uvs + (size_t)v * 2, m->uvs + (size_t)c[k] * 2, 8);
			if (m->tangents)
				memcpy(m->tangents + (size_t)v * 4, m->tangents + (size_t)c[k] * 4,
				       16);
			if (m->colors)
				memcpy(m->colors + (size_t)v * 4, m->colors + (size_t)c[k] * 4, 16);
			if (m->uv1)
				memcpy(m->uv1 + (size_t)v * 2, m->uv1 + (size_t)c[k] * 2, 8);
			c[k] = v;
			added++;
		}
	}
	m->vertex_count += added;
	return 0;
}

int lod_prepare_mesh(struct mesh *m, double pixels, int width, int height,
		     struct lod_result *result)
{
	return lod_prepare_mesh_threads(m, pixels, width, height, 1, result);
}

int lod_prepare_mesh_threads(struct mesh *m, double pixels, int width, int height, int threads,
			     struct lod_result *result)
{
	unsigned *idx = malloc((size_t)m->index_count * sizeof(unsigned) + 1);
	unsigned *remap = malloc((size_t)m->vertex_count * sizeof(unsigned) + 1);
	struct lod_result r = {.triangles_before = m->index_count / 3,
			       .vertices_before = m->vertex_count,
			       .clusters = 1};
	size_t n = m->index_count;
	float error = 0.0f;
	int ret = -ENOMEM;

	if (!idx || !remap || flat_cover(m) || weld_duplicates(m))
		goto out;
	n = m->index_count;
	r.wanted = lod_triangles_wanted(m, pixels, width, height);
	if (m->range_count > 1) {
		ret = simplify_ranges(m, r.wanted, lod_model_error(pixels, width, height), threads,
				      idx, &n, &error, &r);
		if (ret)
			goto out;
	} else if (r.wanted < n / 3) {
		double target = lod_model_error(pixels, width, height);

		if (cluster_count(threads, m->index_count) > 1) {
			ret = simplify_clustered(m, m->indices, m->index_count, r.wanted, target, 0,
						 threads, idx, &n, &error, &r);
			if (ret)
				goto out;
		} else {
			lod_result_part(&r, m->index_count / 3);
			n = simplify(m, r.wanted, target, 0, idx, &error);
			if (n / 3 > SEAM_SLACK * r.wanted)
				n = simplify_seamless(m, r.wanted, target, 0, idx, n, &error);
		}
	} else
		memcpy(idx, m->indices, n * sizeof(unsigned));
	if (m->range_count == 1)
		m->ranges[0].index_count = (uint32_t)n;
	if (m->flat && n < m->index_count && keep_flat(m, idx, n, &remap)) {
		ret = -ENOMEM;
		goto out;
	}
	/* Ordered within each range: the ranges stay where they are. */
	for (uint32_t g = 0; g < (m->range_count ? m->range_count : 1); g++) {
		unsigned *part = idx + (m->range_count ? m->ranges[g].first_index : 0);
		size_t count = m->range_count ? m->ranges[g].index_count : n;

		meshopt_optimizeVertexCache(part, part, count, m->vertex_count);
		meshopt_optimizeOverdraw(part, part, count, m->positions, m->vertex_count,
					 3 * sizeof(float), OVERDRAW_THRESHOLD);
	}
	ret = remap_streams(
	    m, remap, (uint32_t)meshopt_optimizeVertexFetchRemap(remap, idx, n, m->vertex_count));
	if (ret)
		goto out;
	flat_drop(m);
	/* n never exceeds the old count: the index array is reused. */
	meshopt_remapIndexBuffer(m->indices, idx, n, remap);
	m->index_count = (uint32_t)n;
	mesh_range_centers(m);
out:
	r.triangles_after = m->index_count / 3;
	r.vertices_after = m->vertex_count;
	r.error = error;
	r.error_pixels = error * sphere_fit_pixels_per_unit(width, height);
	if (ret)
		log_err("lod: no memory to simplify %u triangles", r.triangles_before);
	else if (r.triangles_after < r.triangles_before)
		log_info(
		    "lod: %u -> %u triangles for %dx%d (%.0f of %.1f px wanted; error %.2f px), "
		    "%u -> %u vertices",
		    r.triangles_before, r.triangles_after, width, height, r.wanted, pixels,
		    r.error_pixels, r.vertices_before, r.vertices_after);
	else
		log_debug("lod: %u triangles kept for %dx%d (%.0f of %.1f px wanted), %u vertices",
			  r.triangles_before, width, height, r.wanted, pixels, r.vertices_after);
	if (result)
		*result = r;
	free(idx);
	free(remap);
	return ret;
}
