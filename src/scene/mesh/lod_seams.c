/* The level of detail's way past seams (lod.h): the surface simplified
 * over its welded positions, each corner then given back its own side's
 * wedge. */
#include "scene/mesh/lod_seams.h"

#include <errno.h>
#include <math.h>
#include <meshoptimizer.h>
#include <stdlib.h>
#include <string.h>

/* Vertices at one position, by representative: list[first[r]..first[r+1])
 * holds every vertex whose rep is r (a seam's or a crease's wedges). */
struct wedges {
	uint32_t *rep, *first, *list;
};

static void wedges_free(struct wedges *w)
{
	free(w->rep);
	free(w->first);
	free(w->list);
}

/* rep[v]: the first vertex equal to v in position, and in uv too when
 * by_uv (then a UV seam stays a seam for meshoptimizer). */
static int weld(const struct mesh *m, bool by_uv, uint32_t *rep)
{
	struct meshopt_Stream streams[2] = {{m->positions, 12, 12}, {m->uvs, 8, 8}};
	uint32_t *first;

	if (!by_uv || !m->uvs)
		return mesh_weld(m->positions, m->vertex_count, rep);
	first = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	if (!first)
		return -ENOMEM;
	/* Over the indices: a vertex no triangle uses stays its own. */
	meshopt_generateVertexRemapMulti(rep, m->indices, m->index_count, m->vertex_count, streams,
					 2);
	for (uint32_t v = m->vertex_count; v-- > 0;)
		if (rep[v] != ~0u)
			first[rep[v]] = v;
	for (uint32_t v = 0; v < m->vertex_count; v++)
		rep[v] = rep[v] == ~0u ? v : first[rep[v]];
	free(first);
	return 0;
}

static int wedges_build(const struct mesh *m, bool by_uv, struct wedges *w)
{
	uint32_t n = m->vertex_count;

	w->rep = malloc((size_t)n * sizeof(uint32_t) + 1);
	w->first = calloc((size_t)n + 2, sizeof(uint32_t));
	w->list = malloc((size_t)n * sizeof(uint32_t) + 1);
	if (!w->rep || !w->first || !w->list || weld(m, by_uv, w->rep))
		return -ENOMEM;
	for (uint32_t v = 0; v < n; v++)
		w->first[w->rep[v] + 2]++;
	for (uint32_t r = 0; r < n; r++)
		w->first[r + 2] += w->first[r + 1];
	for (uint32_t v = 0; v < n; v++)
		w->list[w->first[w->rep[v] + 1]++] = v;
	return 0;
}

static double dot3f(const float *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Of the wedges at position r, the one that belongs to this side: its
 * normal nearest the face's (a crease), then its uv nearest the anchor's
 * (a UV seam). */
static uint32_t pick_wedge(const struct mesh *m, const struct wedges *w, uint32_t r,
			   const double face[3], const float *anchor_uv)
{
	uint32_t best = r;
	double best_score = -INFINITY;

	for (uint32_t i = w->first[r]; i < w->first[r + 1]; i++) {
		uint32_t v = w->list[i];
		double score = dot3f(m->normals + (size_t)v * 3, face);

		if (anchor_uv && m->uvs) {
			const float *uv = m->uvs + (size_t)v * 2;
			/* A seam's sides lie a texture apart; a crease's share uvs. */
			score -= 4.0 * (fabs(uv[0] - anchor_uv[0]) + fabs(uv[1] - anchor_uv[1]));
		}
		if (score > best_score)
			best = v, best_score = score;
	}
	return best;
}

/* How far apart in uv the wedges at position r lie: 0 off a UV seam. */
static double uv_spread(const struct mesh *m, const struct wedges *w, uint32_t r)
{
	const float *a = m->uvs + (size_t)w->list[w->first[r]] * 2;
	double spread = 0.0;

	for (uint32_t i = w->first[r] + 1; i < w->first[r + 1]; i++) {
		const float *b = m->uvs + (size_t)w->list[i] * 2;
		spread = fmax(spread, fabs(a[0] - b[0]) + fabs(a[1] - b[1]));
	}
	return spread;
}

/* A simplified triangle over representatives back onto wedges: the corner
 * off any UV seam anchors the uvs of the others. */
static void unweld_triangle(const struct mesh *m, const struct wedges *w, unsigned *t)
{
	const float *a = m->positions + (size_t)t[0] * 3, *b = m->positions + (size_t)t[1] * 3,
		    *c = m->positions + (size_t)t[2] * 3;
	double e1[3], e2[3], face[3], len;
	int anchor = 0;

	for (int k = 0; k < 3; k++)
		e1[k] = (double)b[k] - a[k], e2[k] = (double)c[k] - a[k];
	face[0] = e1[1] * e2[2] - e1[2] * e2[1];
	face[1] = e1[2] * e2[0] - e1[0] * e2[2];
	face[2] = e1[0] * e2[1] - e1[1] * e2[0];
	len = sqrt(face[0] * face[0] + face[1] * face[1] + face[2] * face[2]);
	for (int k = 0; k < 3 && len > 0; k++)
		face[k] /= len;
	for (int k = 1; k < 3 && m->uvs; k++)
		if (uv_spread(m, w, t[k]) < uv_spread(m, w, t[anchor]))
			anchor = k;
	t[anchor] = pick_wedge(m, w, t[anchor], face, NULL);
	for (int k = 0; k < 3; k++)
		if (k != anchor)
			t[k] = pick_wedge(m, w, t[k], face,
					  m->uvs ? m->uvs + (size_t)t[anchor] * 2 : NULL);
}

size_t lod_simplify_welded(const struct mesh *m, bool by_uv, double wanted, double target,
			   unsigned options, unsigned *out, float *error)
{
	float scale = meshopt_simplifyScale(m->positions, m->vertex_count, 3 * sizeof(float));
	unsigned *welded = malloc((size_t)m->index_count * sizeof(unsigned) + 1);
	/* Only the representatives, numbered apart: meshoptimizer would
	 * still see the other wedges at a position and lock it. */
	float *points = malloc((size_t)m->vertex_count * 3 * sizeof(float) + 1);
	uint32_t *id = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	uint32_t *back = malloc((size_t)m->vertex_count * sizeof(uint32_t) + 1);
	struct wedges w = {NULL, NULL, NULL};
	uint32_t count = 0;
	size_t n = 0;

	if (scale > 0.0f && welded && points && id && back && !wedges_build(m, by_uv, &w)) {
		for (uint32_t v = 0; v < m->vertex_count; v++)
			if (w.rep[v] == v) {
				memcpy(points + (size_t)count * 3, m->positions + (size_t)v * 3,
				       3 * sizeof(float));
				back[count] = v;
				id[v] = count++;
			}
		for (uint32_t i = 0; i < m->index_count; i++)
			welded[i] = id[w.rep[m->indices[i]]];
		n = meshopt_simplify(out, welded, m->index_count, points, count, 3 * sizeof(float),
				     3 * (size_t)wanted, (float)(target / scale), options, error);
		*error *= scale;
		for (size_t i = 0; i < n; i++)
			out[i] = back[out[i]];
		for (size_t t = 0; t + 2 < n; t += 3)
			unweld_triangle(m, &w, out + t);
	}
	wedges_free(&w);
	free(welded);
	free(points);
	free(id);
	free(back);
	return n;
}
